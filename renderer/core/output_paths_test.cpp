#include "renderer/core/output_paths.h"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <unistd.h>

#include <filesystem>
#include <stdexcept>
#include <string>

#include "renderer/core/atomic_file.h"
#include "renderer/core/input_error.h"
#include "tests/support/scene_files.h"

namespace isotrace {
namespace {

using isotrace::testing::read_file;
using isotrace::testing::TemporaryDirectory;
namespace fs = std::filesystem;

// The message of the InputError check_output_paths throws, or "" if it accepts.
std::string refusal(const std::vector<NamedPath>& outputs, const std::vector<NamedPath>& inputs = {}) {
    try {
        check_output_paths(outputs, inputs);
    } catch (const InputError& error) {
        return error.what();
    }
    return "";
}

TEST(OutputPaths, AcceptsAbsentAndRegularFiles) {
    TemporaryDirectory dir("outputs");
    dir.write("old.exr", "previous render");
    EXPECT_EQ(refusal({{(dir / "new.exr").string(), "--output"}, {(dir / "old.exr").string(), "--stats-json"}}), "");
}

// A device node made here, never the real /dev/null: the check must refuse it before anything replaces it.
TEST(OutputPaths, RefusesADeviceNodeAndLeavesIt) {
    TemporaryDirectory dir("outputs");
    const fs::path device = dir / "null";
    if (::mknod(device.c_str(), S_IFCHR | 0666, makedev(1, 3)) != 0) GTEST_SKIP() << "mknod needs privileges here";
    const std::string message = refusal({{device.string(), "--stats-json"}});
    EXPECT_NE(message.find("--stats-json"), std::string::npos) << message;
    EXPECT_NE(message.find("character device"), std::string::npos) << message;
    struct stat status {};
    ASSERT_EQ(::lstat(device.c_str(), &status), 0);
    EXPECT_TRUE(S_ISCHR(status.st_mode));
}

TEST(OutputPaths, RefusesAFifoADirectoryAndASymlink) {
    TemporaryDirectory dir("outputs");
    ASSERT_EQ(::mkfifo((dir / "fifo").c_str(), 0666), 0);
    fs::create_directory(dir / "folder.png");
    dir.write("victim.txt", "precious");
    fs::create_symlink(dir / "victim.txt", dir / "link.png");
    EXPECT_NE(refusal({{(dir / "fifo").string(), "-o"}}).find("a FIFO"), std::string::npos);
    EXPECT_NE(refusal({{(dir / "folder.png").string(), "-o"}}).find("directory"), std::string::npos);
    EXPECT_NE(refusal({{(dir / "link.png").string(), "-o"}}).find("symbolic link"), std::string::npos);
    EXPECT_EQ(read_file(dir / "victim.txt"), "precious");
}

TEST(OutputPaths, RefusesAnOutputThatIsAnInputWhateverTheSpelling) {
    TemporaryDirectory dir("outputs");
    const fs::path scene = dir.write("scene.json", "{}");
    fs::create_directory(dir / "sub");
    const std::string spelled_otherwise = (dir / "sub" / ".." / "scene.json").string();
    const std::string message = refusal({{spelled_otherwise, "--stats-json"}}, {{scene.string(), "the scene"}});
    EXPECT_NE(message.find("the scene"), std::string::npos) << message;
    fs::create_hard_link(scene, dir / "hard.json");
    EXPECT_NE(refusal({{(dir / "hard.json").string(), "-o"}}, {{scene.string(), "the scene"}}), "");
}

TEST(OutputPaths, RefusesTwoOutputsThatAreOneFile) {
    TemporaryDirectory dir("outputs");
    const std::string a = (dir / "x.exr").string(), b = (dir / "sub" / ".." / "x.exr").string();
    fs::create_directory(dir / "sub");
    const std::string message = refusal({{a, "--output"}, {b, "--stats-json"}});
    EXPECT_NE(message.find("same file as --output"), std::string::npos) << message;
}

TEST(OutputPaths, StandardOutputOnlyWhereAllowedAndOnce) {
    EXPECT_EQ(refusal({{"-", "--stats-json", true}}), "");
    EXPECT_NE(refusal({{"-", "--checkpoint"}}), "");
    EXPECT_NE(refusal({{"-", "--stats-json", true}, {"-", "--json", true}}).find("standard output"), std::string::npos);
}

TEST(OutputPaths, RefusesANulInsideAPath) {
    TemporaryDirectory dir("outputs");
    const std::string path = (dir / "a").string() + std::string(1, '\0') + ".exr";
    EXPECT_NE(refusal({{path, "-o"}}).find("NUL"), std::string::npos);
}

TEST(OutputPaths, SameFileRecognisesSpellingsOfExistingAndNewFiles) {
    TemporaryDirectory dir("outputs");
    fs::create_directory(dir / "sub");
    dir.write("ck.bin", "x");
    EXPECT_TRUE(same_file((dir / "ck.bin").string(), (dir / "sub" / ".." / "ck.bin").string()));
    EXPECT_TRUE(same_file((dir / "new.bin").string(), (dir / "sub" / ".." / "new.bin").string()));
    EXPECT_FALSE(same_file((dir / "ck.bin").string(), (dir / "new.bin").string()));
}

// The last line of defence: a path that became a FIFO after the checks is not replaced by the atomic write.
TEST(OutputPaths, AtomicWriteNeverReplacesAFifo) {
    TemporaryDirectory dir("outputs");
    const fs::path fifo = dir / "stats.json";
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0666), 0);
    EXPECT_THROW(write_file_atomically(fifo, "{}"), std::runtime_error);
    struct stat status {};
    ASSERT_EQ(::lstat(fifo.c_str(), &status), 0);
    EXPECT_TRUE(S_ISFIFO(status.st_mode));
    EXPECT_EQ(dir.entries(), std::vector<std::string>{"stats.json"});
}

// Names near NAME_MAX still leave room for the temporary sibling.
TEST(OutputPaths, AtomicWriteAcceptsTheLongestFileName) {
    TemporaryDirectory dir("outputs");
    const fs::path target = dir / (std::string(NAME_MAX - 4, 'a') + ".exr");
    write_file_atomically(target, "pixels");
    EXPECT_EQ(read_file(target), "pixels");
    EXPECT_EQ(dir.entries().size(), 1u);
}

}  // namespace
}  // namespace isotrace
