#pragma once
// The loaders under test read files: each fuzz input is written to one scratch file per process (libFuzzer runs
// inputs one after another in a process, so the file is simply overwritten).
#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <fstream>
#include <string>

namespace isotrace::fuzz {

inline std::string write_input(const std::uint8_t* data, std::size_t size, const std::string& extension) {
    static const std::string path = "/tmp/isotrace-fuzz-" + std::to_string(::getpid()) + extension;
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), std::streamsize(size));
    return path;
}

}  // namespace isotrace::fuzz
