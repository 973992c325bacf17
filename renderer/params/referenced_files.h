#pragma once
// The external files a scene file names (meshes, textures, ...), collected while it loads, so that checkpoints
// can tell whether a scene is still the one they were made from. Thread-safe: plugins may load in parallel.
#include <filesystem>
#include <mutex>
#include <set>
#include <vector>

namespace isotrace {

class ReferencedFiles {
public:
    void add(const std::filesystem::path& file) {
        std::lock_guard lock(mutex_);
        files_.insert(file);
    }
    std::vector<std::filesystem::path> sorted() const {
        std::lock_guard lock(mutex_);
        return {files_.begin(), files_.end()};
    }

private:
    mutable std::mutex mutex_;
    std::set<std::filesystem::path> files_;
};

}  // namespace isotrace
