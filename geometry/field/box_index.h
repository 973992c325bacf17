#pragma once
// An Embree BVH over axis-aligned boxes that lists the boxes within a distance of a point (rtcPointQuery on a
// user geometry whose primitives are the boxes): which skeletal elements' supports reach a cell, say.
#include <embree3/rtcore.h>

#include <cstdint>
#include <vector>

#include "renderer/plugin/implicit_field.h"

namespace isotrace {

class BoxIndex {
public:
    explicit BoxIndex(std::vector<FieldBox> boxes);
    ~BoxIndex();
    BoxIndex(const BoxIndex&) = delete;
    BoxIndex& operator=(const BoxIndex&) = delete;

    // Calls visit(i) for every box i whose distance from `centre` is at most `radius`, in no particular order;
    // stops early when visit returns false. Thread-safe.
    template <class Visit>
    void for_each_near(const Vec3d& centre, double radius, Visit&& visit) const {
        query(centre, radius, [](void* user, std::uint32_t i) { return (*static_cast<Visit*>(user))(i); }, &visit);
    }

private:
    using Callback = bool (*)(void* user, std::uint32_t index);
    void query(const Vec3d& centre, double radius, Callback callback, void* user) const;

    std::vector<FieldBox> boxes_;
    RTCScene scene_ = nullptr;
};

}  // namespace isotrace
