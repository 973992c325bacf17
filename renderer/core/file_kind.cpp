#include "renderer/core/file_kind.h"

namespace isotrace {

std::string describe_file_kind(const struct stat& status) {
    switch (status.st_mode & S_IFMT) {
        case S_IFREG: return "a regular file";
        case S_IFDIR: return "a directory";
        case S_IFIFO: return "a FIFO";
        case S_IFCHR: return "a character device";
        case S_IFBLK: return "a block device";
        case S_IFSOCK: return "a socket";
        case S_IFLNK: return "a symbolic link";
        default: return "a special file";
    }
}

}  // namespace isotrace
