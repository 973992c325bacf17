#pragma once
// SceneNode: typed, checked access to one JSON object of a scene file. Every getter names the JSON path and
// the file position in its errors, and records which keys were read so that unknown keys can be reported
// (with a "did you mean") when the owner calls finish().
#include <array>
#include <filesystem>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "renderer/core/memory_budget.h"
#include "renderer/math/rgb.h"
#include "renderer/math/vec3.h"
#include "renderer/params/json_document.h"
#include "renderer/params/referenced_files.h"

namespace isotrace {

class ColourSystem;

// What every node of one scene file shares.
struct SceneFileContext {
    std::string file;                   // as the user named it (used in messages)
    std::filesystem::path directory;    // external files resolve relative to this
    // The directories of the files the scene includes, by the name their values' locations carry: a relative path
    // written in an included file resolves against that file's directory.
    std::map<std::string, std::filesystem::path> included_directories;
    const std::filesystem::path& directory_of(const SourceLocation& where) const;
    const ColourSystem* colours = nullptr;
    std::shared_ptr<MemoryBudget> memory = std::make_shared<MemoryBudget>();  // large allocations are charged here
    std::shared_ptr<ReferencedFiles> files = std::make_shared<ReferencedFiles>();  // every file_path() resolved
};

// Accepted range of a number; open ends exclude the bound.
struct NumberRange {
    double low = -std::numeric_limits<double>::infinity();
    double high = std::numeric_limits<double>::infinity();
    bool low_open = false;
    bool high_open = false;

    static NumberRange positive() { return {0, std::numeric_limits<double>::infinity(), true, false}; }
    static NumberRange non_negative() { return {0, std::numeric_limits<double>::infinity(), false, false}; }
    static NumberRange unit_interval() { return {0, 1, false, false}; }
    static NumberRange at_least(double v) { return {v, std::numeric_limits<double>::infinity(), false, false}; }
    static NumberRange between(double lo, double hi) { return {lo, hi, false, false}; }

    bool contains(double v) const;
    std::string describe() const;
};

class SceneNode {
public:
    SceneNode(const JsonValue& value, std::string path, std::shared_ptr<const SceneFileContext> context);

    const JsonValue& json() const { return *value_; }
    const std::string& path() const { return path_; }
    // Where the node's value is written: its file (an included file, or a command-line override), line and column.
    SourceLocation location() const;
    const SceneFileContext& context() const { return *context_; }
    const std::shared_ptr<const SceneFileContext>& shared_context() const { return context_; }

    // Whether the key is present. Asking does not count as reading the key, but finish() lists it as known.
    bool has(const std::string& key) const;

    // Sub-objects and arrays of objects.
    SceneNode object(const std::string& key) const;
    std::optional<SceneNode> optional_object(const std::string& key) const;
    std::vector<SceneNode> object_array(const std::string& key) const;  // missing key = empty
    // A child value that may be of any kind (for fields with several accepted forms).
    std::optional<SceneNode> optional_value(const std::string& key) const;
    // Items of this node when it is an array (any kinds).
    std::vector<SceneNode> elements() const;
    // Keys of this object in file order (for maps such as "materials").
    std::vector<std::string> keys() const;
    // Mark all keys as read (for maps whose keys are user-chosen names).
    void accept_all_keys() const;

    double number(const std::string& key, NumberRange range = {}) const;
    double number_or(const std::string& key, double fallback, NumberRange range = {}) const;
    int integer(const std::string& key, NumberRange range = {}) const;
    int integer_or(const std::string& key, int fallback, NumberRange range = {}) const;
    std::uint64_t unsigned_or(const std::string& key, std::uint64_t fallback) const;
    bool boolean_or(const std::string& key, bool fallback) const;
    std::string string(const std::string& key) const;
    std::string string_or(const std::string& key, const std::string& fallback) const;
    // String that must be one of `choices`.
    std::string choice_or(const std::string& key, const std::string& fallback,
                          const std::vector<std::string>& choices) const;
    std::vector<double> numbers(const std::string& key, std::size_t count, NumberRange range = {}) const;
    Vec3d vec3(const std::string& key) const;
    Vec3d vec3_or(const std::string& key, const Vec3d& fallback) const;
    // Colour in the working space: [r, g, b] (working space), a grey number, or
    // {"rgb": [r, g, b], "space": "<OCIO colour space>"}.
    Rgb colour(const std::string& key) const;
    Rgb colour_or(const std::string& key, const Rgb& fallback) const;
    // A file path resolved against the directory of the file the value is written in; must exist.
    std::filesystem::path file_path(const std::string& key) const;

    // The value of this node itself (when the node is not an object).
    double as_number(NumberRange range = {}) const;
    Vec3d as_vec3() const;
    Rgb as_colour() const;

    // Error at this node, or at the value of `key` when it exists.
    [[noreturn]] void fail(const std::string& problem) const;
    [[noreturn]] void fail_at(const std::string& key, const std::string& problem) const;
    // Charges `bytes` for `what` to the scene's memory budget, or fails at `key` when they do not fit.
    void charge_at(const std::string& key, std::uint64_t bytes, const std::string& what) const;

    // Throws for the first key that no getter read (typo protection).
    void finish() const;

    std::string child_path(const std::string& key) const;

private:
    const JsonValue& require(const std::string& key) const;
    const JsonValue* lookup(const std::string& key) const;
    SceneNode wrap(const JsonValue& value, std::string path) const { return {value, std::move(path), context_}; }

    const JsonValue* value_;
    std::string path_;
    std::shared_ptr<const SceneFileContext> context_;
    mutable std::set<std::string> read_keys_;
    mutable std::set<std::string> asked_keys_;  // by has(): known, though not necessarily read
};

// Runs `action`; a std::invalid_argument it throws becomes an InputError at `node`.
template <class Action>
auto at_node(const SceneNode& node, Action action) -> decltype(action()) {
    try {
        return action();
    } catch (const std::invalid_argument& error) {
        node.fail(error.what());
    }
}

}  // namespace isotrace
