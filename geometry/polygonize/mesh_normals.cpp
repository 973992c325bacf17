#include "geometry/polygonize/mesh_normals.h"

#include "renderer/core/parallel_for.h"

namespace isotrace {

std::vector<Vec3f> field_normals(const ImplicitField& field, const std::vector<Vec3f>& positions) {
    std::vector<Vec3f> normals(positions.size());
    parallel_for(std::size_t(0), positions.size(), [&](std::size_t i) {
        const Vec3d g = field.gradient(Vec3d(positions[i]));
        const double l = length(g);
        normals[i] = l > 0 && std::isfinite(l) ? Vec3f(g / l) : Vec3f(0, 0, 1);
    });
    return normals;
}

}  // namespace isotrace
