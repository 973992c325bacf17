#pragma once
// The JSON form of sweeps, key-section edits and deformer options, shared by the "sweep" and "sweep_hierarchy"
// deformers and the "sweep_tubes" shape (docs/scene-format.md, "Sweep deformers"). Everything is read when the
// deformer is created (so unknown keys are reported at once); radii left out are measured from the mesh when
// the deformer is applied, and errors then still name their place in the file.
#include <optional>
#include <string>
#include <vector>

#include "geometry/mesh/triangle_mesh_data.h"
#include "geometry/sweep/key_section.h"
#include "geometry/sweep/multi_resolution_sweep.h"
#include "geometry/sweep/sweep_surface.h"
#include "renderer/params/scene_node.h"

namespace isotrace {

struct KeySectionSpec {
    SceneNode node;
    Vec3d centre;
    Quaternion orientation;
    std::vector<double> radii;  // empty: measured from the mesh
};

struct SweepSpec {
    SceneNode node;
    std::string name;
    std::vector<KeySectionSpec> keys;
    int radius_samples = 16;
    bool relative = false;  // key centres and rotations relative to the previous key section
    double measured_radius_scale = 1;  // measured radii are multiplied by it (a sweep should enclose its part)
    bool measure_circle = false;       // measured sections become circles of the largest measured radius
    SweepSpline spline = SweepSpline::cubic;

    // Radii per key section: those given, or the samples measured.
    std::size_t radius_count() const {
        return keys.front().radii.empty() ? std::size_t(radius_samples) : keys.front().radii.size();
    }
    // Whether radii are measured on the mesh (which is then traced: RadiusProbe).
    bool measures_radii() const;

    // Absolute key sections, missing radii measured on `mesh` (null: an error names the key section).
    std::vector<KeySection> key_sections(const TriangleMeshData* mesh) const;
};

struct EditSpec {
    SceneNode node;
    std::string sweep;  // hierarchy edits: the sweep's name
    int level = 1;
    int key = 0;
    KeyEdit edit;
    std::optional<Vec3d> pull;  // hierarchy edits of loop-bound sweeps: move the key centre by this much
};

SweepSpec parse_sweep_spec(const SceneNode& node);
// `hierarchy`: edits name their sweep and may pull; otherwise they may name a level.
EditSpec parse_edit_spec(const SceneNode& node, bool hierarchy);

}  // namespace isotrace
