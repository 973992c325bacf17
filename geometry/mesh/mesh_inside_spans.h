#pragma once
// The inside spans of a line through a closed, outward-facing mesh, from its crossings with the surface.
#include <vector>

#include "geometry/mesh/mesh_crossing_scene.h"
#include "renderer/plugin/solid.h"

namespace isotrace {

// `crossings` (sorted here) are all crossings of origin + t·direction with the mesh from a point outside it. A
// crossing against a triangle's front enters, along it leaves. Crossings within `tolerance` in t of the first of
// a group count as one event whose net direction decides: a line through an edge crosses both triangles there,
// and a line grazing a silhouette enters and leaves at once. Appends unclipped spans in increasing t.
void mesh_inside_spans(std::vector<MeshCrossing>& crossings, const Vec3d& direction, double tolerance,
                       std::vector<InsideSpan>& spans);

}  // namespace isotrace
