#pragma once
// Entry point for mesh files: picks the loader from the file extension.
#include <string>

#include "geometry/mesh/triangle_mesh_data.h"
#include "renderer/core/memory_budget.h"

namespace isotrace {

// Quads per patch edge when a Bézier patch file (.bpt) is tessellated.
inline constexpr int kBezierPatchSteps = 16;

// .obj, .ply or .bpt (Bézier patches, tessellated), in any letter case. Throws InputError naming `path` for an
// unsupported extension or any problem the loader finds. The result is validated; degenerate triangles are kept.
// Bézier patches and their tessellation are charged to `memory` before they are made.
TriangleMeshData load_mesh_file(const std::string& path, MemoryBudget& memory);

}  // namespace isotrace
