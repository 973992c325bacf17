#include "renderer/params/json_document.h"

#include "renderer/core/input_file.h"
#include "renderer/core/memory_budget.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <memory>

namespace isotrace {

JsonValue::JsonValue() = default;
JsonValue::~JsonValue() = default;
JsonValue::JsonValue(const JsonValue&) = default;
JsonValue::JsonValue(JsonValue&&) noexcept = default;
JsonValue& JsonValue::operator=(const JsonValue&) = default;
JsonValue& JsonValue::operator=(JsonValue&&) noexcept = default;

const JsonValue* JsonValue::find(const std::string& key) const {
    if (key_index && key_index->size() == members.size()) {  // the size check guards against later edits
        const auto found = key_index->find(key);
        return found != key_index->end() && members[found->second].first == key ? &members[found->second].second
                                                                                : nullptr;
    }
    for (const auto& [name, value] : members)
        if (name == key) return &value;
    return nullptr;
}

JsonValue* JsonValue::find(const std::string& key) {
    return const_cast<JsonValue*>(static_cast<const JsonValue*>(this)->find(key));
}

namespace {
constexpr std::size_t kIndexedObjectSize = 16;  // objects with more keys get a key_index
}  // namespace

void JsonValue::reindex() {
    if (members.size() <= kIndexedObjectSize) {
        key_index.reset();
        return;
    }
    auto index = std::make_shared<std::unordered_map<std::string, std::size_t>>();
    for (std::size_t i = 0; i < members.size(); ++i) index->emplace(members[i].first, i);
    key_index = std::move(index);
}

std::uint64_t JsonValue::tree_size() const {
    std::uint64_t count = 1;
    for (const JsonValue& item : items) count += item.tree_size();
    for (const auto& member : members) count += member.second.tree_size();
    return count;
}

const char* JsonValue::kind_name(Kind kind) {
    switch (kind) {
        case Kind::Null: return "null";
        case Kind::Bool: return "boolean";
        case Kind::Number: return "number";
        case Kind::String: return "string";
        case Kind::Array: return "array";
        case Kind::Object: return "object";
    }
    return "value";
}

namespace {

constexpr int kMaxDepth = 256;  // nested arrays/objects; deeper is surely an error and would exhaust the stack
// Resident bytes per value at the parse's peak, beyond its strings: the value itself in its parent's vector, the
// vector's spare capacity and, while a vector grows, the old block beside the new one (measured; docs/reliability.md).
constexpr std::uint64_t kBytesPerValue = 2 * sizeof(JsonValue) + 64;
// An object's member adds its key's std::string beside the value (with spare capacity), and its node in the key
// index (a copy of the key, its hash, the bucket).
constexpr std::uint64_t kBytesPerMember = 2 * sizeof(std::string) + 96;
// Whole numbers from here on are not all exact in a double: their digits are kept.
constexpr double kExactIntegerLimit = 9007199254740992.0;  // 2^53
// The memory budget is charged this much ahead, not once per value.
constexpr std::uint64_t kChargeStep = std::uint64_t(1) << 20;

// Heap bytes of a std::string of `length` characters: none within the small-string buffer, else the allocation
// with malloc's header, rounded to its 16-byte granule.
std::uint64_t heap_bytes(std::size_t length) {
    constexpr std::size_t kInlineCapacity = 15;
    return length <= kInlineCapacity ? 0 : (std::uint64_t(length) + 1 + 8 + 15) / 16 * 16;
}

class JsonParser {
public:
    JsonParser(const std::string& text, const std::string& file, MemoryBudget* memory)
        : text_(text), file_(file), memory_(memory) {}

