#include "renderer/core/atomic_file.h"

#include <fcntl.h>
#include <sys/random.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cstdio>
#include <climits>
#include <cstring>
#include <stdexcept>
#include <string>

#include "renderer/core/output_paths.h"

namespace isotrace {
namespace {

[[noreturn]] void fail(const std::filesystem::path& target, const std::string& what, int error) {
    throw std::runtime_error("cannot write " + target.string() + ": " + what + ": " + std::strerror(error));
}

// 16 characters from [a-z0-9]: 82 bits, so a name cannot be guessed in advance to plant a file there.
std::string random_suffix() {
    unsigned char bytes[16];
    std::size_t filled = 0;
    while (filled < sizeof bytes) {
        const ssize_t got = ::getrandom(bytes + filled, sizeof bytes - filled, 0);
        if (got < 0 && errno != EINTR) throw std::runtime_error(std::string("getrandom: ") + std::strerror(errno));
        if (got > 0) filled += std::size_t(got);
    }
    static constexpr char kAlphabet[] = "abcdefghijklmnopqrstuvwxyz0123456789";
    std::string suffix;
    for (unsigned char b : bytes) suffix += kAlphabet[b % 36];
    return suffix;
}

// A hidden sibling name for the temporary file: ".<stem>.partial-<random><ext>", the stem shortened so that the name
// fits NAME_MAX (the target's own name may be up to NAME_MAX long).
std::filesystem::path temporary_sibling(const std::filesystem::path& target) {
    const std::string marker = ".partial-" + random_suffix();
    std::string stem = target.stem().string(), extension = target.extension().string();
    const std::size_t fixed = 1 + marker.size();
    if (fixed + extension.size() > NAME_MAX) extension.clear();
    stem.resize(std::min(stem.size(), std::size_t(NAME_MAX) - fixed - extension.size()));
    std::filesystem::path temporary = target;
    temporary.replace_filename("." + stem + marker + extension);
    return temporary;
}

// Creates a fresh sibling of `target`; returns its descriptor and sets `temporary` to its path.
int create_temporary(const std::filesystem::path& target, std::filesystem::path& temporary) {
    constexpr int kAttempts = 16;  // a collision with 82 random bits means someone is planting names: give up
    for (int attempt = 0; attempt < kAttempts; ++attempt) {
        temporary = temporary_sibling(target);
        const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666);
        if (fd >= 0) return fd;
        if (errno != EEXIST) fail(target, "cannot create a temporary file in its directory", errno);
    }
    fail(target, "no unused temporary name after " + std::to_string(kAttempts) + " attempts", EEXIST);
}

void write_all(int fd, std::string_view bytes, const std::filesystem::path& target) {
    while (!bytes.empty()) {
        const ssize_t written = ::write(fd, bytes.data(), bytes.size());
        if (written < 0 && errno == EINTR) continue;
        if (written < 0) fail(target, "write failed", errno);
        if (written == 0) fail(target, "write made no progress", EIO);
        bytes.remove_prefix(std::size_t(written));
    }
}

// Temporary paths of the writes in progress, for remove_temporary_files_in_progress(). A slot is Free, then
// Filling while its owner copies the path in, then Live until the temporary file is renamed or removed; a
// signal handler only reads Live slots. More concurrent writes than slots go untracked (none in practice).
class TemporaryFileRegistry {
public:
    // Returns the slot index, or -1 if none is free or the path does not fit.
    int publish(const std::filesystem::path& temporary) noexcept {
        const std::string& text = temporary.native();
        if (text.size() >= PATH_MAX) return -1;
        for (int i = 0; i < kSlots; ++i) {
            int expected = kFree;
            if (!slots_[i].state.compare_exchange_strong(expected, kFilling)) continue;
            std::memcpy(slots_[i].path, text.c_str(), text.size() + 1);
            slots_[i].state.store(kLive);
            return i;
        }
        return -1;
    }
    void withdraw(int slot) noexcept {
        if (slot >= 0) slots_[slot].state.store(kFree);
    }
    void remove_live_files() noexcept {
        for (Slot& slot : slots_)
            if (slot.state.load() == kLive) ::unlink(slot.path);
    }

private:
    static constexpr int kSlots = 8, kFree = 0, kFilling = 1, kLive = 2;
    static_assert(std::atomic<int>::is_always_lock_free, "slot states are read in signal handlers");
    struct Slot {
        std::atomic<int> state{kFree};
        char path[PATH_MAX];
    };
    Slot slots_[kSlots];
};

TemporaryFileRegistry g_temporaries;

}  // namespace

