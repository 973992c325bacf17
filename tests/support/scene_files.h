#pragma once
// Test helper: a scratch directory that is removed with its contents when the object goes out of scope,
// plus a writer for small scene (or any text) files inside it.
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "renderer/params/scene_node.h"

namespace isotrace::testing {

class TemporaryDirectory {
public:
    // Creates a fresh, empty directory under the system temporary directory; `label` makes it easy to spot.
    explicit TemporaryDirectory(const std::string& label = "test");
    ~TemporaryDirectory();
    TemporaryDirectory(const TemporaryDirectory&) = delete;
    TemporaryDirectory& operator=(const TemporaryDirectory&) = delete;

    const std::filesystem::path& path() const { return path_; }
    std::filesystem::path operator/(const std::string& name) const { return path_ / name; }

    // Writes `text` verbatim to path()/name (creating parent folders) and returns the full path.
    std::filesystem::path write(const std::string& name, const std::string& text) const;
    // Names of the entries directly inside the directory, sorted.
    std::vector<std::string> entries() const;

private:
    std::filesystem::path path_;
};

// A scene (or any JSON) file in a temporary directory of its own, removed with the object.
class SceneFile {
public:
    explicit SceneFile(const std::string& json, const std::string& label = "scene")
        : directory_(label), path_(directory_.write("scene.json", json).string()) {}
    const std::string& path() const { return path_; }

private:
    TemporaryDirectory directory_;
    std::string path_;
};

// Reads a whole file (binary); throws std::runtime_error when it cannot be opened.
std::string read_file(const std::filesystem::path& path);

// JSON text parsed as file `file_name` and wrapped in a root SceneNode (which points into the tree kept here).
class ParsedScene {
public:
    explicit ParsedScene(const std::string& text, const ColourSystem* colours = nullptr,
                         std::filesystem::path directory = {}, const std::string& file_name = "scene.json");
    const SceneNode& root() const { return *root_; }

private:
    std::unique_ptr<JsonValue> json_;
    std::optional<SceneNode> root_;
};

// Runs `action`, which must throw InputError, and checks file, line, column, field and the complete message
// (gtest failures otherwise).
void expect_input_error(const std::function<void()>& action, const std::string& file, int line, int column,
                        const std::string& field, const std::string& message);

}  // namespace isotrace::testing
