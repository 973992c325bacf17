#pragma once
// The ray queries of one blob cell (BlobGroup's sweeps: the first crossing, occlusion, every crossing), built twice:
// for baseline x86-64 in the library and for AVX2 in a module beside it (blob_cell_sweep.cpp), chosen once per
// process. Four doubles are one AVX register and two SSE2 ones, and the sweep is mostly such lanes
// (metaball_sweep.h): the AVX2 build runs blobs_1k's rays ×1.2–1.3 as fast (docs/decisions.md, "Blob cell
// queries built twice"). Without FMA, both builds round alike, so a render is the same bits on any x86-64 CPU
// (tested).
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "geometry/implicit/sweep_piece.h"
#include "renderer/math/vec3.h"

namespace isotrace {

class BlobGroup;
struct CellHit;

enum class BlobIsa { Baseline, Avx2 };

// The queries compiled for one instruction set; BlobGroup befriends every one.
template <BlobIsa>
class BlobCellSweep;

struct BlobCellQueries {
    // BlobGroup::first_crossing_in_cell, occluded_in_cell, and every crossing in the cell appended to `out` (a
    // crossing equal to out's last one from index `first` on is not repeated: cells share faces).
    std::optional<CellHit> (*first_crossing)(const BlobGroup& group, std::uint32_t cell, const Vec3d& origin,
                                             const Vec3d& direction, double t_min, double t_max, BlobQueryWork& work);
    bool (*occluded)(const BlobGroup& group, std::uint32_t cell, const Vec3d& origin, const Vec3d& direction,
                     double t_min, double t_max, BlobQueryWork& work);
    void (*crossings)(const BlobGroup& group, std::uint32_t cell, const Vec3d& origin, const Vec3d& direction,
                      double t_min, double t_max, std::vector<FieldCrossing>& out, std::size_t first,
                      BlobQueryWork& work);
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
