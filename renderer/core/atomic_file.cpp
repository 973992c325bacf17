#include "renderer/core/atomic_file.h"

#include <fcntl.h>
#include <sys/random.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <string>

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

// Creates a fresh sibling of `target`; returns its descriptor and sets `temporary` to its path.
int create_temporary(const std::filesystem::path& target, std::filesystem::path& temporary) {
    constexpr int kAttempts = 16;  // a collision with 82 random bits means someone is planting names: give up
    for (int attempt = 0; attempt < kAttempts; ++attempt) {
        temporary = target;
        temporary.replace_filename("." + target.stem().string() + ".partial-" + random_suffix() +
                                   target.extension().string());
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

}  // namespace

void check_atomically_writable(const std::filesystem::path& target) {
    std::error_code ignored;
    if (std::filesystem::is_directory(target, ignored))
        throw std::runtime_error("cannot write " + target.string() + ": it is a directory");
    std::filesystem::path probe;
    ::close(create_temporary(target, probe));
    ::unlink(probe.c_str());
}

void write_file_atomically(const std::filesystem::path& target, std::string_view bytes) {
    std::filesystem::path temporary;
    int fd = create_temporary(target, temporary);
    try {
        write_all(fd, bytes, target);
        if (::fsync(fd) != 0) fail(target, "flushing to disk failed", errno);
        const int closed = ::close(fd);
        fd = -1;
        if (closed != 0) fail(target, "closing failed", errno);
        if (::rename(temporary.c_str(), target.c_str()) != 0) fail(target, "cannot rename the temporary file", errno);
    } catch (...) {
        if (fd >= 0) ::close(fd);
        ::unlink(temporary.c_str());
        throw;
    }
}

}  // namespace isotrace
