#pragma once
// The output policy: what a command may replace. An output is a regular file or absent — never a device, FIFO,
// socket, directory or symbolic link — and never one of the command's inputs or another of its outputs; the same file
// is recognised by device and inode, whatever the spelling (relative, "..", hard links, symlinked directories).
// Checked before any work starts, and again by write_file_atomically just before it replaces a file.
#include <string>
#include <vector>

namespace isotrace {

// `path` as the user gave it; `name` says which one it is in messages ("--stats-json", "the scene").
struct NamedPath {
    std::string path;
    std::string name;
    bool may_be_standard_output = false;  // "-" is standard output here; elsewhere it is refused
};

// "-" as an output path: standard output, written as a stream without a temporary file.
inline constexpr const char* kStandardOutput = "-";

// Throws InputError(field = the output's name) for the first output that breaks the policy: a path with a NUL, a
// path that is not a regular file, a missing or unwritable directory, an output that is an input, two outputs that
// are one file (two "-" included). Inputs that do not exist are ignored (they are reported where they are read).
void check_output_paths(const std::vector<NamedPath>& outputs, const std::vector<NamedPath>& inputs);

// Whether two paths name one file (existing, or to be created in one directory under one name).
bool same_file(const std::string& a, const std::string& b);

// Throws std::runtime_error naming `target` if it exists and is not a regular file: the last check before a rename
// replaces it, for outputs written long after check_output_paths (checkpoints during a render).
void require_replaceable(const std::string& target);

}  // namespace isotrace
