#pragma once
// The ray queries of a blob group's cells (blob_ray.cpp), built twice: for baseline x86-64 in the library and for
// AVX2 in a module beside it. Four doubles are one AVX register and two SSE2 ones, and the march is mostly such lanes
// (metaball_march.h), so the AVX2 build is the faster (docs/decisions.md, "Blob cell queries built twice"). Which
// build runs is chosen once per process; a BlobGroup keeps it from when it was made, and its shape registers that
// build's callbacks with Embree, so no query consults the choice again. Without FMA, both builds round alike: a
// render is the same bits on any x86-64 CPU (tested).
#include <embree3/rtcore.h>

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "geometry/implicit/blob_group.h"

namespace isotrace {

// What a blob group's Embree callbacks find through geometryUserPtr: the group and the counters its work goes to.
struct BlobRayTarget {
    const BlobGroup* group = nullptr;
    int counter_slot = 0;  // the shape type's (intersection tests, candidate hits)
    BlobWorkSlots work_slots{};
};

struct BlobCellQueries {
    // Embree's intersect and occluded callbacks for the cells of a group (one primitive per surface cell; user data:
    // a BlobRayTarget). A hit stores t and the outward normal (Ng; zero where −∇F vanishes, on a hard cube's face).
    RTCIntersectFunctionN intersect;
    RTCOccludedFunctionN occluded;
    // The same on one cell for one ray: the first crossing with t in (t_min, t_max) and its normal; whether any
    // crossing lies there; and every crossing appended to `out` (a crossing equal to out's last one from index
    // `first` on is not repeated: cells share faces).
    std::optional<CellHit> (*first_hit_in_cell)(const BlobGroup& group, std::uint32_t cell, const Vec3d& origin,
                                                const Vec3d& direction, double t_min, double t_max,
                                                BlobQueryWork& work);
    bool (*occluded_in_cell)(const BlobGroup& group, std::uint32_t cell, const Vec3d& origin, const Vec3d& direction,
                             double t_min, double t_max, BlobQueryWork& work);
    void (*crossings_in_cell)(const BlobGroup& group, std::uint32_t cell, const Vec3d& origin,
                              const Vec3d& direction, double t_min, double t_max, std::vector<FieldCrossing>& out,
                              std::size_t first, BlobQueryWork& work);
    const char* isa;  // "baseline x86-64" or "avx2"
};

// The module exports this entry, const BlobCellQueries*(const char* isotrace_version): its queries when the
// library's version is its own, else nullptr (avx2_module_build).
inline constexpr const char* kBlobCellQueriesEntry = "isotrace_blob_cell_queries";

// The queries of the library's own build, and the ones this process uses (the AVX2 module's where the CPU has AVX2
// and the module loads).
const BlobCellQueries& baseline_blob_cell_queries();
const BlobCellQueries& blob_cell_queries();

}  // namespace isotrace
