#include "renderer/core/atomic_file.h"

#include <unistd.h>

#include <atomic>
#include <stdexcept>
#include <string>

namespace isotrace {

void write_atomically(const std::filesystem::path& target,
                      const std::function<void(const std::filesystem::path& temporary)>& write) {
    std::filesystem::path temporary = target;
    // Unique per process and per call, so concurrent writers of one target never share a temporary.
    static std::atomic<unsigned> counter{0};
    temporary.replace_filename("." + target.stem().string() + ".partial-" + std::to_string(::getpid()) + "-" +
                               std::to_string(counter++) + target.extension().string());
    try {
        write(temporary);
        std::filesystem::rename(temporary, target);
    } catch (...) {
        std::error_code ignored;
        std::filesystem::remove(temporary, ignored);
        throw;
    }
}

}  // namespace isotrace
