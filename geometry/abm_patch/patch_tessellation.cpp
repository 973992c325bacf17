#include "geometry/abm_patch/patch_tessellation.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <map>
#include <set>
#include <stdexcept>
#include <string>

namespace isotrace {
namespace {

constexpr int kMaxRounds = 16;  // each round at most halves every segment: 2^16 ≫ the 4096 cap

// Curve parameters ordered by first use, and the welded end points.
struct SharedCurves {
    std::map<const SpaceCurve*, std::vector<double>> parameters;
    std::map<std::pair<const SpaceCurve*, int>, Vec3d> welded_end;  // (curve, 0 = start / 1 = end)
};

std::pair<const SpaceCurve*, int> start_key(const PatchSide& side) { return {side.curve.get(), side.reversed ? 1 : 0}; }
std::pair<const SpaceCurve*, int> end_key(const PatchSide& side) { return {side.curve.get(), side.reversed ? 0 : 1}; }

// Every end point takes the position of the first end point (in patch and side order) of its loop-joined group.
void weld_ends(const std::vector<AbmPatch>& patches, SharedCurves& shared) {
    std::vector<std::pair<const SpaceCurve*, int>> keys;
    std::map<std::pair<const SpaceCurve*, int>, std::size_t> id;
    auto id_of = [&](std::pair<const SpaceCurve*, int> key) {
        const auto [it, added] = id.emplace(key, keys.size());
        if (added) keys.push_back(key);
        return it->second;
    };
    std::vector<std::size_t> parent;
    auto root = [&](std::size_t a) {
        while (parent[a] != a) a = parent[a] = parent[parent[a]];
        return a;
    };
    for (const AbmPatch& patch : patches) {
        const std::vector<PatchSide>& sides = patch.sides();
        for (std::size_t k = 0; k < sides.size(); ++k) {
            const std::size_t a = id_of(end_key(sides[(k + sides.size() - 1) % sides.size()]));
            const std::size_t b = id_of(start_key(sides[k]));
            while (parent.size() < keys.size()) parent.push_back(parent.size());
            const std::size_t ra = root(a), rb = root(b);
            parent[std::max(ra, rb)] = std::min(ra, rb);
        }
    }
    for (std::size_t i = 0; i < keys.size(); ++i) {
        const auto [curve, end] = keys[root(i)];
        shared.welded_end[keys[i]] = (*curve)(end);
    }
}

std::vector<double> uniform_parameters(int segments) {
    std::vector<double> t;
    for (int k = 0; k <= segments; ++k) t.push_back(double(k) / segments);
    return t;
}

// Halves the marked intervals of `values` while the count stays within `cap`; false when none was halved.
bool halve(std::vector<double>& values, const std::set<int>& marked, int cap) {
    std::vector<double> result{values.front()};
    int count = int(values.size()) - 1;
    bool changed = false;
    for (std::size_t k = 0; k + 1 < values.size(); ++k) {
        if (marked.count(int(k)) && count < cap) {
            result.push_back(0.5 * (values[k] + values[k + 1]));
            ++count;
            changed = true;
        }
        result.push_back(values[k + 1]);
    }
    values = std::move(result);
    return changed;
}

enum class VertexKind { Centre, Interior, Boundary, Corner };

struct GridVertex {
    DomainPoint domain;
    Vec3d position;
    VertexKind kind;
    int side = 0;       // Boundary: the side; Corner: the corner
    double along = 0;   // Boundary: λ on the side
};

enum class TriangleKind { Fan, Outer, Inner };  // Fan: (centre, b_k, b_k+1); Outer: (a_k, b_k, b_k+1); Inner: (a_k, b_k+1, a_k+1)

struct GridTriangle {
    std::array<std::uint32_t, 3> v;
    TriangleKind kind;
    int side, column, band;
};

struct PatchGrid {
    std::vector<GridVertex> vertices;
    std::vector<GridTriangle> triangles;
};

// The side's λ values and the curve parameters they come from, in the side's direction.
std::vector<double> side_parameters(const PatchSide& side, const SharedCurves& shared, std::vector<double>* curve_t) {
    const std::vector<double>& t = shared.parameters.at(side.curve.get());
    std::vector<double> along;
    curve_t->clear();
    for (std::size_t k = 0; k < t.size(); ++k) {
        const double value = side.reversed ? t[t.size() - 1 - k] : t[k];
        curve_t->push_back(value);
        along.push_back(side.reversed ? 1 - value : value);
    }
    return along;
}

PatchGrid build_grid(const AbmPatch& patch, const std::vector<double>& rings, const SharedCurves& shared) {
    const PatchDomain& domain = patch.domain();
    const int n = domain.sides();
    const int ring_count = int(rings.size()) - 1;  // rings[0] = 0 (the centre) … rings[ring_count] = 1
    const DomainPoint centre = domain.centre();
    PatchGrid grid;
    grid.vertices.push_back({centre, patch(centre), VertexKind::Centre});

    auto toward = [&](DomainPoint target, double rho) {
        return DomainPoint{centre.x + rho * (target.x - centre.x), centre.y + rho * (target.y - centre.y)};
    };
    // corner_vertex[j][k]: ring j ≥ 1, corner k.
    std::vector<std::vector<std::uint32_t>> corner_vertex(std::size_t(ring_count + 1), std::vector<std::uint32_t>(std::size_t(n)));
    for (int j = 1; j <= ring_count; ++j)
        for (int k = 0; k < n; ++k) {
            corner_vertex[std::size_t(j)][std::size_t(k)] = std::uint32_t(grid.vertices.size());
            const DomainPoint corner = domain.corners()[std::size_t(k)];
            if (j == ring_count)
                grid.vertices.push_back({corner, shared.welded_end.at(start_key(patch.sides()[std::size_t(k)])), VertexKind::Corner, k});
            else {
                const DomainPoint q = toward(corner, rings[std::size_t(j)]);
                grid.vertices.push_back({q, patch(q), VertexKind::Interior});
            }
        }

    std::vector<double> curve_t;
    for (int i = 0; i < n; ++i) {
        const PatchSide& side = patch.sides()[std::size_t(i)];
        const std::vector<double> along = side_parameters(side, shared, &curve_t);
        const int columns = int(along.size()) - 1;
        // row[j][k]: the vertex of ring j at λ_k.
        std::vector<std::vector<std::uint32_t>> row(std::size_t(ring_count + 1), std::vector<std::uint32_t>(along.size()));
        for (int j = 1; j <= ring_count; ++j) {
            row[std::size_t(j)].front() = corner_vertex[std::size_t(j)][std::size_t(i)];
            row[std::size_t(j)].back() = corner_vertex[std::size_t(j)][std::size_t((i + 1) % n)];
            for (int k = 1; k < columns; ++k) {
                row[std::size_t(j)][std::size_t(k)] = std::uint32_t(grid.vertices.size());
                const DomainPoint on_side = domain.on_side(i, along[std::size_t(k)]);
                if (j == ring_count)
                    grid.vertices.push_back({on_side, (*side.curve)(curve_t[std::size_t(k)]), VertexKind::Boundary, i,
                                             along[std::size_t(k)]});
                else {
                    const DomainPoint q = toward(on_side, rings[std::size_t(j)]);
                    grid.vertices.push_back({q, patch(q), VertexKind::Interior});
                }
            }
        }
        auto add = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c, TriangleKind kind, int k, int band) {
            // The pattern turns the way the loop turns in the domain (the inner row lies on the interior side
            // of the direction of increasing λ), so it is counter-clockwise seen from the front.
            grid.triangles.push_back({{a, b, c}, kind, i, k, band});
        };
        for (int k = 0; k < columns; ++k) {
            add(0, row[1][std::size_t(k)], row[1][std::size_t(k + 1)], TriangleKind::Fan, k, 0);
            for (int j = 1; j < ring_count; ++j) {
                const auto& a = row[std::size_t(j)];
                const auto& b = row[std::size_t(j + 1)];
                add(a[std::size_t(k)], b[std::size_t(k)], b[std::size_t(k + 1)], TriangleKind::Outer, k, j);
                add(a[std::size_t(k)], b[std::size_t(k + 1)], a[std::size_t(k + 1)], TriangleKind::Inner, k, j);
            }
        }
    }
    return grid;
}

double deviation(const AbmPatch& patch, const GridVertex& a, const GridVertex& b) {
    const DomainPoint middle{0.5 * (a.domain.x + b.domain.x), 0.5 * (a.domain.y + b.domain.y)};
    return length(patch(middle) - 0.5 * (a.position + b.position));
}

double centroid_deviation(const AbmPatch& patch, const GridVertex& a, const GridVertex& b, const GridVertex& c) {
    const DomainPoint centroid{(a.domain.x + b.domain.x + c.domain.x) / 3, (a.domain.y + b.domain.y + c.domain.y) / 3};
    return length(patch(centroid) - (1.0 / 3) * (a.position + b.position + c.position));
}

// Which refinements each triangle's failing test points ask for. Returns the largest deviation.
struct Marks {
    std::map<const SpaceCurve*, std::set<int>> curve_segments;
    std::set<int> bands;
};

double mark_failures(const AbmPatch& patch, const PatchGrid& grid, const SharedCurves& shared, double tolerance,
                     Marks& marks) {
    double largest = 0;
    for (const GridTriangle& t : grid.triangles) {
        const GridVertex& a = grid.vertices[t.v[0]];  // the inner vertex a_k, or the centre
        const GridVertex& b = grid.vertices[t.v[1]];
        const GridVertex& c = grid.vertices[t.v[2]];
        // Edges (a,b), (b,c), (c,a); which is along a ring (row) and which crosses rings (radial).
        const double e[3] = {deviation(patch, a, b), deviation(patch, b, c), deviation(patch, c, a)};
        const double middle = centroid_deviation(patch, a, b, c);
        largest = std::max({largest, e[0], e[1], e[2], middle});
        bool row = false, radial = false;
        switch (t.kind) {
            case TriangleKind::Fan: radial = e[0] > tolerance || e[2] > tolerance; row = e[1] > tolerance; break;
            case TriangleKind::Outer: radial = e[0] > tolerance; row = e[1] > tolerance; break;
            case TriangleKind::Inner: radial = e[1] > tolerance; row = e[2] > tolerance; break;
        }
        const bool diagonal = (t.kind == TriangleKind::Outer && e[2] > tolerance) ||
                              (t.kind == TriangleKind::Inner && e[0] > tolerance) || middle > tolerance;
        if (row || diagonal) {
            const PatchSide& side = patch.sides()[std::size_t(t.side)];
            const int segments = int(shared.parameters.at(side.curve.get()).size()) - 1;
            marks.curve_segments[side.curve.get()].insert(side.reversed ? segments - 1 - t.column : t.column);
        }
        if (radial || diagonal) marks.bands.insert(t.band);
    }
    return largest;
}

Vec3d vertex_normal(const AbmPatch& patch, const GridVertex& v) {
    switch (v.kind) {
        case VertexKind::Boundary: return patch.side_normal(v.side, v.along);
        case VertexKind::Corner: return patch.corner_normal(v.side);
        default: return patch.normal(v.domain);
    }
}

void append(const AbmPatch& patch, const PatchGrid& grid, TriangleMeshData& mesh) {
    const auto base = std::uint32_t(mesh.positions.size());
    std::vector<bool> without_normal(grid.vertices.size());
    for (std::size_t i = 0; i < grid.vertices.size(); ++i) {
        const GridVertex& v = grid.vertices[i];
        const Vec3d n = vertex_normal(patch, v);
        without_normal[i] = !(length(n) > 0);
        mesh.positions.push_back(Vec3f(v.position));
        mesh.normals.push_back(Vec3f(n));
        mesh.uvs.push_back({float(v.domain.x), float(v.domain.y)});
    }
    for (const GridTriangle& t : grid.triangles) mesh.triangles.push_back({t.v[0] + base, t.v[1] + base, t.v[2] + base});
    // Where the patch folds (no tangent plane), the area-weighted normal of the triangles around the vertex,
    // summed in one pass over the triangles (a patch can fold at every vertex).
    std::vector<Vec3f> sums(grid.vertices.size());
    for (const GridTriangle& t : grid.triangles) {
        if (!without_normal[t.v[0]] && !without_normal[t.v[1]] && !without_normal[t.v[2]]) continue;
        const Vec3f& a = mesh.positions[t.v[0] + base];
        const Vec3f area_normal = cross(mesh.positions[t.v[1] + base] - a, mesh.positions[t.v[2] + base] - a);
        for (const std::uint32_t corner : t.v) sums[corner] += area_normal;
    }
    for (std::size_t i = 0; i < grid.vertices.size(); ++i)
        if (without_normal[i]) mesh.normals[base + i] = length(sums[i]) > 0 ? normalize(sums[i]) : Vec3f{0, 0, 1};
}

// Per sector: a fan and two triangles per column in every band but the first.
std::uint64_t triangle_count(const std::vector<AbmPatch>& patches, const std::vector<std::vector<double>>& rings,
                             const SharedCurves& shared) {
    std::uint64_t total = 0;
    for (std::size_t p = 0; p < patches.size(); ++p)
        for (const PatchSide& side : patches[p].sides())
            total += (shared.parameters.at(side.curve.get()).size() - 1) * (2 * (rings[p].size() - 1) - 1);
    return total;
}

}  // namespace

