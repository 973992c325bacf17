// The two builds of the blob cell queries (blob_cell_queries.h): the AVX2 module is the one used where the CPU has
// AVX2, and it gives the baseline build's bits — crossings, normals, occlusion answers and crossing lists — on
// random rays through random groups of every kernel, of metaballs alone (the metaball march) and with metacubes
// (the general march).
#include "geometry/implicit/blob_cell_queries.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "geometry/implicit/implicit_test_support.h"

namespace isotrace {
namespace {

bool avx2_in_use() { return std::string(blob_cell_queries().isa) == "avx2"; }

TEST(BlobCellQueries, TheAvx2BuildIsUsedWhereTheCpuHasAvx2) {
    EXPECT_EQ(std::string(blob_cell_queries().isa), __builtin_cpu_supports("avx2") ? "avx2" : "baseline x86-64");
    EXPECT_EQ(std::string(baseline_blob_cell_queries().isa), "baseline x86-64");
}

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }
bool same_bits(const Vec3d& a, const Vec3d& b) {
    return same_bits(a.x, b.x) && same_bits(a.y, b.y) && same_bits(a.z, b.z);
}

BlobGroup random_metaball_group(std::uint32_t seed, const std::string& kernel) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(0, 1);
    std::vector<Metacube> elements;
    for (int i = 0; i < 200; ++i)
        elements.push_back(Metacube::metaball(random_vector(rng, -1.5, 1.5), 0.3 + 0.4 * u(rng),
                                              u(rng) < 0.15 ? -0.6 : 0.7 + 0.6 * u(rng)));
    return BlobGroup(std::move(elements), make_field_function(kernel, 4.0), 0.5);
}

// Every query of both builds on every surface cell for 150 random rays (some of them starting inside, as shadow
// and bounce rays do); returns the number of crossings compared.
int expect_same_bits(const BlobGroup& group, std::uint64_t seed) {
    const BlobCellQueries& baseline = baseline_blob_cell_queries();
    const BlobCellQueries& chosen = blob_cell_queries();
    std::mt19937_64 rng(seed);
    int crossings = 0;
    for (int ray = 0; ray < 150; ++ray) {
        const Vec3d origin = ray % 3 == 0 ? random_vector(rng, -1, 1) : normalize(random_vector(rng, -1, 1)) * 4.0;
        const Vec3d direction = normalize(random_vector(rng, -1.5, 1.5) - origin);
        for (std::uint32_t cell = 0; cell < group.cells().surface_cell_count(); ++cell) {
            BlobQueryWork work_a, work_b;
            const auto a = baseline.first_hit_in_cell(group, cell, origin, direction, 0, 10, work_a);
            const auto b = chosen.first_hit_in_cell(group, cell, origin, direction, 0, 10, work_b);
            EXPECT_EQ(a.has_value(), b.has_value()) << "ray " << ray << " cell " << cell;
            if (a && b) {
                EXPECT_TRUE(same_bits(a->crossing.t, b->crossing.t)) << a->crossing.t << " " << b->crossing.t;
                EXPECT_EQ(a->crossing.entering, b->crossing.entering);
                EXPECT_EQ(a->crossing.element, b->crossing.element);
                EXPECT_EQ(a->normal.has_value(), b->normal.has_value());
                if (a->normal && b->normal) { EXPECT_TRUE(same_bits(*a->normal, *b->normal)); }
            }
            EXPECT_EQ(baseline.occluded_in_cell(group, cell, origin, direction, 0, 10, work_a),
                      chosen.occluded_in_cell(group, cell, origin, direction, 0, 10, work_b));
            std::vector<FieldCrossing> all_a, all_b;
            baseline.crossings_in_cell(group, cell, origin, direction, 0, 10, all_a, 0, work_a);
            chosen.crossings_in_cell(group, cell, origin, direction, 0, 10, all_b, 0, work_b);
            EXPECT_EQ(all_a.size(), all_b.size());
            for (std::size_t i = 0; i < std::min(all_a.size(), all_b.size()); ++i) {
                EXPECT_TRUE(same_bits(all_a[i].t, all_b[i].t));
                EXPECT_EQ(all_a[i].entering, all_b[i].entering);
            }
            crossings += int(all_a.size());
        }
    }
    return crossings;
}

TEST(BlobCellQueries, BothBuildsGiveTheSameBits) {
    if (!avx2_in_use()) GTEST_SKIP() << "one build only: the CPU has no AVX2 (or the module did not load)";
    int kernel_seed = 0;
    for (const char* kernel : {"kim", "wyvill", "murakami", "nishimura", "blinn"}) {
        ++kernel_seed;
        SCOPED_TRACE(kernel);
        EXPECT_GT(expect_same_bits(random_metaball_group(std::uint32_t(kernel_seed), kernel), kernel_seed), 100);
        EXPECT_GT(expect_same_bits(random_blob_group(60, std::uint32_t(kernel_seed), kernel, 7), 100 + kernel_seed),
                  100);
    }
}

}  // namespace
}  // namespace isotrace
