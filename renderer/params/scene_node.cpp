#include "renderer/params/scene_node.h"

#include <charconv>
#include <cmath>

#include "renderer/colour/colour_system.h"
#include "renderer/core/did_you_mean.h"
#include "renderer/core/input_file.h"

namespace isotrace {

namespace {

// Exact, shortest form of a number for messages: integers in full ("65536", not "6.5536e+04"), other values
// with as many digits as it takes to tell them apart ("1.00000000001", not "1" beside a limit of 1).
std::string format_number(double v) {
    if (v == std::floor(v) && std::abs(v) < 1e16) return std::to_string(static_cast<long long>(v));
    char buffer[32];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, v);
    return std::string(buffer, result.ptr);
}

}  // namespace

bool NumberRange::contains(double v) const {
    if (!std::isfinite(v)) return false;
    if (low_open ? !(v > low) : !(v >= low)) return false;
    if (high_open ? !(v < high) : !(v <= high)) return false;
    return true;
}

std::string NumberRange::describe() const {
    const bool has_low = std::isfinite(low), has_high = std::isfinite(high);
    if (has_low && has_high)
        return std::string("in ") + (low_open ? "(" : "[") + format_number(low) + ", " + format_number(high) +
               (high_open ? ")" : "]");
    if (has_low) return (low_open ? "> " : ">= ") + format_number(low);
    if (has_high) return (high_open ? "< " : "<= ") + format_number(high);
    return "finite";
}

SceneNode::SceneNode(const JsonValue& value, std::string path, std::shared_ptr<const SceneFileContext> context)
    : value_(&value), path_(std::move(path)), context_(std::move(context)) {}

std::string SceneNode::child_path(const std::string& key) const { return path_.empty() ? key : path_ + "." + key; }

const JsonValue* SceneNode::lookup(const std::string& key) const {
    read_keys_.insert(key);
    return value_->is_object() ? value_->find(key) : nullptr;
}

bool SceneNode::has(const std::string& key) const {
    asked_keys_.insert(key);  // a key a plugin asks about is one it knows: finish() lists it
    return value_->is_object() && value_->find(key) != nullptr;
}

const JsonValue& SceneNode::require(const std::string& key) const {
    if (!value_->is_object()) fail("expected an object, found " + std::string(JsonValue::kind_name(value_->kind)));
    const JsonValue* found = lookup(key);
    if (!found) fail("missing required field \"" + key + "\"");
    return *found;
}

const std::filesystem::path& SceneFileContext::directory_of(const SourceLocation& where) const {
    const auto found = included_directories.find(where.file);
    return found != included_directories.end() ? found->second : directory;
}

SourceLocation SceneNode::location() const {
    SourceLocation where = value_->location;
    if (where.file.empty()) where.file = context_->file;
    return where;
}

void SceneNode::fail(const std::string& problem) const { throw InputError(location(), path_, problem); }

void SceneNode::fail_at(const std::string& key, const std::string& problem) const {
    const JsonValue* found = value_->is_object() ? value_->find(key) : nullptr;
    if (!found) fail(problem);
    wrap(*found, child_path(key)).fail(problem);
}

void SceneNode::charge_at(const std::string& key, std::uint64_t bytes, const std::string& what) const {
    try {
        context().memory->charge(bytes, what);
    } catch (const InputError& error) {
        fail_at(key, error.problem());
    }
}

SceneNode SceneNode::object(const std::string& key) const {
    SceneNode child = wrap(require(key), child_path(key));
    if (!child.json().is_object())
        child.fail(std::string("expected an object, found ") + JsonValue::kind_name(child.json().kind));
    return child;
}

std::optional<SceneNode> SceneNode::optional_object(const std::string& key) const {
    if (!lookup(key)) return std::nullopt;
    return object(key);
}

std::optional<SceneNode> SceneNode::optional_value(const std::string& key) const {
    const JsonValue* found = lookup(key);
    if (!found) return std::nullopt;
    return wrap(*found, child_path(key));
}

std::vector<SceneNode> SceneNode::object_array(const std::string& key) const {
    const JsonValue* found = lookup(key);
    if (!found) return {};
    std::vector<SceneNode> result = wrap(*found, child_path(key)).elements();
    for (const SceneNode& item : result)
        if (!item.json().is_object())
            item.fail(std::string("expected an object, found ") + JsonValue::kind_name(item.json().kind));
    return result;
}

std::vector<SceneNode> SceneNode::elements() const {
    if (!value_->is_array()) fail(std::string("expected an array, found ") + JsonValue::kind_name(value_->kind));
    std::vector<SceneNode> result;
    for (std::size_t i = 0; i < value_->items.size(); ++i)
        result.push_back(wrap(value_->items[i], path_ + "[" + std::to_string(i) + "]"));
    return result;
}

std::vector<std::string> SceneNode::keys() const {
    std::vector<std::string> names;
    for (const auto& member : value_->members) names.push_back(member.first);
    return names;
}

void SceneNode::accept_all_keys() const {
    for (const auto& member : value_->members) read_keys_.insert(member.first);
}

double SceneNode::as_number(NumberRange range) const {
    if (!value_->is_number()) fail(std::string("expected a number, found ") + JsonValue::kind_name(value_->kind));
    if (!range.contains(value_->number))
        fail("value " + format_number(value_->number) + " out of range: must be " + range.describe());
    return value_->number;
}

double SceneNode::number(const std::string& key, NumberRange range) const {
    return wrap(require(key), child_path(key)).as_number(range);
}

double SceneNode::number_or(const std::string& key, double fallback, NumberRange range) const {
    return lookup(key) ? number(key, range) : fallback;
}

