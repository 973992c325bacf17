#pragma once
// Film: per-pixel accumulation of weighted radiance samples (filter importance sampling: every sample belongs
// to exactly one pixel) plus the requested AOVs. A pixel's samples are added in sample-index order by one
// thread, so the result is independent of thread count and tile size. The sums are kept in blocks of
// kSampleBlock consecutive sample indices (each block summed from zero, the blocks' sums added in block order),
// so that a block rendered elsewhere (another MPI rank) can be added with the same roundings: the image is
// bit-identical however the sample indices were split between processes (docs/decisions.md).
#include <cmath>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "renderer/core/zeroed_pages.h"
#include "renderer/film/aov.h"
#include "renderer/image/image_buffer.h"
#include "renderer/math/rgb.h"
#include "renderer/plugin/camera.h"
#include "renderer/plugin/integrator.h"

namespace isotrace {

// Pixel rectangle [x0, x1) x [y0, y1) of the full raster.
struct PixelBounds {
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    int width() const { return x1 - x0; }
    int height() const { return y1 - y0; }
    std::int64_t area() const { return std::int64_t(width()) * height(); }
};

struct FilmSettings {
    RasterSize raster;
    PixelBounds crop;  // the part of the raster rendered and written
    std::vector<Aov> aovs;
    bool half_float = false;  // EXR pixel type
};

// Per-pixel sample counts over the film: a render stopped mid-pass leaves min < max.
struct SampleCountRange {
    std::uint32_t min = 0, max = 0;
    std::uint64_t total = 0;
};

// A pixel's estimate and its uncertainty, per radiance channel.
struct PixelStatistics {
    double mean[3] = {0, 0, 0};
    // Variance of the (weighted) mean: the per-sample variance over the effective sample count
    // (sum w)^2 / sum w^2, which is the sample count when every weight is 1. Infinite below two samples.
    double variance_of_mean[3] = {0, 0, 0};
    std::uint32_t samples = 0;
};

struct CameraSample {
    Rgb radiance;
    float filter_weight = 1;
    float offset_squared = 0;  // squared distance of the sample from the pixel centre (id AOVs keep the nearest)
    PrimaryHitRecord primary;
};

class Film {
public:
    // Sample indices per block of the sums.
    static constexpr std::uint32_t kSampleBlock = 32;

    explicit Film(FilmSettings settings);
    // A film for the samples [first_sample, ...) of each pixel, to be added with append_block() to the film that
    // holds [0, first_sample): its counts start at first_sample, a multiple of kSampleBlock, its sums at zero.
    Film(FilmSettings settings, std::uint32_t first_sample);

    // Bytes a film with these settings holds while rendering and writing: the accumulators, the resolved
    // image and, at most, one encoded copy of it (image writers encode in memory before writing).
    static std::uint64_t memory_bytes(const FilmSettings& settings);

    const FilmSettings& settings() const { return settings_; }
    const PixelBounds& bounds() const { return settings_.crop; }

    // The largest radiance a sample may carry: 32 of its squares, times a filter's weight, must stay finite in the open
    // block's single-precision sums. No scene's light comes near it; a path that does is as broken as a NaN.
    static constexpr float kLargestRadiance = 1e17f;
    // (The comparisons are false for NaN and infinities too.)
    static bool holds(const Rgb& radiance) {
        return std::abs(radiance.r) <= kLargestRadiance && std::abs(radiance.g) <= kLargestRadiance &&
               std::abs(radiance.b) <= kLargestRadiance;
    }

    // x, y in full-raster pixels inside bounds(), the radiance one the film holds(). Not thread-safe per pixel (one
    // thread owns a pixel).
    void add_sample(int x, int y, const CameraSample& sample);
    std::uint32_t sample_count(int x, int y) const;
    // Whether add_sample keeps what a sample's camera ray saw first (the AOVs that need it were asked for).
    bool keeps_hit_data() const { return !aovs_.empty(); }
    SampleCountRange sample_count_range() const;
    PixelStatistics pixel_statistics(int x, int y) const;

