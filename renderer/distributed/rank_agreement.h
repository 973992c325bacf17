#pragma once
// Before a distributed render, every rank says what it is running and what it loaded; rank 0 refuses to start
// when any rank could not load the scene or differs from it (another isotrace build, another scene file, other
// options that change pixels), since its samples would not be the ones a single process takes.
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "renderer/scene/loaded_scene.h"

namespace isotrace {

struct RankIdentity {
    std::string host;
    std::string version;       // the isotrace version
    std::uint64_t binary = 0;  // FNV-1a of the executable and of the isotrace library it runs
    std::uint64_t scene = 0;   // FNV-1a of the scene's files and of the settings that decide pixels
    std::string load_error;    // why this rank could not load the scene (empty when it did)
};

// This process's identity; `scene` is null when loading failed with `load_error`.
RankIdentity identify_this_rank(const LoadedScene* scene, const std::string& load_error);

std::string encode_identity(const RankIdentity& identity);
RankIdentity decode_identity(std::string_view bytes);

// The first problem among the identities (index = rank), each compared with rank 0's, as a message naming the
// rank; empty when all agree.
std::string disagreement(const std::vector<RankIdentity>& ranks);

}  // namespace isotrace