int SceneNode::integer(const std::string& key, NumberRange range) const {
    const double v = number(key, range);
    if (v != std::floor(v) || std::abs(v) > 2147483647.0) fail_at(key, "expected an integer");
    return int(v);
}

int SceneNode::integer_or(const std::string& key, int fallback, NumberRange range) const {
    return lookup(key) ? integer(key, range) : fallback;
}

std::uint64_t SceneNode::unsigned_or(const std::string& key, std::uint64_t fallback) const {
    const JsonValue* found = lookup(key);
    if (!found) return fallback;
    const double v = number(key, NumberRange::non_negative());
    if (v != std::floor(v)) fail_at(key, "expected a non-negative integer");
    if (v < 9007199254740992.0) return std::uint64_t(v);  // 2^53: exact in a double
    std::uint64_t exact = 0;
    const std::string& digits = found->string;  // the parser keeps a large whole number's digits
    const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), exact);
    if (digits.empty() || error != std::errc() || end != digits.data() + digits.size())
        fail_at(key, "expected a whole number from 0 to 18446744073709551615, written out in digits");
    return exact;
}

bool SceneNode::boolean_or(const std::string& key, bool fallback) const {
    const JsonValue* found = lookup(key);
    if (!found) return fallback;
    if (!found->is_bool())
        fail_at(key, std::string("expected true or false, found ") + JsonValue::kind_name(found->kind));
    return found->boolean;
}

std::string SceneNode::string(const std::string& key) const {
    const JsonValue& found = require(key);
    if (!found.is_string()) fail_at(key, std::string("expected a string, found ") + JsonValue::kind_name(found.kind));
    return found.string;
}

std::string SceneNode::string_or(const std::string& key, const std::string& fallback) const {
    return lookup(key) ? string(key) : fallback;
}

std::string SceneNode::choice_or(const std::string& key, const std::string& fallback,
                                 const std::vector<std::string>& choices) const {
    const std::string value = string_or(key, fallback);
    for (const auto& choice : choices)
        if (value == choice) return value;
    std::string list;
    for (const auto& choice : choices) list += (list.empty() ? "" : ", ") + choice;
    fail_at(key, "unknown value \"" + value + "\"" + did_you_mean(value, choices) + "; expected one of: " + list);
}

std::vector<double> SceneNode::numbers(const std::string& key, std::size_t count, NumberRange range) const {
    const SceneNode array = wrap(require(key), child_path(key));
    const JsonValue& json = array.json();
    if (!json.is_array() || json.items.size() != count)
        array.fail("expected an array of " + std::to_string(count) + " numbers");
    std::vector<double> values;
    for (std::size_t i = 0; i < count; ++i)
        values.push_back(wrap(json.items[i], array.path() + "[" + std::to_string(i) + "]").as_number(range));
    return values;
}

Vec3d SceneNode::as_vec3() const {
    const JsonValue& json = *value_;
    if (!json.is_array() || json.items.size() != 3) fail("expected an array of 3 numbers [x, y, z]");
    Vec3d v;
    for (int i = 0; i < 3; ++i) v[i] = wrap(json.items[i], path_ + "[" + std::to_string(i) + "]").as_number();
    return v;
}

Vec3d SceneNode::vec3(const std::string& key) const { return wrap(require(key), child_path(key)).as_vec3(); }

Vec3d SceneNode::vec3_or(const std::string& key, const Vec3d& fallback) const {
    return lookup(key) ? vec3(key) : fallback;
}

Rgb SceneNode::as_colour() const {
    const JsonValue& json = *value_;
    if (json.is_number()) return Rgb(float(as_number()));
    if (json.is_array()) {
        const Vec3d v = as_vec3();
        return {float(v.x), float(v.y), float(v.z)};
    }
    if (!json.is_object()) fail("expected a colour: [r, g, b], a number, or {\"rgb\": [r, g, b], \"space\": name}");
    const Vec3d v = vec3("rgb");
    const std::string space = string("space");
    finish();
    if (!context_->colours) fail("no colour system available to convert from \"" + space + "\"");
    const SourceLocation where = wrap(*json.find("space"), child_path("space")).location();  // where it is written
    return context_->colours->to_working({float(v.x), float(v.y), float(v.z)}, space, where, child_path("space"));
}

Rgb SceneNode::colour(const std::string& key) const { return wrap(require(key), child_path(key)).as_colour(); }

Rgb SceneNode::colour_or(const std::string& key, const Rgb& fallback) const {
    return lookup(key) ? colour(key) : fallback;
}

std::filesystem::path SceneNode::file_path(const std::string& key) const {
    const std::filesystem::path given = string(key);
    const std::filesystem::path resolved =
        given.is_absolute() ? given : context_->directory_of(value_->find(key)->location) / given;
    try {
        require_regular_input(resolved);
    } catch (const InputError& error) {
        fail_at(key, resolved.string() + ": " + error.problem());
    }
    context_->files->add(resolved);
    return resolved;
}

void SceneNode::finish() const {
    if (!value_->is_object()) return;
    // The plugin's whole parameter set as far as this node saw it: keys read, and keys asked about with has()
    // (optional keys such as "crop" are only asked about when the file leaves them out).
    std::set<std::string> known_set = read_keys_;
    known_set.insert(asked_keys_.begin(), asked_keys_.end());
    const std::vector<std::string> known(known_set.begin(), known_set.end());
    for (const auto& [key, value] : value_->members) {
        if (read_keys_.count(key)) continue;
        std::string expected;
        for (const auto& k : known) expected += (expected.empty() ? "" : ", ") + k;
        wrap(value, child_path(key))
            .fail("unknown key \"" + key + "\"" + did_you_mean(key, known) +
                  (expected.empty() ? "" : "; known keys here: " + expected));
    }
}

}  // namespace isotrace
