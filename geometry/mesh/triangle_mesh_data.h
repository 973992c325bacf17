#pragma once
// A triangle mesh as read from a file, before any acceleration structure is built: shared vertices with
// optional per-vertex shading normals and texture coordinates, and triangles indexing them.
#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "renderer/math/transform.h"
#include "renderer/math/vec3.h"

namespace isotrace {

struct MeshBounds {
    Vec3f min;
    Vec3f max;
};

struct TriangleMeshData {
    std::vector<Vec3f> positions;
    std::vector<Vec3f> normals;                      // empty, or one per position (shading normals, any length)
    std::vector<std::array<float, 2>> uvs;           // empty, or one per position
    std::vector<std::array<std::uint32_t, 3>> triangles;  // indices into positions, counter-clockwise = front

    // Throws InputError naming `file` unless the mesh has triangles, every index is in range, every position,
    // normal and uv is finite, and the attribute arrays match the positions in size.
    void validate(const std::string& file) const;

    // Drops triangles whose area is exactly zero (they can never be hit, and their geometric normal is
    // undefined). Returns how many were dropped. Vertices are kept, so indices stay valid.
    std::size_t remove_degenerate_triangles();

    // Bounds of all positions; min > max on every axis when there are none.
    MeshBounds bounds() const;

    // Adds the positions and triangles of `part` (its normals are dropped: for meshes whose normals are computed
    // afterwards). The uvs are kept while every part has them, and dropped as soon as one has none.
    void append_positions_and_triangles(const TriangleMeshData& part);

    // Carries the mesh by `to_world`: positions, normals (by the inverse transpose), and for a mirroring transform
    // two corners of every triangle swapped, so that the front (the outside of a closed mesh) stays the front.
    void transform(const Transform& to_world);
};

}  // namespace isotrace
