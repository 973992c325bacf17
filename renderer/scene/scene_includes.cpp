#include "renderer/scene/scene_includes.h"

#include <algorithm>
#include <unordered_map>

#include "renderer/core/input_file.h"

namespace isotrace {

namespace {

// Where a value is: the document, one of its sections, or inside a section.
enum class Level { Document, Section, Value };

void merge(JsonValue& base, JsonValue&& overlay, Level level) {
    if (base.is_object() && overlay.is_object()) {
        std::unordered_map<std::string, std::size_t> positions;  // a lookup per key keeps large maps linear
        for (std::size_t i = 0; i < base.members.size(); ++i) positions.emplace(base.members[i].first, i);
        for (auto& [key, value] : overlay.members) {
            const auto found = positions.find(key);
            if (found != positions.end()) {
                merge(base.members[found->second].second, std::move(value),
                      level == Level::Document ? Level::Section : Level::Value);
            } else {
                positions.emplace(key, base.members.size());
                base.members.emplace_back(key, std::move(value));
            }
        }
        base.location = overlay.location;
        base.reindex();
    } else if (level == Level::Section && base.is_array() && overlay.is_array()) {
        base.items.insert(base.items.end(), std::make_move_iterator(overlay.items.begin()),
                          std::make_move_iterator(overlay.items.end()));
        base.location = overlay.location;
    } else {
        base = std::move(overlay);
    }
}

class IncludeReader {
public:
    IncludeReader(std::uint64_t max_bytes, MemoryBudget* memory) : max_bytes_(max_bytes), memory_(memory) {}

    SceneDocument read(const std::string& path) {
        SceneDocument document;
        document.root = parse(path);
        if (document.root.is_object()) {  // otherwise the loader says what is wrong
            chain_.push_back({canonical_path(path), path});
            expand(document.root, path);
        }
        document.included_directories = std::move(directories_);
        document.included_files = std::move(files_);
        return document;
    }

private:
    // The file's identity for finding cycles (a file reached through a symlink or "../" is the same file).
    static std::filesystem::path canonical_path(const std::string& path) {
        std::error_code error;
        const std::filesystem::path canonical = std::filesystem::weakly_canonical(path, error);
        return error ? std::filesystem::absolute(path) : canonical;
    }

    struct Link {
        std::filesystem::path canonical;
        std::string name;
    };

    JsonValue parse(const std::string& path) {
        const std::string text = read_input_file(
            path, max_bytes_ - bytes_,
            bytes_ == 0 ? "for scene files (isotrace render --max-scene-size raises it)"
                        : "left for the files the scene includes, of the limit for scene files (isotrace render "
                          "--max-scene-size raises it)");
        bytes_ += text.size();
        return parse_json(text, path, memory_);
    }

    // Replaces the object's "include" by the sections of the files it names, merged under the object's own.
    void expand(JsonValue& object, const std::string& file) {
        const auto include = std::find_if(object.members.begin(), object.members.end(),
                                          [](const auto& member) { return member.first == "include"; });
        if (include == object.members.end()) return;
        const JsonValue names = std::move(include->second);
        object.members.erase(include);
        std::vector<const JsonValue*> list;
        if (names.is_string()) list.push_back(&names);
        for (const JsonValue& item : names.items) list.push_back(&item);
        if (!(names.is_string() || names.is_array()) ||
            !std::all_of(list.begin(), list.end(), [](const JsonValue* v) { return v->is_string(); }))
            throw InputError(names.location, "include", "expected a file name or a list of file names");
        JsonValue merged;
        merged.kind = JsonValue::Kind::Object;
        for (const JsonValue* name : list) merge_scene_sections(merged, read_included(*name, file));
        merge_scene_sections(merged, std::move(object));
        object = std::move(merged);
    }

    JsonValue read_included(const JsonValue& name, const std::string& including_file) {
        const std::filesystem::path given = name.string;
        const std::string path =
            given.is_absolute() ? given.string() : (std::filesystem::path(including_file).parent_path() / given).string();
        const auto refuse = [&](const std::string& problem) {
            throw InputError(name.location, "include", "cannot include \"" + name.string + "\": " + problem);
        };
        std::string chain;
        for (const Link& link : chain_) chain += link.name + " -> ";
        chain += path;
        if (int(chain_.size()) > kMaxIncludeDepth)
            refuse("includes nest more than " + std::to_string(kMaxIncludeDepth) + " deep (" + chain + ")");
        if (++included_ > kMaxIncludedFiles)
            refuse("the scene includes more than " + std::to_string(kMaxIncludedFiles) + " files");
        try {
            require_regular_input(path);
        } catch (const InputError& error) {
            refuse(error.what());
        }
        const std::filesystem::path canonical = canonical_path(path);
        for (const Link& link : chain_)
            if (link.canonical == canonical) refuse("include cycle: " + chain);
        JsonValue included;
        try {
            included = parse(path);
        } catch (const InputError& error) {
            refuse(error.what());
        }
        if (!included.is_object())
            refuse(std::string("expected an object of scene sections, found ") + JsonValue::kind_name(included.kind));
        const std::filesystem::path absolute = std::filesystem::absolute(path);
        directories_[path] = absolute.parent_path();
        files_.push_back(absolute);
        chain_.push_back({canonical, path});
        expand(included, path);
        chain_.pop_back();
        return included;
    }

    const std::uint64_t max_bytes_;
    MemoryBudget* memory_;
    std::uint64_t bytes_ = 0;
    int included_ = 0;
    std::vector<Link> chain_;  // the including files, outermost first
    std::map<std::string, std::filesystem::path> directories_;
    std::vector<std::filesystem::path> files_;
};

}  // namespace

void merge_scene_sections(JsonValue& base, JsonValue&& overlay) { merge(base, std::move(overlay), Level::Document); }

SceneDocument read_scene_document(const std::string& path, std::uint64_t max_bytes, MemoryBudget* memory) {
    return IncludeReader(max_bytes, memory).read(path);
}

}  // namespace isotrace