TriangleMeshData tessellate_patches(const std::vector<AbmPatch>& patches, const PatchTessellationOptions& options,
                                    PatchTessellationReport* report) {
    if (!(options.tolerance > 0)) throw std::invalid_argument("tolerance: must be > 0");
    if (options.max_segments < 1 || options.max_segments > 4096)
        throw std::invalid_argument("max_segments: must be in 1 … 4096");
    if (options.segments < 0 || options.segments > 4096) throw std::invalid_argument("segments: must be in 1 … 4096");

    const bool adaptive = options.segments == 0;
    const int start = adaptive ? std::min(2, options.max_segments) : options.segments;
    SharedCurves shared;
    for (const AbmPatch& patch : patches)
        for (const PatchSide& side : patch.sides()) shared.parameters.emplace(side.curve.get(), uniform_parameters(start));
    weld_ends(patches, shared);
    std::vector<std::vector<double>> rings(patches.size(), uniform_parameters(start));

    PatchTessellationReport summary;
    std::vector<PatchGrid> grids(patches.size());
    for (summary.rounds = 1;; ++summary.rounds) {
        Marks marks;
        std::vector<std::set<int>> bands(patches.size());
        summary.largest_deviation = 0;
        if (options.before_building) options.before_building(triangle_count(patches, rings, shared));
        for (std::size_t p = 0; p < patches.size(); ++p) {
            grids[p] = build_grid(patches[p], rings[p], shared);
            summary.largest_deviation = std::max(summary.largest_deviation,
                                                 mark_failures(patches[p], grids[p], shared, options.tolerance, marks));
            bands[p] = std::move(marks.bands);
            marks.bands.clear();
        }
        if (!adaptive || summary.largest_deviation <= options.tolerance) break;
        bool changed = false;
        for (auto& [curve, segments] : marks.curve_segments)
            changed |= halve(shared.parameters.at(curve), segments, options.max_segments);
        for (std::size_t p = 0; p < patches.size(); ++p) changed |= halve(rings[p], bands[p], options.max_segments);
        if (!changed || summary.rounds == kMaxRounds) {
            summary.capped = true;
            break;
        }
    }

    TriangleMeshData mesh;  // from the grids last checked
    for (std::size_t p = 0; p < patches.size(); ++p) append(patches[p], grids[p], mesh);
    if (report) *report = summary;
    return mesh;
}

}  // namespace isotrace
