#pragma once
// A JSON tree that remembers where every value starts in its file, so that scene errors can name
// file:line:column. (nlohmann::json, used elsewhere for output, does not keep value positions.)
#include <cstdint>
#include <memory>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "renderer/core/input_error.h"

namespace isotrace {

class JsonValue {
public:
    enum class Kind { Null, Bool, Number, String, Array, Object };

    // Defined out of line: `members` holds pairs of this still incomplete class, and clang with libstdc++
    // refuses to instantiate their destructor inside it (GCC accepts it).
    JsonValue();
    ~JsonValue();
    JsonValue(const JsonValue&);
    JsonValue(JsonValue&&) noexcept;
    JsonValue& operator=(const JsonValue&);
    JsonValue& operator=(JsonValue&&) noexcept;

    Kind kind = Kind::Null;
    bool boolean = false;
    double number = 0;
    // A String's text; for a whole Number beyond 2^53, which a double cannot hold exactly, its digits (64-bit seeds).
    std::string string;
    std::vector<JsonValue> items;                           // Array
    std::vector<std::pair<std::string, JsonValue>> members;  // Object, in file order
    SourceLocation location;                                 // where the value starts
    // Key -> position in `members`, built by the parser for large objects so that lookups stay O(1) (a
    // million-key "materials" map would otherwise cost a million linear searches).
    std::shared_ptr<const std::unordered_map<std::string, std::size_t>> key_index;

    bool is_object() const { return kind == Kind::Object; }
    bool is_array() const { return kind == Kind::Array; }
    bool is_number() const { return kind == Kind::Number; }
    bool is_string() const { return kind == Kind::String; }
    bool is_bool() const { return kind == Kind::Bool; }
    bool is_null() const { return kind == Kind::Null; }

    // Member by key or nullptr (objects only).
    const JsonValue* find(const std::string& key) const;
    JsonValue* find(const std::string& key);
    // Brings key_index up to date after members were added (merging includes, --set).
    void reindex();
    // Values in this tree, itself included.
    std::uint64_t tree_size() const;
    // Roughly the bytes of a tree of `values` values, for memory budgets (strings and keys aside).
    static std::uint64_t tree_bytes(std::uint64_t values) { return values * 2 * sizeof(JsonValue); }
    // "object", "array", ... for messages.
    static const char* kind_name(Kind kind);
};

// Scene files larger than this are refused unless the caller allows more (isotrace render --max-scene-size).
constexpr std::uint64_t kDefaultMaxJsonFileBytes = std::uint64_t(64) << 20;

class MemoryBudget;

// Parses JSON (RFC 8259) with two additions for files people write: comments (`// ...` to the end of the line,
// `/* ... */`) and a trailing comma after the last element of an array or object. Duplicate keys and malformed text throw InputError with the position. With a
// `memory` budget, the text and the tree are charged to it while the tree grows (a few bytes of text make a value
// of about a hundred and fifty), so a document too large for it stops the parse where it is refused.
JsonValue parse_json(const std::string& text, const std::string& file_name, MemoryBudget* memory = nullptr);
// Reads at most `max_bytes` (a path such as /dev/zero never ends) and parses the text.
JsonValue parse_json_file(const std::string& path, std::uint64_t max_bytes = kDefaultMaxJsonFileBytes,
                          MemoryBudget* memory = nullptr);

}  // namespace isotrace
