#include "renderer/film/film.h"

#include <algorithm>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>

#include "renderer/core/memory_budget.h"

namespace isotrace {
namespace {

bool needs_hit_data(const std::vector<Aov>& aovs) {
    return std::any_of(aovs.begin(), aovs.end(),
                       [](Aov a) { return a != Aov::SampleCount && a != Aov::Variance; });
}

}  // namespace

std::uint64_t Film::memory_bytes(const FilmSettings& settings) {
    std::uint64_t channels = 4;
    for (Aov aov : settings.aovs) channels += aov_info(aov).channels.size();
    const std::uint64_t per_pixel = sizeof(Accumulator) + (needs_hit_data(settings.aovs) ? sizeof(AovAccumulator) : 0) +
                                    2 * channels * sizeof(float);
    return saturating_product({std::uint64_t(settings.crop.area()), per_pixel});
}

Film::Film(FilmSettings settings) : settings_(std::move(settings)) {
    beauty_.resize(std::size_t(settings_.crop.area()));
    if (needs_hit_data(settings_.aovs)) aovs_.resize(beauty_.size());
}

void Film::add_sample(int x, int y, const CameraSample& sample) {
    const std::size_t i = index(x, y);
    Accumulator& pixel = beauty_[i];
    const double w = sample.filter_weight;
    const double value[3] = {sample.radiance.r, sample.radiance.g, sample.radiance.b};
    pixel.weight += w;
    pixel.weight_squared += w * w;
    for (int c = 0; c < 3; ++c) {
        pixel.rgb[c] += w * value[c];
        pixel.rgb_squared[c] += w * value[c] * value[c];
    }
    if (sample.primary.hit) pixel.coverage += w;
    ++pixel.samples;
    if (aovs_.empty() || !sample.primary.hit) return;

    AovAccumulator& aov = aovs_[i];
    const PrimaryHitRecord& hit = sample.primary;
    const float a[3] = {hit.albedo.r, hit.albedo.g, hit.albedo.b};
    for (int c = 0; c < 3; ++c) {
        aov.albedo[c] += w * a[c];
        aov.normal[c] += w * hit.shading_normal[c];
        aov.position[c] += w * hit.position[c];
    }
    aov.depth += w * hit.depth;
    aov.hit_weight += w;
    if (sample.offset_squared < aov.nearest_offset) {  // ids cannot be averaged: keep the most central sample's
        aov.nearest_offset = sample.offset_squared;
        aov.object_id = hit.object_id;
        aov.primitive_id = hit.primitive_id;
    }
}

std::uint32_t Film::sample_count(int x, int y) const { return beauty_[index(x, y)].samples; }

SampleCountRange Film::sample_count_range() const {
    SampleCountRange range;
    if (beauty_.empty()) return range;
    range.min = range.max = beauty_.front().samples;
    for (const Accumulator& p : beauty_) {
        range.min = std::min(range.min, p.samples);
        range.max = std::max(range.max, p.samples);
        range.total += p.samples;
    }
    return range;
}

PixelStatistics Film::pixel_statistics(int x, int y) const { return statistics_of(beauty_[index(x, y)]); }

PixelStatistics Film::statistics_of(const Accumulator& p) {
    PixelStatistics statistics;
    statistics.samples = p.samples;
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
        visit(p.weight);
        visit(p.weight_squared);
        for (auto& v : p.rgb) visit(v);
        for (auto& v : p.rgb_squared) visit(v);
        visit(p.coverage);
        visit(p.samples);
    }
    for (auto& a : film.aovs_) {
        for (auto& v : a.albedo) visit(v);
        for (auto& v : a.normal) visit(v);
        for (auto& v : a.position) visit(v);
        visit(a.depth);
        visit(a.hit_weight);
        visit(a.nearest_offset);
        visit(a.object_id);
        visit(a.primitive_id);
    }
}

std::string Film::state() const {
    std::string bytes;
    bytes.reserve(beauty_.size() * (11 * sizeof(double) + sizeof(std::uint32_t)));
    visit_state(*this, [&](const auto& field) {
        bytes.append(reinterpret_cast<const char*>(&field), sizeof field);
    });
    return bytes;
}

void Film::restore_state(std::string_view bytes) {
    std::size_t needed = 0;
    visit_state(*this, [&](auto& field) { needed += sizeof field; });
    if (bytes.size() != needed)
        throw std::invalid_argument("film state: " + std::to_string(bytes.size()) + " bytes where these film settings need " +
                                    std::to_string(needed));
    std::size_t at = 0;
    visit_state(*this, [&](auto& field) {
        std::memcpy(&field, bytes.data() + at, sizeof field);
        at += sizeof field;
    });
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
        const Accumulator& p = beauty_[i];
        float* out = image.pixels.data() + i * stride;
        const double inv_w = p.weight > 0 ? 1.0 / p.weight : 0.0;
        for (int c = 0; c < 3; ++c) out[c] = float(p.rgb[c] * inv_w);
        out[3] = float(p.coverage * inv_w);
        std::size_t k = 4;
        for (Aov aov : settings_.aovs) {
            const AovAccumulator* a = aovs_.empty() ? nullptr : &aovs_[i];
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
                case Aov::ObjectId: out[k++] = float(a->object_id); break;
                case Aov::PrimitiveId: out[k++] = float(a->primitive_id); break;
                case Aov::SampleCount: out[k++] = float(p.samples); break;
                case Aov::Variance:
                    for (int c = 0; c < 3; ++c) out[k++] = float(statistics_of(p).variance_of_mean[c]);
                    break;
            }
        }
    }
    return image;
}

}  // namespace isotrace
