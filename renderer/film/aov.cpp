#include "renderer/film/aov.h"

#include <algorithm>
#include <sstream>

#include "renderer/core/did_you_mean.h"
#include "renderer/core/input_error.h"

namespace isotrace {

const std::vector<AovInfo>& all_aovs() {
    static const std::vector<AovInfo> table = {
        {Aov::Albedo, "albedo", {"albedo.R", "albedo.G", "albedo.B"}, "surface albedo at the first hit"},
        {Aov::Normal, "normal", {"N.X", "N.Y", "N.Z"}, "world-space shading normal at the first hit"},
        {Aov::Depth, "depth", {"Z"}, "distance along the camera's viewing axis (world units; inf = no hit)"},
        {Aov::Position, "position", {"P.X", "P.Y", "P.Z"}, "world-space position of the first hit"},
        {Aov::ObjectId, "object_id", {"objectId"}, "index of the object in the scene file (-1 = none)"},
        {Aov::PrimitiveId, "primitive_id", {"primitiveId"}, "primitive index within the object (-1 = none)"},
        {Aov::SampleCount, "sample_count", {"sampleCount"}, "camera samples taken in the pixel"},
        {Aov::Variance, "variance", {"variance.R", "variance.G", "variance.B"},
         "estimated variance of the pixel's mean radiance"},
    };
    return table;
}

const AovInfo& aov_info(Aov aov) {
    for (const auto& info : all_aovs())
        if (info.aov == aov) return info;
    return all_aovs().front();
}

std::vector<Aov> parse_aov_list(const std::string& list, const std::string& source) {
    std::vector<std::string> names;
    for (const auto& info : all_aovs()) names.push_back(info.name);
    std::vector<Aov> result;
    std::stringstream stream(list);
    std::string item;
    while (std::getline(stream, item, ',')) {
        if (item.empty()) continue;
        if (item == "all") {
            for (const auto& info : all_aovs())
                if (std::find(result.begin(), result.end(), info.aov) == result.end()) result.push_back(info.aov);
            continue;
        }
        const auto found = std::find_if(all_aovs().begin(), all_aovs().end(),
                                        [&](const AovInfo& info) { return item == info.name; });
        if (found == all_aovs().end()) {
            std::string known;
            for (const auto& name : names) known += (known.empty() ? "" : ", ") + name;
            throw InputError({}, source, "unknown AOV \"" + item + "\"" + did_you_mean(item, names) +
                                             "; available: " + known + ", all");
        }
        if (std::find(result.begin(), result.end(), found->aov) == result.end()) result.push_back(found->aov);
    }
    return result;
}

}  // namespace isotrace
