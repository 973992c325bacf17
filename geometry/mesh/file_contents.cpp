#include "geometry/mesh/file_contents.h"

#include "renderer/core/input_file.h"
#include "renderer/core/memory_budget.h"

namespace isotrace {

std::string read_file_contents(const std::string& path) {
    return read_input_file(path, MemoryBudget::default_limit_bytes(),
                           "for mesh files (80 % of physical memory)");
}

}  // namespace isotrace
