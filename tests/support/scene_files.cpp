#include "tests/support/scene_files.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace isotrace::testing {

TemporaryDirectory::TemporaryDirectory(const std::string& label) {
    static std::atomic<int> counter{0};
    const std::filesystem::path base = std::filesystem::temp_directory_path();
    for (;;) {
        path_ = base / ("isotrace-" + label + "-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
        if (std::filesystem::create_directories(path_)) break;  // false: left over from an earlier run
    }
}

TemporaryDirectory::~TemporaryDirectory() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
}

std::filesystem::path TemporaryDirectory::write(const std::string& name, const std::string& text) const {
    const std::filesystem::path file = path_ / name;
    std::filesystem::create_directories(file.parent_path());
    std::ofstream out(file, std::ios::binary);
    out << text;
    if (!out) throw std::runtime_error("cannot write test file " + file.string());
    return file;
}

std::vector<std::string> TemporaryDirectory::entries() const {
    std::vector<std::string> names;
    for (const auto& entry : std::filesystem::directory_iterator(path_)) names.push_back(entry.path().filename());
    std::sort(names.begin(), names.end());
    return names;
}

std::string read_file(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw std::runtime_error("cannot open " + path.string());
    std::ostringstream buffer;
    buffer << in.rdbuf();
    return buffer.str();
}

ParsedScene::ParsedScene(const std::string& text, const ColourSystem* colours, std::filesystem::path directory,
                         const std::string& file_name)
    : json_(std::make_unique<JsonValue>(parse_json(text, file_name))) {
    auto context = std::make_shared<SceneFileContext>();
    context->file = file_name;
    context->directory = std::move(directory);
    context->colours = colours;
    root_.emplace(*json_, "", std::move(context));
}

void expect_input_error(const std::function<void()>& action, const std::string& file, int line, int column,
                        const std::string& field, const std::string& message) {
    try {
        action();
    } catch (const InputError& error) {
        EXPECT_EQ(error.location().file, file) << error.what();
        EXPECT_EQ(error.location().line, line) << error.what();
        EXPECT_EQ(error.location().column, column) << error.what();
        EXPECT_EQ(error.field(), field) << error.what();
        EXPECT_EQ(std::string(error.what()), message);
        return;
    }
    ADD_FAILURE() << "no InputError; expected: " << message;
}

}  // namespace isotrace::testing
