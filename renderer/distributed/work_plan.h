#pragma once
// How a distributed render divides an image into work items (docs/distributed.md). Pure planning, no MPI: rank 0
// hands the items out one at a time, to whichever rank asks first.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "renderer/film/film.h"

namespace isotrace {

enum class WorkSplit {
    Samples,  // every rank renders blocks of sample indices of every pixel (long renders of one frame)
    Tiles,    // every rank renders whole regions of the image (huge resolutions)
};

struct WorkItem {
    PixelBounds region;
    std::uint32_t first_sample = 0;  // Samples: the start of a block (the region's film starts there); Tiles: 0
    std::uint32_t last_sample = 0;   // every pixel of the region is brought up to this many samples
    // Samples: the item with the block before this one for the same pixels; it must be merged first.
    std::optional<std::size_t> previous;
};

// Tiles: the film's crop in square regions, each rendered from its pixels' sample counts up to spp; regions that
// already have spp are left out (a resumed render). The region edge is the largest multiple of tile_edge that
// still gives at least min_items regions, so that every rank gets several and early finishers can take more.
std::vector<WorkItem> plan_tiles(const Film& film, int tile_edge, std::uint32_t spp, std::size_t min_items);

// Samples: bands of whole rows of at most kBandPixels pixels (bounding the size of a message and of the results
// waiting to be merged), each cut into the blocks of Film::kSampleBlock indices from first_sample to spp, band by
// band, blocks in order. first_sample must start a block.
inline constexpr std::int64_t kBandPixels = 1 << 16;
std::vector<WorkItem> plan_sample_blocks(const PixelBounds& crop, std::uint32_t first_sample, std::uint32_t spp);

}  // namespace isotrace
