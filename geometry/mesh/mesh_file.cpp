#include "geometry/mesh/mesh_file.h"

#include <algorithm>
#include <cctype>
#include <filesystem>

#include "geometry/mesh/bezier_patches.h"
#include "geometry/mesh/obj_loader.h"
#include "geometry/mesh/ply_loader.h"
#include "renderer/core/input_error.h"

namespace isotrace {

TriangleMeshData load_mesh_file(const std::string& path, MemoryBudget& memory) {
    std::string extension = std::filesystem::path(path).extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    if (extension == ".obj") return load_obj(path);
    if (extension == ".ply") return load_ply(path);
    if (extension == ".bpt") {
        const std::vector<BezierPatch> patches = load_bezier_patches(path, memory);
        charge_bezier_tessellation(patches.size(), kBezierPatchSteps, path, memory);
        TriangleMeshData mesh = tessellate_bezier_patches(patches, kBezierPatchSteps);
        mesh.validate(path);
        return mesh;
    }
    const std::string found = extension.empty() ? "no file extension" : "unsupported file extension '" + extension + "'";
    throw InputError({path}, "", found + " (supported mesh formats: .obj, .ply, .bpt)");
}

}  // namespace isotrace
