#include "renderer/core/atomic_file.h"

#include <gtest/gtest.h>
#include <sys/resource.h>
#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <fstream>
#include <stdexcept>
#include <string>

#include "tests/support/scene_files.h"

namespace isotrace {
namespace {

using isotrace::testing::read_file;
using isotrace::testing::TemporaryDirectory;
namespace fs = std::filesystem;

void write_text(const fs::path& path, const std::string& text) {
    std::ofstream out(path, std::ios::binary);
    out << text;
    ASSERT_TRUE(out.good()) << path;
}

TEST(WriteFileAtomically, WritesTheBytesAndLeavesOnlyTheTarget) {
    TemporaryDirectory dir("atomic");
    const fs::path target = dir / "image.exr";
    write_file_atomically(target, std::string("pix\0els", 7));
    EXPECT_EQ(read_file(target), std::string("pix\0els", 7));
    EXPECT_EQ(dir.entries(), std::vector<std::string>{"image.exr"});
}

TEST(WriteFileAtomically, ReplacesAnExistingTarget) {
    TemporaryDirectory dir("atomic");
    const fs::path target = dir / "out.exr";
    write_text(target, "old");
    write_file_atomically(target, "new");
    EXPECT_EQ(read_file(target), "new");
    EXPECT_EQ(dir.entries(), std::vector<std::string>{"out.exr"});
}

// A link is not the command's to replace, and what it points to may be anything: neither is touched.
TEST(WriteFileAtomically, SymlinkAtTheTargetIsRefusedAndItAndItsReferentKeptIntact) {
    TemporaryDirectory dir("atomic");
    const fs::path victim = dir / "victim.txt";
    write_text(victim, "precious");
    const fs::path target = dir / "out.png";
    fs::create_symlink(victim, target);
    EXPECT_THROW(write_file_atomically(target, "image"), std::runtime_error);
    EXPECT_EQ(read_file(victim), "precious");
    EXPECT_TRUE(fs::is_symlink(target));
    EXPECT_EQ(dir.entries(), (std::vector<std::string>{"out.png", "victim.txt"}));
}

// The old temporary name was predictable (".<stem>.partial-<pid>-<n><ext>"): symlinks planted at every such name
// must neither be followed nor turn the output into a symlink.
TEST(WriteFileAtomically, SymlinksPlantedAtPredictableTemporaryNamesAreNeverFollowed) {
    TemporaryDirectory dir("atomic");
    const fs::path victim = dir / "victim.txt";
    write_text(victim, "precious");
    for (int n = 0; n < 64; ++n)
        fs::create_symlink(victim, dir / (".out.partial-" + std::to_string(::getpid()) + "-" + std::to_string(n) + ".png"));
    const fs::path target = dir / "out.png";
    write_file_atomically(target, "image");
    EXPECT_EQ(read_file(victim), "precious");
    EXPECT_FALSE(fs::is_symlink(target));
    EXPECT_EQ(read_file(target), "image");
    EXPECT_EQ(dir.entries().size(), 64u + 2u);  // the planted links, the victim and the output; no temporary
}

TEST(WriteFileAtomically, MissingDirectoryThrowsNamingTheTarget) {
    TemporaryDirectory dir("atomic");
    const fs::path target = dir / "no_such_dir" / "out.exr";
    try {
        write_file_atomically(target, "x");
        FAIL() << "expected an error";
    } catch (const std::runtime_error& error) {
        EXPECT_NE(std::string(error.what()).find(target.string()), std::string::npos) << error.what();
    }
    EXPECT_TRUE(dir.entries().empty());
}

// Disk full and a file-size limit fail the same way (write returns an error part-way): the limit is testable
// without a small file system. SIGXFSZ is ignored as isotrace's main() does, so write() reports EFBIG.
TEST(WriteFileAtomically, FileSizeLimitLeavesNeitherTargetNorTemporaryAndKeepsTheOldTarget) {
    TemporaryDirectory dir("atomic");
    const fs::path target = dir / "out.png";
    write_text(target, "previous render");
    rlimit saved{};
    ASSERT_EQ(::getrlimit(RLIMIT_FSIZE, &saved), 0);
    rlimit small = saved;
    small.rlim_cur = 4096;
    const auto previous_handler = std::signal(SIGXFSZ, SIG_IGN);
    ASSERT_EQ(::setrlimit(RLIMIT_FSIZE, &small), 0);
    std::string error;
    try {
        write_file_atomically(target, std::string(1 << 20, 'x'));
    } catch (const std::runtime_error& e) {
        error = e.what();
    }
    ::setrlimit(RLIMIT_FSIZE, &saved);
    std::signal(SIGXFSZ, previous_handler);
    EXPECT_NE(error.find("out.png"), std::string::npos) << "no error naming the target: \"" << error << "\"";
    EXPECT_EQ(read_file(target), "previous render");
    EXPECT_EQ(dir.entries(), std::vector<std::string>{"out.png"});
}

// A signal handler that ends the process in the middle of a write (a second Ctrl-C) removes the temporary file
// first. The signal here is SIGXFSZ, raised by a file-size limit inside write(), so it arrives deterministically
// while the temporary file exists; the child process ends from the handler like isotrace's second signal does.
extern "C" void remove_temporaries_and_exit(int) {
    remove_temporary_files_in_progress();
    ::_exit(42);
}

// Forks a child that writes 1 MiB to `target` under a 4 KiB file-size limit, with `on_limit` handling SIGXFSZ,
// so that the handler runs inside write(); the child exits 1 if the handler returns. Returns its wait status.
int write_past_size_limit_in_child(const fs::path& target, void (*on_limit)(int)) {
    const pid_t child = ::fork();
    if (child < 0) return -1;
    if (child == 0) {
        std::signal(SIGXFSZ, on_limit);
        rlimit small{};
        ::getrlimit(RLIMIT_FSIZE, &small);
        small.rlim_cur = 4096;
        ::setrlimit(RLIMIT_FSIZE, &small);
        try {
            write_file_atomically(target, std::string(1 << 20, 'x'));
        } catch (...) {
        }
        ::_exit(1);
    }
    int status = -1;
    ::waitpid(child, &status, 0);
    return status;
}

TEST(WriteFileAtomically, SignalHandlerRemovesTheTemporaryFileOfAWriteInProgress) {
    TemporaryDirectory dir("atomic");
    const int status = write_past_size_limit_in_child(dir / "out.exr", remove_temporaries_and_exit);
    ASSERT_TRUE(WIFEXITED(status));
    EXPECT_EQ(WEXITSTATUS(status), 42);
    EXPECT_TRUE(dir.entries().empty()) << dir.entries().front();
}

// SIGKILL cannot be caught, so nothing can clean up after it: the bytes are written to an unnamed file that the
// kernel discards with the process. The kill arrives deterministically mid-write: a file-size limit raises SIGXFSZ
// inside write(), and its handler sends SIGKILL.
extern "C" void kill_self(int) { ::kill(::getpid(), SIGKILL); }

TEST(WriteFileAtomically, SigkillDuringTheWriteLeavesNothingBehindAndKeepsTheOldTarget) {
    TemporaryDirectory dir("atomic");
    const int probe = ::open(dir.path().c_str(), O_TMPFILE | O_WRONLY, 0600);
    if (probe < 0) GTEST_SKIP() << "the file system of " << dir.path() << " has no O_TMPFILE";
    ::close(probe);
    const fs::path target = dir / "checkpoint.bin";
    write_text(target, "previous checkpoint");
    const int status = write_past_size_limit_in_child(target, kill_self);
    ASSERT_TRUE(WIFSIGNALED(status));
    EXPECT_EQ(WTERMSIG(status), SIGKILL);
    EXPECT_EQ(dir.entries(), std::vector<std::string>{"checkpoint.bin"});
    EXPECT_EQ(read_file(target), "previous checkpoint");
}

}  // namespace
}  // namespace isotrace
