#pragma once
// Arbitrary output variables: per-pixel data written beside the beauty image in the EXR.
#include <string>
#include <vector>

namespace isotrace {

enum class Aov { Albedo, Normal, Depth, Position, ObjectId, PrimitiveId, SampleCount, Variance };

struct AovInfo {
    Aov aov;
    const char* name;                       // as written in scenes and on the command line
    std::vector<const char*> channels;      // EXR channel names
    const char* description;
};

const std::vector<AovInfo>& all_aovs();
const AovInfo& aov_info(Aov aov);
// Parses "albedo,normal,depth" (also accepts "all"); throws InputError naming the bad entry.
std::vector<Aov> parse_aov_list(const std::string& list, const std::string& source);

}  // namespace isotrace