    JsonValue parse_document() {
        if (memory_) memory_->charge(text_.size(), "the text of the file", {file_, 0, 0});
        // RFC 8259 section 8.1 lets parsers ignore a UTF-8 byte order mark (some Windows editors write one).
        if (text_.compare(0, 3, "\xEF\xBB\xBF") == 0) pos_ = line_start_ = 3;
        skip_whitespace();
        JsonValue root = parse_value(0);
        skip_whitespace();
        if (pos_ < text_.size()) fail("unexpected text after the end of the JSON document");
        return root;
    }

private:
    [[noreturn]] void fail(const std::string& problem) const { throw InputError(here(), "", problem); }

    SourceLocation here() const { return {file_, line_, int(pos_ - line_start_) + 1}; }

    bool at_end() const { return pos_ >= text_.size(); }
    char peek() const { return at_end() ? '\0' : text_[pos_]; }

    void advance() {
        if (text_[pos_] == '\n') {
            ++line_;
            line_start_ = pos_ + 1;
        }
        ++pos_;
    }

    // Whitespace and comments: `// ...` to the end of the line, `/* ... */` (not nested). A '/' that starts
    // neither is left for the caller to report.
    void skip_whitespace() {
        for (;;) {
            while (!at_end() && (peek() == ' ' || peek() == '\t' || peek() == '\n' || peek() == '\r')) advance();
            if (peek() != '/' || pos_ + 1 >= text_.size()) return;
            const char next = text_[pos_ + 1];
            if (next == '/') {
                while (!at_end() && peek() != '\n') advance();
            } else if (next == '*') {
                const SourceLocation opening = here();
                advance();
                advance();
                while (!at_end() && !(peek() == '*' && pos_ + 1 < text_.size() && text_[pos_ + 1] == '/')) advance();
                if (at_end()) throw InputError(opening, "", "unterminated comment (missing closing '*/')");
                advance();
                advance();
            } else {
                return;
            }
        }
    }

    void expect(char c, const char* what) {
        if (peek() != c) fail(std::string("expected ") + what + describe_next());
        advance();
    }

    std::string describe_next() const {
        if (at_end()) return " but the file ended";
        return std::string(" but found '") + peek() + "'";
    }

    // Counts `bytes` more of the tree (about to be allocated) and charges the budget ahead when they pass what it
    // was charged with: by as much again as is used so far, at most kChargeStep, so that a small document is not
    // charged for more than twice its size.
    void account(std::uint64_t bytes) {
        used_ += bytes;
        if (!memory_ || used_ <= charged_) return;
        const std::uint64_t step = std::max(std::min(kChargeStep, used_), used_ - charged_);
        memory_->charge(step, "the parsed document (" + std::to_string(values_) + " values so far)", here());
        charged_ += step;
    }

    // `depth` = number of arrays/objects enclosing the value.
    JsonValue parse_value(int depth) {
        ++values_;
        account(kBytesPerValue + file_heap_bytes_);
        JsonValue value;
        value.location = here();
        const char c = peek();
        if ((c == '{' || c == '[') && depth >= kMaxDepth)
            fail("JSON nested too deeply (more than " + std::to_string(kMaxDepth) + " arrays/objects)");
        if (c == '{') {
            parse_object(value, depth);
        } else if (c == '[') {
            parse_array(value, depth);
        } else if (c == '"') {
            value.kind = JsonValue::Kind::String;
            value.string = parse_string();
            account(heap_bytes(value.string.size()));
        } else if (c == '-' || (c >= '0' && c <= '9')) {
            value.kind = JsonValue::Kind::Number;
            const std::size_t start = pos_;
            value.number = parse_number();
            if (value.number >= kExactIntegerLimit &&
                std::all_of(text_.begin() + std::ptrdiff_t(start), text_.begin() + std::ptrdiff_t(pos_),
                            [](char d) { return d >= '0' && d <= '9'; })) {
                value.string.assign(text_, start, pos_ - start);
                account(heap_bytes(value.string.size()));
            }
        } else if (match_word("true")) {
            value.kind = JsonValue::Kind::Bool;
            value.boolean = true;
        } else if (match_word("false")) {
            value.kind = JsonValue::Kind::Bool;
        } else if (match_word("null")) {
            value.kind = JsonValue::Kind::Null;
        } else {
            fail("expected a JSON value" + describe_next());
        }
        return value;
    }

