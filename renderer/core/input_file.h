#pragma once
// Input files: what the process reads must be a regular file. A FIFO would block forever, a device (/dev/zero,
// /dev/urandom) would stream without end, and a directory opens fine on Linux and reads as empty; each is refused
// with a message that says what the path is instead of "file not found".
#include <cstdint>
#include <filesystem>
#include <string>

namespace isotrace {

// Throws InputError({path}) unless `path` names a regular file (symlinks followed), saying what it names instead:
// nothing, a directory, a FIFO, a character or block device, a socket. A path with a NUL inside is refused too: the
// system would open only the part before the NUL. Never opens the path, so a FIFO cannot block the check.
void require_regular_input(const std::filesystem::path& path);

// Reads the whole regular file `path`, refusing more than `max_bytes` ("larger than the limit of 64.0 MB " + `limit`,
// which says whose limit it is and how to raise it). Opened without blocking and checked on the
// open descriptor, so a path swapped for a FIFO or device after require_regular_input is still refused. Errors are
// InputError({path}) naming the reason (read errors included: /proc/self/mem fails with EIO).
std::string read_input_file(const std::filesystem::path& path, std::uint64_t max_bytes, const std::string& limit);

}  // namespace isotrace
