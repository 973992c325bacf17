#include "renderer/core/atomic_file.h"

#include <unistd.h>

#include <stdexcept>
#include <string>

namespace isotrace {

void write_atomically(const std::filesystem::path& target,
                      const std::function<void(const std::filesystem::path& temporary)>& write) {
    std::filesystem::path temporary = target;
    temporary.replace_filename("." + target.stem().string() + ".partial-" + std::to_string(::getpid()) +
                               target.extension().string());
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
