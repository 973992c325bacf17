#pragma once
// The sweep deformers ("sweep", "sweep_hierarchy") also hand out their sweeps, before or after the edits, so
// that the "sweep_tubes" shape can show them (the translucent tubes of the figures).
#include <vector>

#include "geometry/mesh/mesh_deformer.h"
#include "geometry/sweep/sweep_surface.h"

namespace isotrace {

class SweepFamilyDeformer : public MeshDeformer {
public:
    // `mesh`: where radii left out of the key sections are measured.
    virtual std::vector<SweepSurface> sweeps(const TriangleMeshData& mesh, bool edited) const = 0;
};

}  // namespace isotrace
