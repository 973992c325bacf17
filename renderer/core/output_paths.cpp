#include "renderer/core/output_paths.h"

#include <sys/stat.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <optional>
#include <stdexcept>

#include "renderer/core/atomic_file.h"
#include "renderer/core/file_kind.h"
#include "renderer/core/input_error.h"

namespace isotrace {
namespace {

namespace fs = std::filesystem;

// Which file a path names: the device and inode of an existing file, or of its directory plus the name for one
// that does not exist yet (two spellings of one new file still collide).
struct FileIdentity {
    dev_t device = 0;
    ino_t inode = 0;
    std::string name;  // empty for an existing file

    bool operator==(const FileIdentity&) const = default;
};

std::optional<FileIdentity> existing_identity(const std::string& path) {
    struct stat status {};
    if (::stat(path.c_str(), &status) != 0) return std::nullopt;
    return FileIdentity{status.st_dev, status.st_ino, {}};
}

std::string directory_of(const std::string& path) {
    const fs::path parent = fs::path(path).parent_path();
    return parent.empty() ? "." : parent.string();
}

// The identity of an existing file, else of the file `path` would create; none if its directory is missing.
std::optional<FileIdentity> identity(const std::string& path) {
    if (auto existing = existing_identity(path)) return existing;
    struct stat parent {};
    if (::stat(directory_of(path).c_str(), &parent) != 0) return std::nullopt;
    return FileIdentity{parent.st_dev, parent.st_ino, fs::path(path).filename().string()};
}

struct CheckedOutput {
    const NamedPath* output;
    FileIdentity identity;
};

[[noreturn]] void refuse(const NamedPath& output, const std::string& problem) {
    throw InputError({}, output.name, "\"" + output.path + "\" " + problem);
}

// The policy for one output path on its own; returns its identity.
FileIdentity check_one(const NamedPath& output) {
    if (output.path.empty()) refuse(output, "is an empty file name");
    if (output.path.find('\0') != std::string::npos) refuse(output, "contains a NUL character");
    struct stat status {};
    if (::lstat(output.path.c_str(), &status) == 0) {
        if (S_ISLNK(status.st_mode))
            refuse(output, "is a symbolic link: isotrace replaces only regular files, never a link or what it points "
                           "to (remove the link, or name its target)");
        if (!S_ISREG(status.st_mode))
            refuse(output, "is " + describe_file_kind(status) + ": an output must be a regular file or not exist yet");
    } else if (errno != ENOENT) {
        refuse(output, std::string("cannot be examined: ") + std::strerror(errno));
    }
    const std::string directory = directory_of(output.path);
    struct stat parent_status {};
    if (::stat(directory.c_str(), &parent_status) != 0 || !S_ISDIR(parent_status.st_mode))
        refuse(output, "is in a directory that does not exist (\"" + directory + "\")");
    try {
        check_atomically_writable(output.path);
    } catch (const std::runtime_error& problem) {
        throw InputError({}, output.name, problem.what());
    }
    return *identity(output.path);
}

}  // namespace

void check_output_paths(const std::vector<NamedPath>& outputs, const std::vector<NamedPath>& inputs) {
    std::vector<CheckedOutput> checked;
    const NamedPath* standard_output = nullptr;
    for (const NamedPath& output : outputs) {
        if (output.path == kStandardOutput) {
            if (!output.may_be_standard_output)
                refuse(output, "(standard output) cannot be used here: name a file (\"./-\" for a file named -)");
            if (standard_output)
                throw InputError({}, output.name,
                                 "both " + standard_output->name + " and " + output.name +
                                     " write to standard output (\"-\"): give one of them a file");
            standard_output = &output;
            continue;
        }
        const FileIdentity identity = check_one(output);
        for (const CheckedOutput& earlier : checked)
            if (earlier.identity == identity)
                refuse(output, "is the same file as " + earlier.output->name + " \"" + earlier.output->path +
                                   "\": each output needs a file of its own");
        checked.push_back({&output, identity});
    }
    for (const NamedPath& input : inputs) {
        const std::optional<FileIdentity> identity = existing_identity(input.path);
        if (!identity) continue;
        for (const CheckedOutput& output : checked)
            if (output.identity == *identity)
                refuse(*output.output, "is " + input.name + " (\"" + input.path +
                                           "\"): an output may not replace an input");
    }
}

bool same_file(const std::string& a, const std::string& b) {
    if (a == b) return true;
    const auto first = identity(a), second = identity(b);
    return first && second && *first == *second;
}

void require_replaceable(const std::string& target) {
    struct stat status {};
    if (::lstat(target.c_str(), &status) != 0) return;
    if (!S_ISREG(status.st_mode))
        throw std::runtime_error("cannot write " + target + ": it is " + describe_file_kind(status) +
                                 " now, and isotrace replaces only regular files");
}

}  // namespace isotrace
