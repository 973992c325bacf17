#include "renderer/plugin/placement_record.h"

#include <stdexcept>

namespace isotrace {
namespace {

Transform::Matrix promoted(const std::array<float, 12>& rows) {
    Transform::Matrix m{};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 4; ++j) m[i][j] = double(rows[std::size_t(i * 4 + j)]);
    m[3] = {0, 0, 0, 1};
    return m;
}

}  // namespace

std::optional<PlacementRecord> placement_record(const Transform& to_world, std::uint32_t variant) {
    PlacementRecord record;
    // Held by value: a reference to the matrix of the temporary inverse() returns dangles once the statement ends.
    const Transform from_world = to_world.inverse();
    const Transform::Matrix& inverse = from_world.matrix();
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 4; ++j) record.from_world[std::size_t(i * 4 + j)] = float(inverse[i][j]);
    record.variant = variant;
    try {
        Transform::from_matrix(promoted(record.from_world));
    } catch (const std::invalid_argument&) {
        return std::nullopt;
    }
    return record;
}

Transform to_world_of_record(const PlacementRecord& record) {
    // placement_record checked that this succeeds, and the same bits give the same answer.
    return Transform::inverse_of_accepted(promoted(record.from_world));
}

}  // namespace isotrace
