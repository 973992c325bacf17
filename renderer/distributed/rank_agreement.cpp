#include "renderer/distributed/rank_agreement.h"

#include <dlfcn.h>
#include <unistd.h>

#include <cinttypes>
#include <cstdio>

#include "renderer/core/fnv_hash.h"
#include "renderer/core/version.h"
#include "renderer/distributed/message_bytes.h"
#include "renderer/core/input_file.h"

namespace isotrace {
namespace {

// Continues `h` over the file's bytes (not its path: ranks may see the same files under other paths).
std::uint64_t hash_file(const std::string& path, std::uint64_t h) {
    return fnv1a_64(read_input_file(path, UINT64_MAX, ""), h);
}

std::uint64_t hash_binary() {
    std::uint64_t h = hash_file("/proc/self/exe", kFnv1aOffset);
    Dl_info library{};  // the shared library that holds this function: libisotrace
    if (dladdr(reinterpret_cast<void*>(&hash_binary), &library) && library.dli_fname)
        h = hash_file(library.dli_fname, h);
    return h;
}

std::uint64_t hash_scene(const LoadedScene& scene) {
    std::uint64_t h = hash_file(scene.path, kFnv1aOffset);
    for (const auto& file : scene.referenced_files) h = hash_file(file.string(), h);
    MessageWriter settings;
    settings.put(scene.film.raster).put(scene.film.crop).put(scene.film.half_float).put(scene.spp).put(scene.seed);
    for (Aov aov : scene.film.aovs) settings.put(aov);
    settings.put_string(scene.integrator_type).put_string(scene.sampler_type).put_string(scene.filter_type);
    for (const auto& [key, value] : scene.integrator->settings()) settings.put_string(key).put_string(value);
    return fnv1a_64(settings.take(), h);
}

std::string host_name() {
    char name[256] = {};
    if (gethostname(name, sizeof name - 1) != 0) return "unknown host";
    return name;
}

}  // namespace

RankIdentity identify_this_rank(const LoadedScene* scene, const std::string& load_error) {
    RankIdentity identity;
    identity.host = host_name();
    identity.version = kIsotraceVersion;
    identity.binary = hash_binary();
    identity.scene = scene ? hash_scene(*scene) : 0;
    identity.load_error = load_error;
    return identity;
}

std::string encode_identity(const RankIdentity& identity) {
    return MessageWriter()
        .put_string(identity.host)
        .put_string(identity.version)
        .put(identity.binary)
        .put(identity.scene)
        .put_string(identity.load_error)
        .take();
}

RankIdentity decode_identity(std::string_view bytes) {
    MessageReader in(bytes);
    RankIdentity identity;
    identity.host = in.get_string();
    identity.version = in.get_string();
    identity.binary = in.get<std::uint64_t>();
    identity.scene = in.get<std::uint64_t>();
    identity.load_error = in.get_string();
    return identity;
}

std::string disagreement(const std::vector<RankIdentity>& ranks) {
    const RankIdentity& first = ranks.front();
    for (std::size_t rank = 1; rank < ranks.size(); ++rank) {
        const RankIdentity& other = ranks[rank];
        const std::string who = "rank " + std::to_string(rank) + " (on " + other.host + ")";
        if (!other.load_error.empty()) return who + " could not load the scene: " + other.load_error;
        if (other.version != first.version)
            return who + " runs isotrace " + other.version + ", rank 0 isotrace " + first.version +
                   ": every rank must run the same build";
        if (other.binary != first.binary)
            return who + " runs another isotrace build than rank 0 (binary fingerprint " + hex64(other.binary) +
                   ", rank 0's " + hex64(first.binary) + "): every rank must run the same build";
        if (other.scene != first.scene)
            return who + " loaded another scene than rank 0 (scene fingerprint " + hex64(other.scene) + ", rank 0's " +
                   hex64(first.scene) + "): the scene file, a file it references or an option differs between ranks";
    }
    return {};
}

}  // namespace isotrace