    bool match_word(const char* word) {
        const std::size_t n = std::char_traits<char>::length(word);
        if (text_.compare(pos_, n, word) != 0) return false;
        for (std::size_t i = 0; i < n; ++i) advance();
        return true;
    }

    void parse_object(JsonValue& value, int depth) {
        value.kind = JsonValue::Kind::Object;
        advance();  // '{'
        skip_whitespace();
        if (peek() == '}') {
            advance();
            return;
        }
        // Duplicates are found through the index (a linear search per key is quadratic in the key count).
        auto index = std::make_shared<std::unordered_map<std::string, std::size_t>>();
        for (;;) {
            skip_whitespace();
            if (peek() != '"') fail("expected a quoted key" + describe_next());
            const SourceLocation key_location = here();
            std::string key = parse_string();
            account(kBytesPerMember + 2 * heap_bytes(key.size()));  // the key in the member and in the index
            if (!index->emplace(key, value.members.size()).second) throw InputError(key_location, key, "duplicate key");
            skip_whitespace();
            expect(':', "':' after the key");
            skip_whitespace();
            value.members.emplace_back(std::move(key), parse_value(depth + 1));
            skip_whitespace();
            if (peek() == ',') {
                advance();
                skip_whitespace();
                if (peek() != '}') continue;  // a trailing comma before the closing brace is allowed
            }
            expect('}', "',' or '}'");
            if (value.members.size() > kIndexedObjectSize) value.key_index = std::move(index);
            return;
        }
    }

    void parse_array(JsonValue& value, int depth) {
        value.kind = JsonValue::Kind::Array;
        advance();  // '['
        skip_whitespace();
        if (peek() == ']') {
            advance();
            return;
        }
        for (;;) {
            skip_whitespace();
            value.items.push_back(parse_value(depth + 1));
            skip_whitespace();
            if (peek() == ',') {
                advance();
                skip_whitespace();
                if (peek() != ']') continue;  // a trailing comma before the closing bracket is allowed
            }
            expect(']', "',' or ']'");
            return;
        }
    }

    double parse_number() {
        const std::size_t start = pos_;
        if (peek() == '-') advance();
        if (peek() == '0') {
            advance();
            if (std::isdigit(static_cast<unsigned char>(peek())))
                throw InputError({file_, line_, int(start - line_start_) + 1}, "",
                                 "malformed number: leading zeros are not allowed");
        } else if (peek() >= '1' && peek() <= '9') {
            while (std::isdigit(static_cast<unsigned char>(peek()))) advance();
        } else {
            fail("malformed number");
        }
        if (peek() == '.') {
            advance();
            if (!std::isdigit(static_cast<unsigned char>(peek()))) fail("malformed number: digit expected after '.'");
            while (std::isdigit(static_cast<unsigned char>(peek()))) advance();
        }
        if (peek() == 'e' || peek() == 'E') {
            advance();
            if (peek() == '+' || peek() == '-') advance();
            if (!std::isdigit(static_cast<unsigned char>(peek()))) fail("malformed number: digit expected in exponent");
            while (std::isdigit(static_cast<unsigned char>(peek()))) advance();
        }
        double result = 0;
        const auto [end, error] = std::from_chars(text_.data() + start, text_.data() + pos_, result);
        if (error == std::errc::result_out_of_range || !std::isfinite(result))
            throw InputError({file_, line_, int(start - line_start_) + 1}, "", "number out of range");
        (void)end;
        return result;
    }

