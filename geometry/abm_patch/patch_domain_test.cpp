// Patch domains: distances vanish on their own side, parameters run 0 → 1 linearly along it, gradients match
// finite differences.
#include <gtest/gtest.h>

#include "geometry/abm_patch/patch_domain.h"

namespace isotrace {
namespace {

std::vector<std::unique_ptr<PatchDomain>> all_domains() {
    std::vector<std::unique_ptr<PatchDomain>> domains;
    domains.push_back(right_triangle_domain());
    domains.push_back(unit_square_domain());
    for (int n = 3; n <= 8; ++n) domains.push_back(regular_polygon_domain(n));
    return domains;
}

TEST(PatchDomain, EachSideIsItsOwnFootprint) {
    for (const auto& domain : all_domains()) {
        const int n = domain->sides();
        Footprint f[PatchDomain::kMaxSides];
        for (int i = 0; i < n; ++i)
            for (double t : {0.0, 0.1, 0.5, 0.77, 1.0}) {
                domain->footprints(domain->on_side(i, t), f);
                EXPECT_NEAR(f[i].distance, 0, 1e-15) << domain->name() << " " << n;
                if (0 < t && t < 1) {
                    EXPECT_NEAR(f[i].parameter, t, 1e-14) << domain->name() << " " << n << " side " << i;
                    for (int j = 0; j < n; ++j) {
                        if (j != i) {
                            EXPECT_GT(f[j].distance, 0);
                        }
                    }
                }
            }
    }
}

TEST(PatchDomain, GradientsMatchFiniteDifferences) {
    const double h = 1e-7;
    for (const auto& domain : all_domains()) {
        const int n = domain->sides();
        const DomainPoint c = domain->centre();
        for (int k = 0; k < n; ++k) {
            const DomainPoint corner = domain->corners()[std::size_t(k)];
            const DomainPoint x{c.x + 0.6 * (corner.x - c.x) + 0.01, c.y + 0.6 * (corner.y - c.y)};
            Footprint f[PatchDomain::kMaxSides], fx[PatchDomain::kMaxSides], fy[PatchDomain::kMaxSides];
            Footprint gx[PatchDomain::kMaxSides], gy[PatchDomain::kMaxSides];
            domain->footprints(x, f);
            domain->footprints({x.x + h, x.y}, fx);
            domain->footprints({x.x - h, x.y}, gx);
            domain->footprints({x.x, x.y + h}, fy);
            domain->footprints({x.x, x.y - h}, gy);
            for (int i = 0; i < n; ++i) {
                EXPECT_NEAR(f[i].distance_dx, (fx[i].distance - gx[i].distance) / (2 * h), 1e-7);
                EXPECT_NEAR(f[i].distance_dy, (fy[i].distance - gy[i].distance) / (2 * h), 1e-7);
                EXPECT_NEAR(f[i].parameter_dx, (fx[i].parameter - gx[i].parameter) / (2 * h), 1e-6);
                EXPECT_NEAR(f[i].parameter_dy, (fy[i].parameter - gy[i].parameter) / (2 * h), 1e-6);
                EXPECT_GE(f[i].parameter, 0);
                EXPECT_LE(f[i].parameter, 1);
            }
        }
    }
}

TEST(PatchDomain, PaperDomainsRunClockwiseAndPolygonsCounterClockwise) {
    EXPECT_EQ(right_triangle_domain()->orientation(), -1);
    EXPECT_EQ(unit_square_domain()->orientation(), -1);
    for (int n = 3; n <= 8; ++n) EXPECT_EQ(regular_polygon_domain(n)->orientation(), 1);
}

}  // namespace
}  // namespace isotrace
