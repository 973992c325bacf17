#include "renderer/film/film.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <type_traits>

#include "renderer/core/memory_budget.h"

namespace isotrace {
namespace {

bool needs_hit_data(const std::vector<Aov>& aovs) {
    return std::any_of(aovs.begin(), aovs.end(),
                       [](Aov a) { return a != Aov::SampleCount && a != Aov::Variance; });
}

// into += from, field by field (the sums of a block added to those of the blocks before it).
template <template <class> class Sums, class Real>
void add_sums(Sums<double>& into, const Sums<Real>& from) {
    static_assert(sizeof(Sums<Real>) == Sums<Real>::kFieldCount * sizeof(Real), "kFieldCount counts every sum");
    double* target[Sums<double>::kFieldCount];
    int n = 0;
    Sums<double>::each(into, [&](double& field) { target[n++] = &field; });
    n = 0;
    Sums<Real>::each(from, [&](const Real& field) { *target[n++] += double(field); });
}

// Ends a pixel's block: its sums join the total and the next block starts from zero.
template <template <class> class Sums>
void close_block(Sums<double>& total, Sums<float>& block) {
    add_sums(total, block);
    block = Sums<float>();
}

// total + block: a pixel's sums over all its samples.
template <template <class> class Sums>
Sums<double> all_samples(const Sums<double>& total, const Sums<float>& block) {
    Sums<double> sum = total;
    add_sums(sum, block);
    return sum;
}

}  // namespace

std::uint64_t Film::memory_bytes(const FilmSettings& settings) {
    std::uint64_t channels = 4;
    for (Aov aov : settings.aovs) channels += aov_info(aov).channels.size();
    const std::uint64_t per_pixel = sizeof(Accumulator) + (needs_hit_data(settings.aovs) ? sizeof(AovAccumulator) : 0) +
                                    2 * channels * sizeof(float);
    return saturating_product({std::uint64_t(settings.crop.area()), per_pixel});
}

Film::Film(FilmSettings settings)
    : settings_(std::move(settings)),
      beauty_(std::size_t(settings_.crop.area())),
      aovs_(needs_hit_data(settings_.aovs) ? beauty_.size() : 0) {
    for (AovAccumulator& a : aovs_) a = AovAccumulator();  // no id yet: not all zero bytes
}

Film::Film(FilmSettings settings, std::uint32_t first_sample) : Film(std::move(settings)) {
    if (first_sample % kSampleBlock != 0)
        throw std::invalid_argument("a film's first sample must start a block of " + std::to_string(kSampleBlock));
    for (Accumulator& p : beauty_) p.samples = first_sample;
}

void Film::add_sample(int x, int y, const CameraSample& sample) {
    const std::size_t i = index(x, y);
    Accumulator& pixel = beauty_[i];
    BeautySums<float>& sums = pixel.block;
    const float w = sample.filter_weight;
    const float value[3] = {sample.radiance.r, sample.radiance.g, sample.radiance.b};
    sums.weight += w;
    sums.weight_squared += w * w;
    for (int c = 0; c < 3; ++c) {
        sums.rgb[c] += w * value[c];
        sums.rgb_squared[c] += w * value[c] * value[c];
    }
    if (sample.primary.hit) sums.coverage += w;
    const bool block_ends = ++pixel.samples % kSampleBlock == 0;
    if (block_ends) close_block(pixel.total, pixel.block);
    if (aovs_.empty()) return;

    AovAccumulator& aov = aovs_[i];
    if (sample.primary.hit) {
        const PrimaryHitRecord& hit = sample.primary;
        const float a[3] = {hit.albedo.r, hit.albedo.g, hit.albedo.b};
        for (int c = 0; c < 3; ++c) {
            aov.block.albedo[c] += w * a[c];
            aov.block.normal[c] += w * hit.shading_normal[c];
            aov.block.position[c] += w * hit.position[c];
        }
        aov.block.depth += w * hit.depth;
        aov.block.hit_weight += w;
        if (sample.offset_squared < aov.nearest_offset) {  // ids cannot be averaged: keep the most central sample's
            aov.nearest_offset = sample.offset_squared;
            aov.object_id = hit.object_id;
            aov.primitive_id = hit.primitive_id;
        }
    }
    if (block_ends) close_block(aov.total, aov.block);
}

std::uint32_t Film::sample_count(int x, int y) const { return beauty_[index(x, y)].samples; }

SampleCountRange Film::sample_count_range() const {
    SampleCountRange range;
    if (beauty_.empty()) return range;
    range.min = range.max = beauty_[0].samples;
    for (const Accumulator& p : beauty_) {
        range.min = std::min(range.min, p.samples);
        range.max = std::max(range.max, p.samples);
        range.total += p.samples;
    }
    return range;
}

PixelStatistics Film::pixel_statistics(int x, int y) const {
    const Accumulator& pixel = beauty_[index(x, y)];
    return statistics_of(all_samples(pixel.total, pixel.block), pixel.samples);
}

PixelStatistics Film::statistics_of(const BeautySums<double>& p, std::uint32_t samples) {
    PixelStatistics statistics;
    statistics.samples = samples;
    const double inv_w = p.weight > 0 ? 1.0 / p.weight : 0.0;
    // Sums in double: the cancellation in E[x^2] - E[x]^2 costs about n * 1e-16 of mean^2, far below the noise
    // of any pixel whose variance matters (docs/decisions.md, "Reference mode").
    const double denominator = p.weight * p.weight - p.weight_squared;
    for (int c = 0; c < 3; ++c) {
        const double mean = p.rgb[c] * inv_w;
        const double spread = std::max(0.0, p.rgb_squared[c] * inv_w - mean * mean);
        statistics.mean[c] = mean;
        statistics.variance_of_mean[c] = denominator > 0 ? spread * p.weight_squared / denominator
                                                         : std::numeric_limits<double>::infinity();
    }
    return statistics;
}

// Field by field (struct padding is not data), in declaration order, in the machine's byte order.
template <class Self, class Visit>
void Film::visit_state(Self& film, Visit&& visit) {
    for (auto& p : film.beauty_) {
        BeautySums<double>::each(p.total, visit);
        BeautySums<float>::each(p.block, visit);
        visit(p.samples);
    }
    for (auto& a : film.aovs_) {
        AovSums<double>::each(a.total, visit);
        AovSums<float>::each(a.block, visit);
        visit(a.nearest_offset);
        visit(a.object_id);
        visit(a.primitive_id);
    }
}

std::size_t Film::state_size() const {
    std::size_t size = 0;
    visit_state(*this, [&](const auto& field) { size += sizeof field; });
    return size;
}

std::string Film::state() const {
    std::string bytes;
    bytes.reserve(state_size());
    visit_state(*this, [&](const auto& field) {
        bytes.append(reinterpret_cast<const char*>(&field), sizeof field);
    });
    return bytes;
}

void Film::restore_state(std::string_view bytes, std::uint32_t max_samples) {
    const std::size_t needed = state_size();
    if (bytes.size() != needed)
        throw std::invalid_argument("film state: " + std::to_string(bytes.size()) + " bytes where these film settings need " +
                                    std::to_string(needed));
    std::size_t at = 0;
    visit_state(*this, [&](auto& field) {
        std::memcpy(&field, bytes.data() + at, sizeof field);
        at += sizeof field;
    });
    // Values no render leaves: a checksum only says that the bytes are the ones written.
    const auto refuse = [&](std::size_t i, const std::string& problem) {
        const std::size_t width = std::size_t(settings_.crop.width());
        throw std::invalid_argument("film state: pixel (" + std::to_string(settings_.crop.x0 + int(i % width)) + ", " +
                                    std::to_string(settings_.crop.y0 + int(i / width)) + ") " + problem);
    };
    const auto finite = [](const auto& sums) {
        bool all = true;
        std::decay_t<decltype(sums)>::each(sums, [&](auto v) { all = all && std::isfinite(v); });
        return all;
    };
    for (std::size_t i = 0; i < beauty_.size(); ++i) {
        const Accumulator& pixel = beauty_[i];
        if (pixel.samples > max_samples)
            refuse(i, "has a sample count of " + std::to_string(pixel.samples) + ", above the render's target of " +
                          std::to_string(max_samples));
        if (!finite(pixel.total) || !finite(pixel.block)) refuse(i, "holds a sum that is not a finite number");
    }
    for (std::size_t i = 0; i < aovs_.size(); ++i) {
        const AovAccumulator& aov = aovs_[i];
        if (!finite(aov.total) || !finite(aov.block) || !std::isfinite(aov.nearest_offset))
            refuse(i, "holds an AOV sum that is not a finite number");
    }
}

void Film::copy_pixels(const Film& from, Film& to, const PixelBounds& area) {
    for (int y = area.y0; y < area.y1; ++y) {
        const std::size_t source = from.index(area.x0, y), target = to.index(area.x0, y);
        std::copy_n(from.beauty_.begin() + source, area.width(), to.beauty_.begin() + target);
        if (!to.aovs_.empty()) std::copy_n(from.aovs_.begin() + source, area.width(), to.aovs_.begin() + target);
    }
}

Film Film::region(const PixelBounds& area) const {
    FilmSettings settings = settings_;
    settings.crop = area;
    Film part(std::move(settings));
    copy_pixels(*this, part, area);
    return part;
}

void Film::replace_region(const Film& part) { copy_pixels(part, *this, part.bounds()); }

void Film::append_block(const Film& later) {
    const PixelBounds& area = later.bounds();
    for (int y = area.y0; y < area.y1; ++y) {
        for (int x = area.x0; x < area.x1; ++x) {
            Accumulator& pixel = beauty_[index(x, y)];
            const Accumulator& next = later.beauty_[later.index(x, y)];
            if (pixel.samples % kSampleBlock != 0 || next.samples <= pixel.samples ||
                next.samples - pixel.samples > kSampleBlock)
                throw std::invalid_argument("film block: pixel (" + std::to_string(x) + ", " + std::to_string(y) +
                                            ") holds " + std::to_string(pixel.samples) +
                                            " samples; the block to append ends at " + std::to_string(next.samples));
            // `next` started from zero at a block boundary: its total is its one completed block (or zero), and
            // its open block is what follows it, exactly as add_sample would have left them here.
            add_sums(pixel.total, next.total);
            pixel.block = next.block;
            pixel.samples = next.samples;
            if (aovs_.empty()) continue;
            AovAccumulator& aov = aovs_[index(x, y)];
            const AovAccumulator& next_aov = later.aovs_[later.index(x, y)];
            add_sums(aov.total, next_aov.total);
            aov.block = next_aov.block;
            if (next_aov.nearest_offset < aov.nearest_offset) {  // strictly nearer, as add_sample decides
                aov.nearest_offset = next_aov.nearest_offset;
                aov.object_id = next_aov.object_id;
                aov.primitive_id = next_aov.primitive_id;
            }
        }
    }
}

ImageBuffer Film::resolve() const {
    ImageBuffer image;
    image.width = settings_.crop.width();
    image.height = settings_.crop.height();
    image.channels = {"R", "G", "B", "A"};
    for (Aov aov : settings_.aovs)
        for (const char* channel : aov_info(aov).channels) image.channels.push_back(channel);
    const std::size_t stride = image.channels.size();
    image.pixels.assign(beauty_.size() * stride, 0.0f);
    const float inf = std::numeric_limits<float>::infinity();

    for (std::size_t i = 0; i < beauty_.size(); ++i) {
        const std::uint32_t samples = beauty_[i].samples;
        const BeautySums<double> p = all_samples(beauty_[i].total, beauty_[i].block);
        float* out = image.pixels.data() + i * stride;
        const double inv_w = p.weight > 0 ? 1.0 / p.weight : 0.0;
        for (int c = 0; c < 3; ++c) out[c] = float(p.rgb[c] * inv_w);
        out[3] = float(p.coverage * inv_w);
        std::size_t k = 4;
        for (Aov aov : settings_.aovs) {
            const AovAccumulator* ids = aovs_.empty() ? nullptr : &aovs_[i];
            const std::optional<AovSums<double>> sums =
                ids ? std::optional<AovSums<double>>(all_samples(ids->total, ids->block)) : std::nullopt;
            const AovSums<double>* a = sums ? &*sums : nullptr;
            const double inv_hit = a && a->hit_weight > 0 ? 1.0 / a->hit_weight : 0.0;
            switch (aov) {
                case Aov::Albedo:
                    for (int c = 0; c < 3; ++c) out[k++] = float(a->albedo[c] * inv_hit);
                    break;
                case Aov::Normal:
                    for (int c = 0; c < 3; ++c) out[k++] = float(a->normal[c] * inv_hit);
                    break;
                case Aov::Position:
                    for (int c = 0; c < 3; ++c) out[k++] = float(a->position[c] * inv_hit);
                    break;
                case Aov::Depth: out[k++] = a->hit_weight > 0 ? float(a->depth * inv_hit) : inf; break;
                case Aov::ObjectId: out[k++] = float(ids->object_id); break;
                case Aov::PrimitiveId: out[k++] = float(ids->primitive_id); break;
                case Aov::SampleCount: out[k++] = float(samples); break;
                case Aov::Variance: {
                    const PixelStatistics statistics = statistics_of(p, samples);
                    for (int c = 0; c < 3; ++c) out[k++] = float(statistics.variance_of_mean[c]);
                    break;
                }
            }
        }
    }
    return image;
}

}  // namespace isotrace
