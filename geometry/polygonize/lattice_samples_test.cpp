// The lattice samples against brute force over the whole lattice: the surface cells are exactly the cells whose
// corners differ in sign, only their corners are kept, and each crossing is edge_crossing's for that edge — on a
// Cartesian and a spherical lattice, for a blob field (sampled in batches of its own) and for a field that samples
// one point at a time; and the samples are the same for any thread count.
#include "geometry/polygonize/lattice_samples.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cstring>
#include <set>

#include "geometry/field/surface_bounds.h"
#include "geometry/implicit/blob_group_shape.h"
#include "geometry/implicit/implicit_test_support.h"
#include "geometry/polygonize/cartesian_lattice.h"
#include "geometry/polygonize/polygonize_test_support.h"
#include "geometry/polygonize/spherical_lattice.h"

namespace isotrace {
namespace {

// Twenty elements, a fifth of them carving, about the origin (which lies outside the surface's pieces).
BlobGroupShape blob_cloud() { return BlobGroupShape(random_blob_group(20, 3, "kim", 5)); }

double value_at(const ImplicitField& field, const Lattice& lattice, const LatticeIndex& corner) {
    const LatticeIndex c = lattice.canonical_corner(corner);
    return field.value(lattice.position(Vec3d(c[0], c[1], c[2])));
}

void expect_brute_force(const ImplicitField& field, const Lattice& lattice, const std::string& what) {
    const LatticeSamples samples = sample_lattice(field, lattice);
    const int n = lattice.cells_per_axis();
    std::vector<LatticeKey> cells;
    std::set<LatticeKey> corners;
    for (int z = 0; z < n; ++z)
        for (int y = 0; y < n; ++y)
            for (int x = 0; x < n; ++x) {
                int inside = 0;
                for (int c = 0; c < 8; ++c)
                    inside += value_at(field, lattice, {x + (c & 1), y + ((c >> 1) & 1), z + ((c >> 2) & 1)}) < 0;
                if (inside == 0 || inside == 8) continue;
                cells.push_back(lattice_key({x, y, z}));
                for (int c = 0; c < 8; ++c)
                    corners.insert(lattice_key(lattice.canonical_corner({x + (c & 1), y + ((c >> 1) & 1), z + ((c >> 2) & 1)})));
            }
    std::sort(cells.begin(), cells.end());
    ASSERT_FALSE(cells.empty()) << what;
    EXPECT_EQ(samples.cells, cells) << what;
    EXPECT_EQ(samples.corners, std::vector<LatticeKey>(corners.begin(), corners.end())) << what;
    EXPECT_GE(samples.candidate_cells, samples.cells.size()) << what;
    ASSERT_EQ(samples.crossings.size(), samples.edges.size()) << what;
    for (std::size_t e = 0; e < samples.edges.size(); ++e) {
        const int axis = int(samples.edges[e] & 3);
        const LatticeIndex corner = lattice_index(samples.edges[e] >> 2);
        LatticeIndex upper = corner;
        ++upper[axis];
        const double lower_value = value_at(field, lattice, corner);
        const Vec3d expected = edge_crossing(field, lattice, corner, axis, lower_value, value_at(field, lattice, upper));
        ASSERT_EQ(std::memcmp(&samples.crossings[e], &expected, sizeof(Vec3d)), 0) << what << " edge " << e;
        const Vec3d gradient = field.gradient(expected);
        ASSERT_EQ(std::memcmp(&samples.gradients[e], &gradient, sizeof(Vec3d)), 0) << what << " edge " << e;
        EXPECT_EQ(samples.lower_inside[e] != 0, lower_value < 0) << what << " edge " << e;
    }
}

TEST(LatticeSamples, AreTheLatticeCellsWithBothSignsAndTheirCrossings) {
    const BlobGroupShape cloud = blob_cloud();
    const std::unique_ptr<ImplicitField> field = cloud.implicit_field();
    const SurfaceBoundedField blobs(*field);
    const TorusField torus({0.05, 0.1, -0.1}, 1.0, 0.35);
    const SurfaceBoundedField ring(torus);
    for (const ImplicitField* sampled : {static_cast<const ImplicitField*>(&blobs), static_cast<const ImplicitField*>(&ring)}) {
        const std::string what = sampled == &blobs ? "blobs" : "torus";
        for (int depth : {2, 5}) expect_brute_force(*sampled, CartesianLattice::around(sampled->bounds(), depth), what);
        const FieldBox box = sampled->bounds();
        const SphericalRange range{box.centre() + Vec3d{0.01, 0.02, 0.03}, 0.05, length(box.extent())};
        expect_brute_force(*sampled, SphericalLattice(range, 5), what + " spherical");
    }
}

// The samples of a blob field, on one thread and on several: the same, bit for bit.
TEST(LatticeSamples, AreTheSameForAnyThreadCount) {
    const BlobGroupShape cloud = blob_cloud();
    const std::unique_ptr<ImplicitField> field = cloud.implicit_field();
    const SurfaceBoundedField blobs(*field);
    const CartesianLattice lattice = CartesianLattice::around(blobs.bounds(), 6);
    LatticeSamples one, many;
    {
        tbb::global_control single(tbb::global_control::max_allowed_parallelism, 1);
        one = sample_lattice(blobs, lattice);
    }
    {
        tbb::global_control several(tbb::global_control::max_allowed_parallelism, 4);
        many = sample_lattice(blobs, lattice);
    }
    EXPECT_EQ(one.cells, many.cells);
    EXPECT_EQ(one.inside, many.inside);
    EXPECT_EQ(one.edges, many.edges);
    ASSERT_EQ(one.crossings.size(), many.crossings.size());
    EXPECT_EQ(0, std::memcmp(one.crossings.data(), many.crossings.data(), one.crossings.size() * sizeof(Vec3d)));
    EXPECT_EQ(0, std::memcmp(one.gradients.data(), many.gradients.data(), one.gradients.size() * sizeof(Vec3d)));
    EXPECT_EQ(one.corners, many.corners);
}

}  // namespace
}  // namespace isotrace
