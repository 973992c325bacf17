#include "renderer/core/input_file.h"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>
#include <string>

#include "renderer/core/input_error.h"
#include "tests/support/scene_files.h"

namespace isotrace {
namespace {

using isotrace::testing::TemporaryDirectory;
namespace fs = std::filesystem;

std::string read_refusal(const fs::path& path, std::uint64_t max_bytes = 1 << 20) {
    try {
        read_input_file(path, max_bytes, "for tests");
    } catch (const InputError& error) {
        return error.what();
    }
    return "";
}

TEST(InputFile, ReadsARegularFileWhole) {
    TemporaryDirectory dir("inputs");
    const std::string text(100000, 'x');
    EXPECT_EQ(read_input_file(dir.write("a.json", text), 1 << 20, "for tests"), text);
    EXPECT_EQ(read_input_file(dir.write("empty.json", ""), 1 << 20, "for tests"), "");
}

// A FIFO used to block the reader forever: it is refused at once, without opening it for a writer.
TEST(InputFile, RefusesAFifoWithoutBlocking) {
    TemporaryDirectory dir("inputs");
    const fs::path fifo = dir / "scene.json";
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0666), 0);
    const std::string message = read_refusal(fifo);
    EXPECT_NE(message.find("is a FIFO"), std::string::npos) << message;
    EXPECT_NE(message.find(fifo.string()), std::string::npos) << message;
}

TEST(InputFile, RefusesDevicesAndDirectoriesSayingWhatTheyAre) {
    TemporaryDirectory dir("inputs");
    EXPECT_NE(read_refusal("/dev/zero").find("character device"), std::string::npos);
    EXPECT_NE(read_refusal(dir.path()).find("is a directory"), std::string::npos);
    EXPECT_NE(read_refusal(dir / "missing.json").find("file not found"), std::string::npos);
}

TEST(InputFile, RefusesFilesOverTheLimitNamingIt) {
    TemporaryDirectory dir("inputs");
    const std::string message = read_refusal(dir.write("big.json", std::string(5000, ' ')), 4096);
    EXPECT_NE(message.find("larger than the limit"), std::string::npos) << message;
    EXPECT_NE(message.find("for tests"), std::string::npos) << message;
    EXPECT_EQ(read_refusal(dir.write("exact.json", std::string(4096, ' ')), 4096), "");
}

// A file whose size the system does not know (procfs reports 0) is read to its end, and a read error names the file.
TEST(InputFile, ProcFilesAreReadToTheirEndAndReadErrorsNameTheFile) {
    EXPECT_NE(read_input_file("/proc/self/status", 1 << 20, "for tests").find("VmPeak"), std::string::npos);
    const std::string message = read_refusal("/proc/self/mem");
    EXPECT_NE(message.find("/proc/self/mem"), std::string::npos) << message;
    EXPECT_NE(message.find("cannot read"), std::string::npos) << message;
}

// "/etc/passwd\0.obj" would pass an extension check on the whole string and open the part before the NUL.
TEST(InputFile, RefusesANulInsideThePath) {
    const std::string path = std::string("/etc/passwd") + '\0' + ".obj";
    EXPECT_NE(read_refusal(path).find("NUL"), std::string::npos);
    EXPECT_THROW(require_regular_input(path), InputError);
}

}  // namespace
}  // namespace isotrace
