#pragma once
// The work of a blob group's ray queries, for the statistics (`render --stats full`): each field a named counter,
// per group ("blobs[name].pieces") and for all groups ("blobs.pieces").
#include <array>
#include <cstdint>
#include <string>

#include "renderer/core/render_counters.h"

namespace isotrace {

struct BlobQueryWork {
    std::uint64_t queries = 0;            // cells marched
    std::uint64_t queries_bounded = 0;    // of which the candidates' bound proved free of crossings at once
    std::uint64_t candidates = 0;         // listed elements whose bounding sphere the marched stretch meets
    std::uint64_t joined = 0;             // of which the march reached (sliced and summed)
    std::uint64_t pieces = 0;             // ray pieces examined
    std::uint64_t skipped_pieces = 0;     // of which the Bernstein or interval bound proved free of crossings
    std::uint64_t polynomial_solves = 0;
    std::uint64_t lipschitz_searches = 0;
    std::uint64_t root_iterations = 0;  // Newton/bisection steps of the polynomial solves and Lipschitz searches
    std::uint64_t roots = 0;            // crossings reported (for occlusion, also those proven before a stretch)

    static constexpr std::size_t kFields = 10;
    std::array<std::uint64_t, kFields> amounts() const {
        return {queries,        queries_bounded,   candidates,         joined,          pieces,
                skipped_pieces, polynomial_solves, lipschitz_searches, root_iterations, roots};
    }
};

// The counter slots of a group's BlobQueryWork, in the order of BlobQueryWork::amounts.
using BlobWorkSlots = std::array<int, BlobQueryWork::kFields>;

// Registers the counters of the group called `group` ("blobs[name]") of shape type `type` ("blobs").
inline BlobWorkSlots register_blob_work(const std::string& type, const std::string& group) {
    static constexpr const char* kNames[BlobQueryWork::kFields] = {
        ".cell_queries",      ".cell_queries_bounded", ".candidates",      ".elements_joined", ".pieces",
        ".pieces_skipped_by_bounds", ".polynomial_solves", ".lipschitz_searches", ".root_iterations", ".roots"};
    BlobWorkSlots slots{};
    for (std::size_t k = 0; k < slots.size(); ++k)
        slots[k] = counters::named_counter_slot(group + kNames[k], counters::named_counter_slot(type + kNames[k]));
    return slots;
}

// Adds a query's work to its group's counters (nothing for a query that marched no cell).
inline void count_blob_work(const BlobWorkSlots& slots, const BlobQueryWork& work) {
    if (work.queries != 0) counters::add_to_named(slots, work.amounts());
}

}  // namespace isotrace
