#pragma once
// Pixel reconstruction filter, used by filter importance sampling: each camera sample is offset from the
// pixel centre by a draw from the (separable) filter and weighted by filter / pdf, so every sample stays in
// its own pixel and the image does not depend on how pixels are split among threads.
#include <array>
#include <memory>

#include "renderer/plugin/registry.h"

namespace isotrace {

class Distribution1D;

struct FilterSample {
    float dx = 0, dy = 0;  // offset from the pixel centre, in pixels
    float weight = 1;      // filter(dx, dy) / pdf(dx, dy), up to a constant (1 when sampled exactly)
};

class PixelFilter {
public:
    virtual ~PixelFilter();
    float radius() const { return radius_; }
    // Separable 1-D profile, zero outside [-radius, radius].
    virtual float evaluate(float x) const = 0;
    virtual FilterSample sample(std::array<float, 2> u) const;

protected:
    explicit PixelFilter(float radius);
    // Tabulates evaluate() for sample(); concrete filters call it at the end of their constructor.
    void tabulate();

private:
    float sample_axis(float u) const;
    float radius_;
    std::unique_ptr<Distribution1D> table_;
};

Registry<PixelFilter>& pixel_filter_registry();

}  // namespace isotrace
