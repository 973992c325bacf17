#include "renderer/core/input_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <algorithm>
#include <cstring>

#include "renderer/core/file_kind.h"
#include "renderer/core/input_error.h"
#include "renderer/core/memory_budget.h"

namespace isotrace {
namespace {

[[noreturn]] void refuse(const std::filesystem::path& path, const std::string& problem) {
    throw InputError({path.string()}, "", problem);
}

void require_regular(const std::filesystem::path& path, const struct stat& status) {
    if (!S_ISREG(status.st_mode))
        refuse(path, "is " + describe_file_kind(status) + ", not a regular file (isotrace reads only regular files)");
}

}  // namespace

void require_regular_input(const std::filesystem::path& path) {
    if (path.native().find('\0') != std::string::npos)
        refuse(path, "the file name contains a NUL character");
    if (path.empty()) refuse(path, "the file name is empty");
    struct stat status {};
    if (::stat(path.c_str(), &status) != 0) {
        const int error = errno;
        refuse(path, error == ENOENT ? std::string("file not found") : std::string("cannot open: ") + std::strerror(error));
    }
    require_regular(path, status);
}

std::string read_input_file(const std::filesystem::path& path, std::uint64_t max_bytes, const std::string& limit) {
    const auto too_large = [&] {
        refuse(path, "the file is larger than the limit of " + format_bytes(max_bytes) + " " + limit);
    };
    require_regular_input(path);
    const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC);
    if (fd < 0) refuse(path, std::string("cannot open: ") + std::strerror(errno));
    std::string contents;
    try {
        struct stat status {};
        if (::fstat(fd, &status) != 0) refuse(path, std::string("cannot open: ") + std::strerror(errno));
        require_regular(path, status);
        if (std::uint64_t(status.st_size) > max_bytes) too_large();
        // Reads until the end whatever st_size said (files in /proc report 0), and one byte past the limit at most.
        const std::uint64_t ceiling = max_bytes < UINT64_MAX ? max_bytes + 1 : max_bytes;
        contents.resize(std::size_t(std::min<std::uint64_t>(std::uint64_t(status.st_size) + 1, ceiling)));
        std::size_t filled = 0;
        for (;;) {
            if (filled == contents.size()) {
                if (filled >= ceiling) too_large();
                contents.resize(std::size_t(std::min<std::uint64_t>(std::max<std::uint64_t>(4096, 2 * filled), ceiling)));
            }
            const ssize_t got = ::read(fd, contents.data() + filled, contents.size() - filled);
            if (got < 0 && errno == EINTR) continue;
            if (got < 0) refuse(path, std::string("cannot read: ") + std::strerror(errno));
            if (got == 0) break;
            filled += std::size_t(got);
        }
        contents.resize(filled);
    } catch (...) {
        ::close(fd);
        throw;
    }
    ::close(fd);
    return contents;
}

}  // namespace isotrace
