#pragma once
// The checkpoint file format (docs/checkpoints.md): a fixed header, a JSON block of metadata and the film's
// accumulator state, closed by a checksum. The metadata's meaning belongs to the writer (isotrace render);
// this layer only guarantees that what is read back is exactly what was written, or says why not.
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

namespace isotrace {

// 2: the film's sums in blocks of sample indices (Film::kSampleBlock).
inline constexpr std::uint32_t kCheckpointFormatVersion = 3;

struct CheckpointContents {
    std::string metadata_json;
    std::string film_state;  // Film::state()
};

std::string encode_checkpoint(const CheckpointContents& contents);

// Throws InputError naming `source` for anything that is not a complete, intact checkpoint of this format
// version: too short, wrong magic (not a checkpoint), another format version or byte order, lengths that do not
// add up (truncated or extended), a checksum mismatch (corrupted).
CheckpointContents decode_checkpoint(std::string_view bytes, const std::string& source);

// write_file_atomically(encode_checkpoint(...)): a kill at any moment leaves the previous checkpoint or the new one.
void write_checkpoint(const std::filesystem::path& path, const CheckpointContents& contents);
// Reads the file (InputError if it cannot be read) and decodes it.
CheckpointContents read_checkpoint(const std::filesystem::path& path);

}  // namespace isotrace
