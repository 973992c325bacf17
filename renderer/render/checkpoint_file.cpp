#include "renderer/render/checkpoint_file.h"

#include <cstring>

#include "renderer/core/atomic_file.h"
#include "renderer/core/fnv_hash.h"
#include "renderer/core/input_error.h"
#include "renderer/core/input_file.h"
#include "renderer/core/memory_budget.h"

namespace isotrace {
namespace {

constexpr char kMagic[8] = {'I', 'S', 'O', 'T', 'R', 'C', 'K', 'P'};
constexpr std::uint32_t kByteOrderMark = 0x01020304;

// magic, format version, byte order mark, metadata length, film state length
constexpr std::size_t kHeaderBytes = sizeof kMagic + 2 * sizeof(std::uint32_t) + 2 * sizeof(std::uint64_t);
constexpr std::size_t kChecksumBytes = sizeof(std::uint64_t);

template <class T>
void append(std::string& out, T value) {
    out.append(reinterpret_cast<const char*>(&value), sizeof value);
}

template <class T>
T read_at(std::string_view bytes, std::size_t at) {
    T value;
    std::memcpy(&value, bytes.data() + at, sizeof value);
    return value;
}

[[noreturn]] void reject(const std::string& source, const std::string& problem) {
    throw InputError({source}, "", "not a usable checkpoint: " + problem);
}

}  // namespace

std::string encode_checkpoint(const CheckpointContents& contents) {
    std::string out;
    out.reserve(kHeaderBytes + contents.metadata_json.size() + contents.film_state.size() + kChecksumBytes);
    out.append(kMagic, sizeof kMagic);
    append(out, kCheckpointFormatVersion);
    append(out, kByteOrderMark);
    append(out, std::uint64_t(contents.metadata_json.size()));
    append(out, std::uint64_t(contents.film_state.size()));
    out += contents.metadata_json;
    out += contents.film_state;
    append(out, fnv1a_64(std::string_view(out).substr(kHeaderBytes)));
    return out;
}

CheckpointContents decode_checkpoint(std::string_view bytes, const std::string& source) {
    if (bytes.size() < sizeof kMagic || std::memcmp(bytes.data(), kMagic, sizeof kMagic) != 0)
        reject(source, "it is not an isotrace checkpoint (no ISOTRCKP signature)");
    if (bytes.size() < kHeaderBytes + kChecksumBytes) reject(source, "the file is truncated (incomplete header)");
    const auto version = read_at<std::uint32_t>(bytes, 8);
    if (read_at<std::uint32_t>(bytes, 12) != kByteOrderMark)
        reject(source, "it was written on a machine with another byte order");
    if (version != kCheckpointFormatVersion)
        reject(source, "checkpoint format version " + std::to_string(version) + " (this build reads version " +
                           std::to_string(kCheckpointFormatVersion) + ")");
    const auto metadata_length = read_at<std::uint64_t>(bytes, 16);
    const auto state_length = read_at<std::uint64_t>(bytes, 24);
    const std::uint64_t payload = bytes.size() - kHeaderBytes - kChecksumBytes;
    if (metadata_length > payload || state_length != payload - metadata_length) {
        // Lengths near 2^64 must not wrap around into a plausible size.
        const bool truncated = metadata_length > payload || state_length > payload - metadata_length;
        std::uint64_t announced = 0;
        const bool announced_fits =
            !__builtin_add_overflow(metadata_length, state_length, &announced) &&
            !__builtin_add_overflow(announced, kHeaderBytes + kChecksumBytes, &announced);
        reject(source, "the file is " + std::string(truncated ? "truncated" : "too long") + " (" +
                           std::to_string(bytes.size()) + " bytes; the header announces " +
                           (announced_fits ? std::to_string(announced) : "more than 2^64") + ")");
    }
    const std::string_view body = bytes.substr(kHeaderBytes, payload);
    if (fnv1a_64(body) != read_at<std::uint64_t>(bytes, kHeaderBytes + payload))
        reject(source, "the checksum does not match (the file is corrupted)");
    return {std::string(body.substr(0, metadata_length)), std::string(body.substr(metadata_length))};
}

void write_checkpoint(const std::filesystem::path& path, const CheckpointContents& contents) {
    write_file_atomically(path, encode_checkpoint(contents));
}

CheckpointContents read_checkpoint(const std::filesystem::path& path) {
    const std::string bytes =
        read_input_file(path, MemoryBudget::default_limit_bytes(), "for checkpoints (80 % of physical memory)");
    return decode_checkpoint(bytes, path.string());
}

}  // namespace isotrace