    unsigned parse_hex4() {
        unsigned code = 0;
        for (int i = 0; i < 4; ++i) {
            const char c = peek();
            unsigned digit;
            if (c >= '0' && c <= '9') digit = unsigned(c - '0');
            else if (c >= 'a' && c <= 'f') digit = unsigned(c - 'a' + 10);
            else if (c >= 'A' && c <= 'F') digit = unsigned(c - 'A' + 10);
            else fail("malformed \\u escape");
            code = code * 16 + digit;
            advance();
        }
        return code;
    }

    static void append_utf8(std::string& out, unsigned code) {
        if (code < 0x80) {
            out += char(code);
        } else if (code < 0x800) {
            out += char(0xC0 | (code >> 6));
            out += char(0x80 | (code & 0x3F));
        } else if (code < 0x10000) {
            out += char(0xE0 | (code >> 12));
            out += char(0x80 | ((code >> 6) & 0x3F));
            out += char(0x80 | (code & 0x3F));
        } else {
            out += char(0xF0 | (code >> 18));
            out += char(0x80 | ((code >> 12) & 0x3F));
            out += char(0x80 | ((code >> 6) & 0x3F));
            out += char(0x80 | (code & 0x3F));
        }
    }

    std::string parse_string() {
        // A string that runs to the end of the file or of the line is reported where it starts: that is
        // where the closing quote is missing.
        const SourceLocation opening = here();
        advance();  // opening quote
        std::string out;
        for (;;) {
            if (at_end()) throw InputError(opening, "", "unterminated string (missing closing '\"')");
            const char c = peek();
            if (c == '"') {
                advance();
                return out;
            }
            if (c == '\n' || c == '\r')
                throw InputError(opening, "", "unterminated string (line break before the closing '\"')");
            if (static_cast<unsigned char>(c) < 0x20) fail("control character in string (use an escape)");
            if (c != '\\') {
                out += c;
                advance();
                continue;
            }
            const SourceLocation escape = here();
            advance();
            if (at_end()) throw InputError(opening, "", "unterminated string (missing closing '\"')");
            const char e = peek();
            advance();
            switch (e) {
                case '"': out += '"'; break;
                case '\\': out += '\\'; break;
                case '/': out += '/'; break;
                case 'b': out += '\b'; break;
                case 'f': out += '\f'; break;
                case 'n': out += '\n'; break;
                case 'r': out += '\r'; break;
                case 't': out += '\t'; break;
                case 'u': {
                    unsigned code = parse_hex4();
                    if (code >= 0xDC00 && code <= 0xDFFF)  // a low surrogate must follow a high one
                        throw InputError(escape, "", "unpaired surrogate in \\u escape");
                    if (code >= 0xD800 && code < 0xDC00) {  // surrogate pair
                        if (!match_word("\\u")) throw InputError(escape, "", "unpaired surrogate in \\u escape");
                        const unsigned low = parse_hex4();
                        if (low < 0xDC00 || low > 0xDFFF)
                            throw InputError(escape, "", "invalid low surrogate in \\u escape");
                        code = 0x10000 + ((code - 0xD800) << 10) + (low - 0xDC00);
                    }
                    append_utf8(out, code);
                    break;
                }
                default: throw InputError(escape, "", std::string("invalid escape '\\") + e + "'");
            }
        }
    }

    const std::string& text_;
    const std::string& file_;
    MemoryBudget* memory_;
    const std::uint64_t file_heap_bytes_ = heap_bytes(file_.size());  // every value's location holds the name
    std::uint64_t values_ = 0, used_ = 0, charged_ = 0;
    std::size_t pos_ = 0;
    std::size_t line_start_ = 0;
    int line_ = 1;
};

}  // namespace

JsonValue parse_json(const std::string& text, const std::string& file_name, MemoryBudget* memory) {
    return JsonParser(text, file_name, memory).parse_document();
}

JsonValue parse_json_file(const std::string& path, std::uint64_t max_bytes, MemoryBudget* memory) {
    return parse_json(read_input_file(path, max_bytes, "for scene files (isotrace render --max-scene-size raises it)"),
                      path, memory);
}

}  // namespace isotrace
