#pragma once
// The polygoniser's resolution as the commands that tessellate blob groups (bench, polygonize) take it.
#include <CLI/CLI.hpp>

#include <optional>
#include <string>

#include "geometry/implicit/blob_group.h"
#include "geometry/mesh/triangle_mesh_data.h"

namespace isotrace::cli {

struct TessellationOptions {
    std::optional<double> cell_size;  // lattice spacing in each shape's own units; default from cells_per_radius
    double cells_per_radius = 4;      // lattice cells across the smallest element's field radius

    // Adds --cell-size and --cells-per-radius to a command.
    void add_to(CLI::App& command);
    double cell_size_for(const BlobGroup& group) const;
};

// polygonize() at `cell`; a cell size the lattice cannot take becomes an InputError naming --cell-size and `what`.
TriangleMeshData tessellate(const BlobGroup& group, double cell, const std::string& what);

}  // namespace isotrace::cli
