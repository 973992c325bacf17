#pragma once
// One wording for every out-of-range index, whichever loader or check finds it.
#include <cstddef>
#include <string>
#include <string_view>

namespace isotrace {

// "vertex index 99 out of range (vertex count 8)". `shown_index` is the index as the file numbers it
// (OBJ counts from 1, PLY from 0), so the user can find it.
inline std::string index_out_of_range_problem(std::string_view what, long long shown_index, std::size_t count) {
    const std::string name(what);
    return name + " index " + std::to_string(shown_index) + " out of range (" + name + " count " +
           std::to_string(count) + ")";
}

}  // namespace isotrace
