#pragma once
// The lattice a polygoniser works on: cells of one size at depth L (2^L along each of three index axes), with
// the conventions of cube_cycles.h for their corners and edges. A Cartesian lattice is a cube of space; a
// spherical lattice indexes (r, θ, φ) about an origin, where the φ axis wraps and the θ = 0, π planes collapse
// onto the polar axis. Everything else (sampling, marching cubes, dual contouring) works on indices only and
// asks the lattice where they are.
#include <array>
#include <cstdint>
#include <vector>

#include "renderer/plugin/implicit_field.h"

namespace isotrace {

using LatticeIndex = std::array<int, 3>;
using LatticeKey = std::uint64_t;

constexpr int kMaxLatticeDepth = 16;  // indices up to 2^16 fit the 20 bits a key gives each axis

inline LatticeKey lattice_key(const LatticeIndex& v) {
    return std::uint64_t(v[0]) | std::uint64_t(v[1]) << 20 | std::uint64_t(v[2]) << 40;
}
inline LatticeIndex lattice_index(LatticeKey key) {
    return {int(key & 0xFFFFF), int((key >> 20) & 0xFFFFF), int((key >> 40) & 0xFFFFF)};
}
// An edge: its canonical lower corner and its axis.
inline LatticeKey edge_key(const LatticeIndex& corner, int axis) { return lattice_key(corner) << 2 | LatticeKey(axis); }

// A cell around a lattice edge, and which of its cube edges the lattice edge is.
struct EdgeNeighbour {
    LatticeIndex cell;
    int cube_edge = 0;
};

class Lattice {
public:
    explicit Lattice(int depth) : depth_(depth), cells_(1 << depth) {}
    virtual ~Lattice() = default;

    int depth() const { return depth_; }
    int cells_per_axis() const { return cells_; }

    // The point at fractional lattice coordinates (corner i of a cell is at the cell's index + offset).
    virtual Vec3d position(const Vec3d& coordinates) const = 0;
    // The one name of a corner that several index triples denote (φ = 0 and 2π, all φ on the pole).
    virtual LatticeIndex canonical_corner(LatticeIndex corner) const { return corner; }
    // The canonical lower corner of the edge from `corner` along `axis`, or false for an edge of zero length.
    virtual bool canonical_edge(LatticeIndex& corner, int axis) const {
        (void)corner;
        (void)axis;
        return true;
    }
    // The cells sharing the edge, counter-clockwise about its axis' positive direction (four, or a ring around the
    // polar axis); empty when the edge lies on the lattice's outer boundary.
    virtual void cells_around_edge(const LatticeIndex& corner, int axis, std::vector<EdgeNeighbour>& out) const;
    // Conservative: false only when the cell of `level` (2^(L − level) finest cells wide) holds no surface.
    virtual bool may_hold_surface(const ImplicitField& field, int level, const LatticeIndex& cell) const = 0;
    // The point of the finest cell nearest to p in the lattice's own coordinates (a dual vertex stays in its cell).
    virtual Vec3d clamp_to_cell(const Vec3d& p, const LatticeIndex& cell) const = 0;
    // True when an edge along `axis` from a corner of this θ index lies on the polar axis (spherical only).
    virtual bool is_polar_edge(const LatticeIndex& corner, int axis) const {
        (void)corner;
        (void)axis;
        return false;
    }

protected:
    // Wraps index `value` of `axis` into range, or returns false when it is outside a non-periodic axis.
    virtual bool wrap_cell(int axis, int& value) const {
        (void)axis;
        return value >= 0 && value < cells_;
    }

private:
    int depth_;
    int cells_;
};

}  // namespace isotrace
