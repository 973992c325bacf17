#include "geometry/mesh/bezier_patches.h"

#include <cmath>
#include <map>
#include <sstream>
#include <stdexcept>
#include <tuple>

#include "geometry/curves/bspline_curve.h"
#include "geometry/mesh/file_contents.h"
#include "geometry/mesh/vertex_normals.h"
#include "renderer/core/input_error.h"

namespace isotrace {

BezierPatch::Sample BezierPatch::evaluate(double u, double v) const {
    // The v-curves of every row at v (and their v-derivatives), then one u-curve through each set.
    std::vector<Vec3d> at_v, rate_v;
    for (int i = 0; i <= degree_u; ++i) {
        const auto begin = control_points.begin() + i * (degree_v + 1);
        const BSplineCurve<Vec3d> row = bezier_curve(std::vector<Vec3d>(begin, begin + degree_v + 1));
        at_v.push_back(row(v));
        rate_v.push_back(row.derivative()(v));
    }
    const BSplineCurve<Vec3d> across = bezier_curve(at_v);
    return {across(u), across.derivative()(u), bezier_curve(rate_v)(u)};
}

namespace {

class PatchReader {
public:
    explicit PatchReader(const std::string& path) : path_(path), in_(read_file_contents(path)) {}

    std::vector<double> numbers(std::size_t count) {
        std::string line;
        do {
            ++line_;
            if (!std::getline(in_, line)) fail("unexpected end of file");
        } while (line.find_first_not_of(" \t\r") == std::string::npos);
        std::istringstream fields(line);
        std::vector<double> values;
        std::string field;
        while (fields >> field) {
            std::size_t used = 0;
            double value = 0;
            try {
                value = std::stod(field, &used);
            } catch (const std::exception&) {
                used = 0;
            }
            if (used != field.size() || !std::isfinite(value)) fail("'" + field + "' is not a finite number");
            values.push_back(value);
        }
        if (values.size() != count)
            fail("expected " + std::to_string(count) + " number" + (count == 1 ? "" : "s") + ", found " +
                 std::to_string(values.size()));
        return values;
    }

    int integer(double value, int low, int high, const std::string& what) {
        if (value != std::floor(value) || value < low || value > high)
            fail(what + " must be an integer in [" + std::to_string(low) + ", " + std::to_string(high) + "]");
        return int(value);
    }

    [[noreturn]] void fail(const std::string& problem) const { throw InputError({path_, line_, 0}, "", problem); }

private:
    std::string path_;
    std::istringstream in_;
    int line_ = 0;
};

}  // namespace

std::vector<BezierPatch> load_bezier_patches(const std::string& path, MemoryBudget& memory) {
    PatchReader reader(path);
    const int count = reader.integer(reader.numbers(1)[0], 1, 100000, "the patch count");
    memory.charge(std::uint64_t(count) * sizeof(BezierPatch), std::to_string(count) + " Bézier patches", {path});
    std::vector<BezierPatch> patches(static_cast<std::size_t>(count));
    for (BezierPatch& patch : patches) {
        const std::vector<double> degrees = reader.numbers(2);
        patch.degree_u = reader.integer(degrees[0], 1, 16, "a patch degree");
        patch.degree_v = reader.integer(degrees[1], 1, 16, "a patch degree");
        const int points = (patch.degree_u + 1) * (patch.degree_v + 1);
        memory.charge(std::uint64_t(points) * sizeof(Vec3d), "the control points of Bézier patches", {path});
        for (int k = 0; k < points; ++k) {
            const std::vector<double> p = reader.numbers(3);
            patch.control_points.push_back({p[0], p[1], p[2]});
        }
    }
    return patches;
}

void charge_bezier_tessellation(std::size_t patch_count, int steps, const std::string& path, MemoryBudget& memory) {
    const std::uint64_t quads = saturating_product({patch_count, std::uint64_t(steps), std::uint64_t(steps)});
    memory.charge(saturating_product({quads, kBezierQuadPeakBytes}),
                  "a tessellation of " + std::to_string(patch_count) + " Bézier patches into " + std::to_string(2 * quads) +
                      " triangles",
                  {path});
}

TriangleMeshData tessellate_bezier_patches(const std::vector<BezierPatch>& patches, int steps) {
    if (steps < 1 || steps > 256) throw std::invalid_argument("steps: must be in [1, 256]");
    TriangleMeshData mesh;
    Vec3d low(INFINITY, INFINITY, INFINITY), high = -low;
    for (const BezierPatch& patch : patches)
        for (const Vec3d& p : patch.control_points) {
            low = min(low, p);
            high = max(high, p);
        }
    // Points closer than a millionth of the model merge (shared edges evaluate to the same point up to rounding).
    const double cell = 1e-6 * std::max(length(high - low), 1e-300);
    std::map<std::tuple<long long, long long, long long>, std::uint32_t> welded;
    auto vertex = [&](const Vec3d& p) {
        const auto key = std::make_tuple(std::llround(p.x / cell), std::llround(p.y / cell), std::llround(p.z / cell));
        const auto [at, inserted] = welded.emplace(key, std::uint32_t(mesh.positions.size()));
        if (inserted) mesh.positions.push_back(Vec3f(p));
        return at->second;
    };
    std::vector<std::uint32_t> grid(std::size_t(steps + 1) * std::size_t(steps + 1));
    for (const BezierPatch& patch : patches) {
        for (int i = 0; i <= steps; ++i)
            for (int j = 0; j <= steps; ++j)
                grid[std::size_t(i * (steps + 1) + j)] = vertex(patch.evaluate(double(i) / steps, double(j) / steps).position);
        for (int i = 0; i < steps; ++i)
            for (int j = 0; j < steps; ++j) {
                const std::uint32_t a = grid[std::size_t(i * (steps + 1) + j)], b = grid[std::size_t((i + 1) * (steps + 1) + j)];
                const std::uint32_t c = grid[std::size_t((i + 1) * (steps + 1) + j + 1)], d = grid[std::size_t(i * (steps + 1) + j + 1)];
                // Collapsed edges (poles) give triangles with a repeated corner: skip those.
                if (a != b && b != c && a != c) mesh.triangles.push_back({a, b, c});
                if (a != c && c != d && a != d) mesh.triangles.push_back({a, c, d});
            }
    }
    compute_vertex_normals(mesh);
    return mesh;
}

}  // namespace isotrace
