// Curves shared by geometry: copies of a curve are welded into one (no crack), near copies are refused, curves
// that merely join the same corners are left alone.
#include <gtest/gtest.h>

#include "geometry/abm_patch/abm_patch_test_support.h"
#include "geometry/abm_patch/curve_sharing.h"
#include "geometry/abm_patch/patch_tessellation.h"

namespace isotrace {
namespace {

using abm_test::curved_tetrahedron;
using abm_test::open_edges;

TEST(CurveSharing, CopiesOfACurveAreWeldedIntoOne) {
    const std::vector<AbmPatch> copies = curved_tetrahedron(false, 1, true);
    TriangleMeshData cracked = tessellate_patches(copies, {.tolerance = 2e-3});
    cracked.remove_degenerate_triangles();
    EXPECT_GT(open_edges(cracked), 0);  // each copy is sampled on its own: T-junctions

    const std::vector<AbmPatch> shared = share_coincident_curves(copies, 1e-6);
    std::set<const SpaceCurve*> curves;
    for (const AbmPatch& patch : shared)
        for (const PatchSide& side : patch.sides()) curves.insert(side.curve.get());
    EXPECT_EQ(curves.size(), 6u);
    TriangleMeshData welded = tessellate_patches(shared, {.tolerance = 2e-3});
    welded.remove_degenerate_triangles();
    EXPECT_EQ(open_edges(welded), 0);
    // A copy within the tolerance is the same curve.
    EXPECT_NO_THROW(share_coincident_curves(curved_tetrahedron(false, 1, true, 1e-7), 1e-6));
}

TEST(CurveSharing, NearCopiesAreRefusedWithTheirPlace) {
    try {
        share_coincident_curves(curved_tetrahedron(false, 1, true, 1e-4), 1e-6);
        FAIL() << "a near copy was accepted";
    } catch (const NearlySharedCurve& error) {
        EXPECT_EQ(error.patch, 1u);  // patch 1's first side runs along patch 0's first curve
        EXPECT_EQ(error.side, 2u);
        EXPECT_NE(std::string(error.what()).find("nearly coincides with edge of patch 0: they differ by up to"),
                  std::string::npos)
            << error.what();
    }
}

TEST(CurveSharing, CurvesThatOnlyJoinTheSameCornersStayApart) {
    // A bulge of 0.05 on an edge of length 2.8 is more than kNearlySharedFraction of it: a different curve.
    const std::vector<AbmPatch> copies = curved_tetrahedron(false, 1, true, 0.05);
    const std::vector<AbmPatch> shared = share_coincident_curves(copies, 1e-6);
    for (std::size_t p = 0; p < copies.size(); ++p)
        for (std::size_t i = 0; i < 3; ++i) EXPECT_EQ(shared[p].sides()[i].curve, copies[p].sides()[i].curve);
}

}  // namespace
}  // namespace isotrace
