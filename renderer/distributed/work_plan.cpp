#include "renderer/distributed/work_plan.h"

#include <algorithm>

namespace isotrace {
namespace {

std::int64_t regions_along(int length, int edge) { return (length + edge - 1) / edge; }

bool complete(const Film& film, const PixelBounds& region, std::uint32_t spp) {
    for (int y = region.y0; y < region.y1; ++y)
        for (int x = region.x0; x < region.x1; ++x)
            if (film.sample_count(x, y) < spp) return false;
    return true;
}

}  // namespace

std::vector<WorkItem> plan_tiles(const Film& film, int tile_edge, std::uint32_t spp, std::size_t min_items) {
    const PixelBounds& crop = film.bounds();
    int edge = std::max(1, tile_edge);
    for (int larger = edge + tile_edge; larger < std::max(crop.width(), crop.height()) + tile_edge; larger += tile_edge) {
        if (regions_along(crop.width(), larger) * regions_along(crop.height(), larger) < std::int64_t(min_items)) break;
        edge = larger;
    }
    std::vector<WorkItem> items;
    for (int y = crop.y0; y < crop.y1; y += edge) {
        for (int x = crop.x0; x < crop.x1; x += edge) {
            const PixelBounds region{x, y, std::min(x + edge, crop.x1), std::min(y + edge, crop.y1)};
            if (!complete(film, region, spp)) items.push_back({region, 0, spp, std::nullopt});
        }
    }
    return items;
}

std::vector<WorkItem> plan_sample_blocks(const PixelBounds& crop, std::uint32_t first_sample, std::uint32_t spp) {
    const int band_rows = int(std::clamp<std::int64_t>(kBandPixels / std::max(1, crop.width()), 1, crop.height()));
    std::vector<WorkItem> items;
    for (int y = crop.y0; y < crop.y1; y += band_rows) {
        const PixelBounds band{crop.x0, y, crop.x1, std::min(y + band_rows, crop.y1)};
        std::optional<std::size_t> previous;
        for (std::uint32_t first = first_sample; first < spp; first += Film::kSampleBlock) {
            items.push_back({band, first, std::min(spp, first + Film::kSampleBlock), previous});
            previous = items.size() - 1;
        }
    }
    return items;
}

}  // namespace isotrace
