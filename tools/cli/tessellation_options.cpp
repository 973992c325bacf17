#include "tools/cli/tessellation_options.h"

#include <stdexcept>

#include "geometry/polygonize/blob_polygonizer.h"
#include "renderer/core/input_error.h"

namespace isotrace::cli {

void TessellationOptions::add_to(CLI::App& command) {
    command.add_option("--cell-size", cell_size,
                       "Tessellation cell size in each shape's own units (an object's transform scales its cells)")->check(CLI::PositiveNumber);
    command
        .add_option("--cells-per-radius", cells_per_radius,
                    "Tessellation cells across the smallest element's radius (when --cell-size is not given)")
        ->capture_default_str()
        ->check(CLI::PositiveNumber);
}

double TessellationOptions::cell_size_for(const BlobGroup& group) const {
    return cell_size.value_or(cell_size_for_smallest_element(group, cells_per_radius));
}

TriangleMeshData tessellate(const BlobGroup& group, double cell, const std::string& what) {
    try {
        return polygonize(group, {cell});
    } catch (const std::invalid_argument& error) {
        throw InputError({}, "--cell-size", what + ": " + error.what());
    }
}

}  // namespace isotrace::cli