void remove_temporary_files_in_progress() noexcept { g_temporaries.remove_live_files(); }

void check_atomically_writable(const std::filesystem::path& target) {
    std::error_code ignored;
    if (std::filesystem::is_directory(target, ignored))
        throw std::runtime_error("cannot write " + target.string() + ": it is a directory");
    std::filesystem::path probe;
    ::close(create_temporary(target, probe));
    ::unlink(probe.c_str());
}

namespace {

// The flushed file `fd`, named `temporary` (registered in `slot`), becomes the target: renamed over it at once, so
// nothing else runs while the contents have a name of their own, and closed after (the data is on disk already).
// A failed rename removes the temporary file and closes `fd`.
void publish_as_target(int fd, const std::filesystem::path& temporary, const std::filesystem::path& target,
                       int slot) {
    try {
        require_replaceable(target.string());
    } catch (...) {
        ::unlink(temporary.c_str());
        g_temporaries.withdraw(slot);
        ::close(fd);
        throw;
    }
    if (::rename(temporary.c_str(), target.c_str()) != 0) {
        const int error = errno;
        ::unlink(temporary.c_str());
        g_temporaries.withdraw(slot);
        ::close(fd);
        fail(target, "cannot rename the temporary file", error);
    }
    g_temporaries.withdraw(slot);
    if (::close(fd) != 0) fail(target, "closing failed", errno);
}

// An unnamed file in the target's directory (O_TMPFILE): whatever happens to the process while it is written —
// even SIGKILL — nothing is left behind. -1 where the file system does not support it.
int open_unnamed_beside(const std::filesystem::path& target) {
    const std::filesystem::path directory = target.has_parent_path() ? target.parent_path() : ".";
    return ::open(directory.c_str(), O_TMPFILE | O_WRONLY | O_CLOEXEC, 0666);
}

// Gives the unnamed file `fd` a fresh random hidden name beside the target (for the instant before the rename),
// registered in `slot` before it exists so that nothing but the link and the rename themselves runs while it has
// that name. A SIGKILL between those two system calls is the one way a write can leave a file behind (complete,
// under the hidden name): Linux cannot link an unnamed file over an existing name. False when it cannot be linked
// (no /proc): the caller then writes a named file instead.
bool link_unnamed(int fd, const std::filesystem::path& target, std::filesystem::path& temporary, int& slot) {
    const std::string self = "/proc/self/fd/" + std::to_string(fd);
    constexpr int kAttempts = 16;
    for (int attempt = 0; attempt < kAttempts; ++attempt) {
        temporary = temporary_sibling(target);
        slot = g_temporaries.publish(temporary);
        if (::linkat(AT_FDCWD, self.c_str(), AT_FDCWD, temporary.c_str(), AT_SYMLINK_FOLLOW) == 0) return true;
        const int error = errno;
        g_temporaries.withdraw(slot);
        if (error != EEXIST) return false;
    }
    return false;
}

}  // namespace

void write_file_atomically(const std::filesystem::path& target, std::string_view bytes) {
    std::filesystem::path temporary;
    int fd = open_unnamed_beside(target);
    if (fd >= 0) {
        try {
            write_all(fd, bytes, target);
            if (::fsync(fd) != 0) fail(target, "flushing to disk failed", errno);
        } catch (...) {
            ::close(fd);  // an unnamed file disappears with its last descriptor
            throw;
        }
        int slot = -1;
        if (link_unnamed(fd, target, temporary, slot)) {
            publish_as_target(fd, temporary, target, slot);
            return;
        }
        ::close(fd);
    }
    // No O_TMPFILE (or no /proc to link it): a named temporary file from the start.
    fd = create_temporary(target, temporary);
    const int slot = g_temporaries.publish(temporary);
    try {
        write_all(fd, bytes, target);
        if (::fsync(fd) != 0) fail(target, "flushing to disk failed", errno);
    } catch (...) {
        ::close(fd);
        ::unlink(temporary.c_str());
        g_temporaries.withdraw(slot);
        throw;
    }
    publish_as_target(fd, temporary, target, slot);
}

}  // namespace isotrace
