#pragma once
// A strict pass over OBJ text before tinyobjloader parses it. tinyobjloader reads numbers leniently: "nan" and
// "abc" become 0, and an index such as 4294967299 wraps around to 3, so a broken file would load as a wrong mesh.
#include <string>
#include <string_view>

namespace isotrace {

// Every number on a v, vn and vt line must be a finite decimal number (and there must be enough of them); every
// index on an f, l and p line must be a non-zero whole number that fits a 32-bit int. Throws InputError naming
// `path` and the line otherwise.
void check_obj_syntax(std::string_view text, const std::string& path);

}  // namespace isotrace
