#pragma once
// Embree 3 intersects a BVH whose root is a leaf without testing that leaf's box: when the user geometries of a
// scene hold a single primitive between them, its callback runs for every ray of the scene, wherever the ray goes
// (one superquadric beside a mesh floor, a speck behind the camera). A second primitive that is never hit makes
// the root an inner node, whose children's boxes are tested first.
#include <embree3/rtcore.h>

#include "renderer/math/vec3.h"

namespace isotrace {

class InnerRootSentinel {
public:
    // Adds to `scene` (not yet committed) a user geometry of one primitive, a point that no callback reports.
    // The point should lie in the lone primitive's box, so that the scene's bounds do not change. The sentinel
    // must outlive the scene's builds.
    void add_to(RTCDevice device, RTCScene scene, const Vec3f& point);

private:
    static void bounds(const RTCBoundsFunctionArguments* args);
    Vec3f point_;
};

}  // namespace isotrace
