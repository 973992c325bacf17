// The output policy: bytes build a small directory of regular files, FIFOs, directories, symbolic and hard links,
// then name outputs and inputs in it under several spellings. check_output_paths must accept or throw InputError,
// change nothing in the directory, and accept only outputs that are regular files or absent, none of them an input
// or another output.
#include <sys/stat.h>
#include <unistd.h>

#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include "renderer/core/input_error.h"
#include "renderer/core/output_paths.h"

namespace {

namespace fs = std::filesystem;

class Bytes {
public:
    Bytes(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}
    unsigned next(unsigned range) { return at_ < size_ ? data_[at_++] % range : 0; }

private:
    const std::uint8_t* data_;
    std::size_t size_, at_ = 0;
};

// Kind, inode and contents of every entry: what no check may change.
std::map<std::string, std::string> snapshot(const fs::path& directory) {
    std::map<std::string, std::string> entries;
    for (const fs::directory_entry& entry : fs::recursive_directory_iterator(directory)) {
        struct stat status {};
        ::lstat(entry.path().c_str(), &status);
        std::string state = std::to_string(status.st_mode) + ":" + std::to_string(status.st_ino);
        if (S_ISREG(status.st_mode)) {
            std::ifstream in(entry.path(), std::ios::binary);
            state += ":" + std::string(std::istreambuf_iterator<char>(in), {});
        }
        entries[entry.path().string()] = state;
    }
    return entries;
}

bool regular_or_absent(const std::string& path) {
    struct stat status {};
    return ::lstat(path.c_str(), &status) != 0 || S_ISREG(status.st_mode);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static const fs::path root = fs::temp_directory_path() / ("isotrace-fuzz-outputs-" + std::to_string(::getpid()));
    fs::remove_all(root);
    fs::create_directories(root / "sub");
    Bytes bytes(data, size);
    const int entries = 1 + int(bytes.next(6));
    std::vector<std::string> names;
    for (int i = 0; i < entries; ++i) {
        const std::string name = "e" + std::to_string(i) + (bytes.next(2) ? ".exr" : "");
        const fs::path path = root / name;
        switch (bytes.next(6)) {
            case 0: break;  // absent
            case 1: std::ofstream(path) << "file " << i; break;
            case 2: ::mkfifo(path.c_str(), 0666); break;
            case 3: fs::create_directory(path); break;
            case 4: if (!names.empty()) fs::create_symlink(root / names[bytes.next(unsigned(names.size()))], path); break;
            case 5:
                if (!names.empty() && fs::is_regular_file(root / names.back()))
                    fs::create_hard_link(root / names.back(), path);
                break;
        }
        names.push_back(name);
    }
    const auto spelled = [&](const std::string& name) {
        switch (bytes.next(3)) {
            case 0: return (root / name).string();
            case 1: return (root / "sub" / ".." / name).string();
            default: return (root / "." / name).string();
        }
    };
    std::vector<isotrace::NamedPath> outputs, inputs;
    for (unsigned i = 0, n = 1 + bytes.next(4); i < n; ++i) {
        const bool standard = bytes.next(8) == 0;
        outputs.push_back({standard ? "-" : spelled(names[bytes.next(unsigned(names.size()))]),
                           "output " + std::to_string(i), bytes.next(2) == 0});
    }
    for (unsigned i = 0, n = bytes.next(4); i < n; ++i)
        inputs.push_back({spelled(names[bytes.next(unsigned(names.size()))]), "input " + std::to_string(i)});

    const auto before = snapshot(root);
    bool accepted = true;
    try {
        isotrace::check_output_paths(outputs, inputs);
    } catch (const isotrace::InputError&) {
        accepted = false;
    }
    if (snapshot(root) != before) std::abort();  // the check changed the directory
    if (accepted) {
        for (std::size_t i = 0; i < outputs.size(); ++i) {
            if (outputs[i].path == "-") continue;
            if (!regular_or_absent(outputs[i].path)) std::abort();
            for (std::size_t j = 0; j < outputs.size(); ++j)
                if (j != i && outputs[j].path != "-" && isotrace::same_file(outputs[i].path, outputs[j].path))
                    std::abort();
            for (const isotrace::NamedPath& input : inputs)
                if (fs::exists(input.path) && isotrace::same_file(outputs[i].path, input.path)) std::abort();
        }
    }
    fs::remove_all(root);
    return 0;
}