    // The accumulators exactly (sums, counts, ids), for checkpoints: restore_state(state()) on a film with the
    // same settings gives a film that continues bit-identically. restore_state throws std::invalid_argument naming
    // the pixel if the bytes do not have the size these settings need, a pixel holds more than `max_samples`
    // samples (the render's target) or a sum is not finite.
    std::string state() const;
    void restore_state(std::string_view bytes, std::uint32_t max_samples = UINT32_MAX);

    // The accumulators of `area` (inside bounds()) as a film of its own whose crop is `area`.
    Film region(const PixelBounds& area) const;
    // Replaces the accumulators of part.bounds() (inside bounds()) with part's.
    void replace_region(const Film& part);
    // Adds `later`: for each pixel of later.bounds(), the samples that follow this film's, at most one block of
    // them, starting at a block boundary (a Film(settings, first_sample) rendered up to some count). The result
    // is bit-identical to adding those samples here one by one. Throws std::invalid_argument when a pixel's
    // samples do not follow on like that.
    void append_block(const Film& later);

    // Beauty RGBA followed by the AOV channels in the order requested.
    ImageBuffer resolve() const;

private:
    // A pixel's sums in Real: the samples of its open block in float (a sum of 32 is good to a few parts in 10⁷, near
    // the float image's own rounding), the completed blocks' total in double (a reference render adds thousands).
    template <class Real>
    struct BeautySums {
        Real weight = 0, weight_squared = 0;
        Real rgb[3] = {0, 0, 0};
        Real rgb_squared[3] = {0, 0, 0};
        Real coverage = 0;  // weighted fraction of samples that hit a surface
        static constexpr int kFieldCount = 9;
        // Calls visit(field) for every sum; Self is BeautySums or const BeautySums.
        template <class Self, class Visit>
        static void each(Self& sums, Visit&& visit) {
            visit(sums.weight);
            visit(sums.weight_squared);
            for (auto& v : sums.rgb) visit(v);
            for (auto& v : sums.rgb_squared) visit(v);
            visit(sums.coverage);
        }
    };
    template <class Real>
    struct AovSums {
        Real albedo[3] = {0, 0, 0}, normal[3] = {0, 0, 0}, position[3] = {0, 0, 0};
        Real depth = 0, hit_weight = 0;
        static constexpr int kFieldCount = 11;
        template <class Self, class Visit>
        static void each(Self& sums, Visit&& visit) {
            for (auto& v : sums.albedo) visit(v);
            for (auto& v : sums.normal) visit(v);
            for (auto& v : sums.position) visit(v);
            visit(sums.depth);
            visit(sums.hit_weight);
        }
    };
    // total: the sums of the completed blocks; block: of the samples since.
    struct Accumulator {
        BeautySums<double> total;
        BeautySums<float> block;
        std::uint32_t samples = 0;
    };
    struct AovAccumulator {
        AovSums<double> total;
        AovSums<float> block;
        float nearest_offset = 1e30f;
        std::int64_t object_id = -1, primitive_id = -1;
    };
    static PixelStatistics statistics_of(const BeautySums<double>& sums, std::uint32_t samples);
    std::size_t index(int x, int y) const {
        return std::size_t(y - settings_.crop.y0) * std::size_t(settings_.crop.width()) + std::size_t(x - settings_.crop.x0);
    }

    // Calls visit(field) for every accumulator field; Self is Film or const Film.
    template <class Self, class Visit>
    static void visit_state(Self& film, Visit&& visit);
    std::size_t state_size() const;  // bytes of state()
    // The accumulators of `area` (inside both films' crops) from one film to the other.
    static void copy_pixels(const Film& from, Film& to, const PixelBounds& area);

    FilmSettings settings_;
    // A film starts with zero bytes (zero sums, no samples), written first by the threads that render its pixels.
    ZeroedPages<Accumulator> beauty_;
    ZeroedPages<AovAccumulator> aovs_;  // empty unless AOVs need them
};

}  // namespace isotrace
