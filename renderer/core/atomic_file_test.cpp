#include "renderer/core/atomic_file.h"

#include <gtest/gtest.h>

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

TEST(WriteAtomically, TargetAppearsOnlyAfterTheWriterSucceeds) {
    TemporaryDirectory dir("atomic");
    const fs::path target = dir / "image.exr";
    fs::path seen_temporary;
    write_atomically(target, [&](const fs::path& temporary) {
        seen_temporary = temporary;
        EXPECT_FALSE(fs::exists(target)) << "target must not exist while the writer runs";
        write_text(temporary, "pixels");
        EXPECT_FALSE(fs::exists(target));
    });
    EXPECT_EQ(read_file(target), "pixels");
    EXPECT_FALSE(fs::exists(seen_temporary)) << "temporary must be renamed away";
    EXPECT_EQ(dir.entries(), std::vector<std::string>{"image.exr"});
}

TEST(WriteAtomically, TemporaryIsAHiddenSiblingThatKeepsTheExtension) {
    TemporaryDirectory dir("atomic");
    const fs::path target = dir / "render.final.png";
    fs::path seen_temporary;
    write_atomically(target, [&](const fs::path& temporary) {
        seen_temporary = temporary;
        write_text(temporary, "x");
    });
    EXPECT_EQ(seen_temporary.parent_path(), target.parent_path());  // same folder: rename cannot cross devices
    EXPECT_EQ(seen_temporary.extension(), ".png");                   // image writers choose the format by it
    EXPECT_NE(seen_temporary.filename(), target.filename());
    const std::string name = seen_temporary.filename().string();
    EXPECT_EQ(name.front(), '.');
    EXPECT_NE(name.find("render.final"), std::string::npos);
}

TEST(WriteAtomically, ReplacesAnExistingTargetOnSuccess) {
    TemporaryDirectory dir("atomic");
    const fs::path target = dir / "out.exr";
    write_text(target, "old");
    write_atomically(target, [&](const fs::path& temporary) { write_text(temporary, "new"); });
    EXPECT_EQ(read_file(target), "new");
    EXPECT_EQ(dir.entries(), std::vector<std::string>{"out.exr"});
}

TEST(WriteAtomically, ThrowingWriterLeavesNeitherTargetNorTemporary) {
    TemporaryDirectory dir("atomic");
    const fs::path target = dir / "out.exr";
    fs::path seen_temporary;
    EXPECT_THROW(write_atomically(target,
                                  [&](const fs::path& temporary) {
                                      seen_temporary = temporary;
                                      write_text(temporary, "half a fi");
                                      throw std::runtime_error("disk full");
                                  }),
                 std::runtime_error);
    EXPECT_FALSE(seen_temporary.empty());
    EXPECT_FALSE(fs::exists(seen_temporary));
    EXPECT_FALSE(fs::exists(target));
    EXPECT_TRUE(dir.entries().empty());
}

TEST(WriteAtomically, FailureLeavesAnExistingTargetUntouched) {
    TemporaryDirectory dir("atomic");
    const fs::path target = dir / "out.png";
    write_text(target, "previous render");
    try {
        write_atomically(target, [&](const fs::path& temporary) {
            write_text(temporary, "trunc");
            throw std::runtime_error("encoder failed");
        });
        FAIL() << "the writer's exception must propagate";
    } catch (const std::runtime_error& error) {
        EXPECT_STREQ(error.what(), "encoder failed");  // the original exception, not a wrapper
    }
    EXPECT_EQ(read_file(target), "previous render");
    EXPECT_EQ(dir.entries(), std::vector<std::string>{"out.png"});
}

TEST(WriteAtomically, WriterThatCreatesNoFileIsAnErrorAndLeavesNoTarget) {
    TemporaryDirectory dir("atomic");
    const fs::path target = dir / "out.exr";
    EXPECT_THROW(write_atomically(target, [](const fs::path&) {}), fs::filesystem_error);
    EXPECT_FALSE(fs::exists(target));
    EXPECT_TRUE(dir.entries().empty());
}

}  // namespace
}  // namespace isotrace
