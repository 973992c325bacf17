#pragma once
#include <filesystem>
#include <functional>

namespace isotrace {

// Calls write(temporary) with a sibling path of `target` that keeps its extension (image writers choose the
// format by extension), then renames it over `target`. If write throws, the temporary is removed and
// `target` is untouched, so a failure never leaves a truncated file under the requested name.
void write_atomically(const std::filesystem::path& target,
                      const std::function<void(const std::filesystem::path& temporary)>& write);

}  // namespace isotrace
