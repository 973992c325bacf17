#pragma once
// What a path names, for messages about files of the wrong kind.
#include <sys/stat.h>

#include <string>

namespace isotrace {

// "a regular file", "a directory", "a FIFO", "a character device", "a block device", "a socket",
// "a symbolic link" (for lstat results), or "a special file".
std::string describe_file_kind(const struct stat& status);

}  // namespace isotrace
