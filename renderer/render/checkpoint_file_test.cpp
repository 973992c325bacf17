// The checkpoint container: round trip, and every kind of damage (foreign, truncated at each length, extended,
// flipped bytes, another version or byte order) rejected with a message that says which.
#include "renderer/render/checkpoint_file.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <fstream>
#include <utility>

#include "renderer/core/input_error.h"
#include "tests/support/scene_files.h"

namespace isotrace {
namespace {

CheckpointContents sample_contents() {
    CheckpointContents c;
    c.metadata_json = R"({"seed": "7"})";
    for (int i = 0; i < 100; ++i) c.film_state += char(i * 37);
    return c;
}

std::string error_of(std::string_view bytes) {
    try {
        decode_checkpoint(bytes, "ck.bin");
    } catch (const InputError& error) {
        return error.what();
    }
    return "";
}

TEST(CheckpointFile, RoundTripsExactly) {
    const CheckpointContents c = sample_contents();
    const CheckpointContents back = decode_checkpoint(encode_checkpoint(c), "ck.bin");
    EXPECT_EQ(back.metadata_json, c.metadata_json);
    EXPECT_EQ(back.film_state, c.film_state);
    const CheckpointContents empty = decode_checkpoint(encode_checkpoint({}), "ck.bin");
    EXPECT_TRUE(empty.metadata_json.empty());
    EXPECT_TRUE(empty.film_state.empty());
}

TEST(CheckpointFile, ForeignFilesAreNotCheckpoints) {
    EXPECT_NE(error_of("").find("not an isotrace checkpoint"), std::string::npos);
    EXPECT_NE(error_of("{\"isotrace\": 1}").find("not an isotrace checkpoint"), std::string::npos);
    EXPECT_NE(error_of("ck.bin").find("ck.bin"), std::string::npos);
}

TEST(CheckpointFile, EveryTruncationAndExtensionIsRejected) {
    const std::string bytes = encode_checkpoint(sample_contents());
    for (std::size_t length = 8; length < bytes.size(); ++length)
        EXPECT_NE(error_of(std::string_view(bytes).substr(0, length)).find("truncated"), std::string::npos) << length;
    EXPECT_NE(error_of(bytes + "x").find("too long"), std::string::npos);
}

// The lengths are checked against the file's size before anything is allocated from them; lengths whose sum wraps
// around 2^64 to the file's size are truncation, not a match.
TEST(CheckpointFile, LengthsBeyondTheFileAreTruncationWhateverTheirSum) {
    const std::string bytes = encode_checkpoint(sample_contents());
    const std::uint64_t metadata = sample_contents().metadata_json.size(), state = sample_contents().film_state.size();
    constexpr std::uint64_t kMax = ~std::uint64_t(0);
    for (const auto& [m, s] : {std::pair{metadata + 1, state}, std::pair{kMax, state + metadata + 1},
                               std::pair{metadata, kMax}, std::pair{kMax, kMax}}) {
        std::string damaged = bytes;
        std::memcpy(damaged.data() + 16, &m, 8);
        std::memcpy(damaged.data() + 24, &s, 8);
        const std::string message = error_of(damaged);
        EXPECT_NE(message.find("truncated"), std::string::npos) << message;
    }
}

TEST(CheckpointFile, EveryFlippedPayloadByteIsCaught) {
    const std::string bytes = encode_checkpoint(sample_contents());
    for (std::size_t i = 32; i < bytes.size(); ++i) {
        std::string damaged = bytes;
        damaged[i] ^= 0x10;
        EXPECT_NE(error_of(damaged).find("corrupted"), std::string::npos) << i;
    }
}

TEST(CheckpointFile, OtherVersionsAndByteOrdersAreNamed) {
    std::string bytes = encode_checkpoint(sample_contents());
    std::string newer = bytes;
    const std::uint32_t version = kCheckpointFormatVersion + 1;
    std::memcpy(newer.data() + 8, &version, 4);
    EXPECT_NE(error_of(newer).find("format version " + std::to_string(version)), std::string::npos);
    std::string swapped = bytes;
    std::swap(swapped[12], swapped[15]);
    std::swap(swapped[13], swapped[14]);
    EXPECT_NE(error_of(swapped).find("byte order"), std::string::npos);
}

TEST(CheckpointFile, WritesAndReadsFiles) {
    const testing::TemporaryDirectory dir;
    const auto path = dir.path() / "ck.bin";
    write_checkpoint(path, sample_contents());
    EXPECT_EQ(read_checkpoint(path).film_state, sample_contents().film_state);
    EXPECT_THROW(read_checkpoint(dir.path() / "missing.bin"), InputError);
}

}  // namespace
}  // namespace isotrace
