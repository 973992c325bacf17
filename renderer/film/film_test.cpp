// Film accumulation: weighted means, alpha coverage, the variance of the mean, depth and ids, sample counts,
// crop-window indexing and the channel layout of resolve().
#include "renderer/film/film.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "renderer/core/input_error.h"

namespace isotrace {
namespace {

FilmSettings settings(int width, int height, std::vector<Aov> aovs = {}, PixelBounds crop = {}) {
    FilmSettings s;
    s.raster = {width, height};
    s.crop = crop.area() > 0 ? crop : PixelBounds{0, 0, width, height};
    s.aovs = std::move(aovs);
    return s;
}

CameraSample miss(const Rgb& radiance, float weight = 1, float offset_squared = 0) {
    CameraSample s;
    s.radiance = radiance;
    s.filter_weight = weight;
    s.offset_squared = offset_squared;
    return s;
}

CameraSample hit(const Rgb& radiance, float weight, float depth, std::uint32_t object, std::uint32_t primitive,
                 float offset_squared = 0) {
    CameraSample s = miss(radiance, weight, offset_squared);
    s.primary.hit = true;
    s.primary.depth = depth;
    s.primary.object_id = object;
    s.primary.primitive_id = primitive;
    s.primary.albedo = Rgb(0.5f * weight, 0.25f, 1.0f);
    s.primary.shading_normal = Vec3f(0, weight, 1);
    s.primary.position = Vec3f(depth, 2 * depth, -depth);
    return s;
}

int channel(const ImageBuffer& image, const std::string& name) {
    for (std::size_t i = 0; i < image.channels.size(); ++i)
        if (image.channels[i] == name) return int(i);
    ADD_FAILURE() << "no channel " << name;
    return 0;
}

float value(ImageBuffer& image, int x, int y, const std::string& name) { return image.pixel(x, y)[channel(image, name)]; }

TEST(Film, ResolveIsTheWeightedMean) {
    Film film(settings(2, 1));
    const float weights[] = {0.5f, 2.0f, 1.25f, 0.125f};
    const Rgb values[] = {{1, 2, 3}, {0.5f, 0.25f, 8}, {4, 0, 1}, {-1, 3, 0.5f}};
    double sum_w = 0, sum[3] = {0, 0, 0};
    for (int i = 0; i < 4; ++i) {
        film.add_sample(1, 0, miss(values[i], weights[i]));
        sum_w += weights[i];
        sum[0] += double(weights[i]) * values[i].r;
        sum[1] += double(weights[i]) * values[i].g;
        sum[2] += double(weights[i]) * values[i].b;
    }
    ImageBuffer image = film.resolve();
    ASSERT_EQ(image.width, 2);
    ASSERT_EQ(image.height, 1);
    EXPECT_FLOAT_EQ(image.pixel(1, 0)[0], float(sum[0] / sum_w));
    EXPECT_FLOAT_EQ(image.pixel(1, 0)[1], float(sum[1] / sum_w));
    EXPECT_FLOAT_EQ(image.pixel(1, 0)[2], float(sum[2] / sum_w));
    EXPECT_EQ(image.pixel(1, 0)[3], 0.0f);  // nothing was hit
    // The untouched pixel is black and transparent, not NaN.
    for (int c = 0; c < 4; ++c) EXPECT_EQ(image.pixel(0, 0)[c], 0.0f);
}

TEST(Film, ScaleOfTheWeightsCancels) {
    Film a(settings(1, 1)), b(settings(1, 1));
    const Rgb values[] = {{1, 2, 3}, {0.5f, 0.25f, 8}, {4, 0, 1}};
    for (const Rgb& v : values) {
        a.add_sample(0, 0, miss(v, 1.0f));
        b.add_sample(0, 0, miss(v, 0.25f));  // a power of two: exactly the same quotients
    }
    const ImageBuffer ia = a.resolve(), ib = b.resolve();
    EXPECT_EQ(ia.pixels, ib.pixels);
}

TEST(Film, AlphaIsTheWeightedCoverage) {
    Film film(settings(1, 1));
    film.add_sample(0, 0, hit(Rgb(1), 1.0f, 2, 0, 0));
    film.add_sample(0, 0, miss(Rgb(0), 3.0f));
    film.add_sample(0, 0, hit(Rgb(1), 0.5f, 2, 0, 0));
    film.add_sample(0, 0, hit(Rgb(1), 0.5f, 2, 0, 0));
    ImageBuffer image = film.resolve();
    EXPECT_FLOAT_EQ(value(image, 0, 0, "A"), 2.0f / 5.0f);
    EXPECT_FLOAT_EQ(value(image, 0, 0, "R"), 2.0f / 5.0f);  // radiance 1 on the hits, 0 on the miss
}

TEST(Film, VarianceAovIsTheSampleVarianceOfTheMeanForEqualWeights) {
    for (float w : {1.0f, 0.3f, 2.5f}) {
        Film film(settings(1, 1, {Aov::Variance}));
        const std::vector<Rgb> values = {{1, 0, 5}, {2, 0, 5.5f}, {4, 0, 4}, {0.5f, 0, 7}, {3, 0, 6}};
        for (const Rgb& v : values) film.add_sample(0, 0, miss(v, w));
        ImageBuffer image = film.resolve();
        const double n = double(values.size());
        for (int c = 0; c < 3; ++c) {
            double mean = 0;
            for (const Rgb& v : values) mean += (c == 0 ? v.r : c == 1 ? v.g : v.b) / n;
            double squares = 0;
            for (const Rgb& v : values) squares += std::pow((c == 0 ? v.r : c == 1 ? v.g : v.b) - mean, 2);
            const double sample_variance = squares / (n - 1);
            const char* names[] = {"variance.R", "variance.G", "variance.B"};
            EXPECT_NEAR(value(image, 0, 0, names[c]), sample_variance / n, 1e-6 * (1 + sample_variance))
                << "weight " << w << " channel " << c;
        }
    }
}

TEST(Film, VarianceWithOneSampleIsUnknown) {
    Film film(settings(2, 1, {Aov::Variance}));
    film.add_sample(0, 0, miss(Rgb(1), 1));
    ImageBuffer image = film.resolve();
    EXPECT_TRUE(std::isinf(value(image, 0, 0, "variance.R")));
    EXPECT_TRUE(std::isinf(value(image, 1, 0, "variance.G")));  // no sample at all
}

TEST(Film, DepthIsTheWeightedMeanOverHittingSamplesAndInfinityWithoutHits) {
    Film film(settings(2, 1, {Aov::Depth}));
    film.add_sample(0, 0, hit(Rgb(1), 1.0f, 2.0f, 0, 0));
    film.add_sample(0, 0, miss(Rgb(1), 5.0f));  // misses do not pull the depth towards anything
    film.add_sample(0, 0, hit(Rgb(1), 3.0f, 6.0f, 0, 0));
    film.add_sample(1, 0, miss(Rgb(1), 1.0f));
    ImageBuffer image = film.resolve();
    EXPECT_EQ(value(image, 0, 0, "Z"), float((1.0 * 2 + 3.0 * 6) / 4.0));
    EXPECT_EQ(value(image, 1, 0, "Z"), std::numeric_limits<float>::infinity());
}

TEST(Film, AlbedoNormalPositionAreWeightedMeansOverHits) {
    Film film(settings(1, 1, {Aov::Albedo, Aov::Normal, Aov::Position}));
    const CameraSample a = hit(Rgb(0), 1.0f, 1.0f, 0, 0), b = hit(Rgb(0), 3.0f, 5.0f, 0, 0);
    film.add_sample(0, 0, a);
    film.add_sample(0, 0, miss(Rgb(0), 10.0f));
    film.add_sample(0, 0, b);
    ImageBuffer image = film.resolve();
    const auto mean = [](float x, float y) { return float((1.0 * x + 3.0 * y) / 4.0); };
    EXPECT_EQ(value(image, 0, 0, "albedo.R"), mean(a.primary.albedo.r, b.primary.albedo.r));
    EXPECT_EQ(value(image, 0, 0, "albedo.B"), 1.0f);
    EXPECT_EQ(value(image, 0, 0, "N.Y"), mean(a.primary.shading_normal.y, b.primary.shading_normal.y));
    EXPECT_EQ(value(image, 0, 0, "P.X"), mean(1, 5));
    EXPECT_EQ(value(image, 0, 0, "P.Y"), mean(2, 10));
    EXPECT_EQ(value(image, 0, 0, "P.Z"), mean(-1, -5));
}

TEST(Film, IdsComeFromTheMostCentralHittingSample) {
    Film film(settings(3, 1, {Aov::ObjectId, Aov::PrimitiveId}));
    // Pixel 0: the most central sample arrives in the middle.
    film.add_sample(0, 0, hit(Rgb(0), 1, 1, 4, 40, 0.3f));
    film.add_sample(0, 0, hit(Rgb(0), 1, 1, 7, 70, 0.01f));
    film.add_sample(0, 0, hit(Rgb(0), 1, 1, 9, 90, 0.2f));
    // Pixel 1: only misses.
    film.add_sample(1, 0, miss(Rgb(0), 1, 0.0f));
    // Pixel 2: a large id survives the float channel exactly, and a central miss does not clear it.
    film.add_sample(2, 0, hit(Rgb(0), 1, 1, 123456, 16777215, 0.25f));
    film.add_sample(2, 0, miss(Rgb(0), 1, 0.0f));
    ImageBuffer image = film.resolve();
    EXPECT_EQ(value(image, 0, 0, "objectId"), 7.0f);
    EXPECT_EQ(value(image, 0, 0, "primitiveId"), 70.0f);
    EXPECT_EQ(value(image, 1, 0, "objectId"), -1.0f);
    EXPECT_EQ(value(image, 1, 0, "primitiveId"), -1.0f);
    EXPECT_EQ(value(image, 2, 0, "objectId"), 123456.0f);
    EXPECT_EQ(value(image, 2, 0, "primitiveId"), 16777215.0f);
}

TEST(Film, SampleCountCountsEverySample) {
    Film film(settings(3, 2, {Aov::SampleCount}));
    for (int i = 0; i < 5; ++i) film.add_sample(2, 1, miss(Rgb(1), 0.5f));
    film.add_sample(0, 0, hit(Rgb(1), 1.0f, 1, 0, 0));
    EXPECT_EQ(film.sample_count(2, 1), 5u);
    EXPECT_EQ(film.sample_count(0, 0), 1u);
    EXPECT_EQ(film.sample_count(1, 1), 0u);
    ImageBuffer image = film.resolve();
    EXPECT_EQ(value(image, 2, 1, "sampleCount"), 5.0f);
    EXPECT_EQ(value(image, 0, 0, "sampleCount"), 1.0f);
    EXPECT_EQ(value(image, 1, 0, "sampleCount"), 0.0f);
}

TEST(Film, CropWindowIsIndexedInFullRasterCoordinates) {
    const PixelBounds crop{2, 3, 6, 5};
    Film film(settings(10, 8, {Aov::SampleCount}, crop));
    EXPECT_EQ(film.bounds().x0, 2);
    EXPECT_EQ(film.bounds().y1, 5);
    for (int y = crop.y0; y < crop.y1; ++y)
        for (int x = crop.x0; x < crop.x1; ++x)
            for (int s = 0; s <= x + 10 * y; s += 7) film.add_sample(x, y, miss(Rgb(float(x), float(y), float(s)), 1));
    ImageBuffer image = film.resolve();
    ASSERT_EQ(image.width, 4);
    ASSERT_EQ(image.height, 2);
    ASSERT_EQ(image.pixels.size(), std::size_t(4 * 2 * 5));
    for (int y = crop.y0; y < crop.y1; ++y)
        for (int x = crop.x0; x < crop.x1; ++x) {
            const float* p = image.pixel(x - crop.x0, y - crop.y0);
            EXPECT_EQ(p[0], float(x));
            EXPECT_EQ(p[1], float(y));
            EXPECT_EQ(p[4], float((x + 10 * y) / 7 + 1));
            EXPECT_EQ(film.sample_count(x, y), std::uint32_t((x + 10 * y) / 7 + 1));
        }
}

TEST(Film, ChannelsAreBeautyThenAovsInRequestedOrder) {
    Film film(settings(1, 1, {Aov::SampleCount, Aov::Normal, Aov::Depth, Aov::Albedo, Aov::ObjectId, Aov::Position,
                              Aov::PrimitiveId, Aov::Variance}));
    const ImageBuffer image = film.resolve();
    const std::vector<std::string> expected = {"R",       "G",       "B",        "A",          "sampleCount",
                                               "N.X",     "N.Y",     "N.Z",      "Z",          "albedo.R",
                                               "albedo.G", "albedo.B", "objectId", "P.X",        "P.Y",
                                               "P.Z",     "primitiveId", "variance.R", "variance.G", "variance.B"};
    EXPECT_EQ(image.channels, expected);
    EXPECT_EQ(image.pixels.size(), expected.size());
    const Film plain(settings(1, 1));
    EXPECT_EQ(plain.resolve().channels, (std::vector<std::string>{"R", "G", "B", "A"}));
}

TEST(Film, AovTableMatchesParsing) {
    EXPECT_EQ(parse_aov_list("depth,albedo,depth", "test"), (std::vector<Aov>{Aov::Depth, Aov::Albedo}));
    EXPECT_EQ(parse_aov_list("all", "test").size(), all_aovs().size());
    EXPECT_THROW(parse_aov_list("albdo", "test"), InputError);
}

// A film restored from state() continues exactly as the original: the same further samples give the same bits,
// in every channel (accumulated doubles, counts, nearest-sample ids).
TEST(Film, StateRestoresEveryAccumulatorExactly) {
    const FilmSettings s = settings(3, 2, {Aov::Albedo, Aov::Depth, Aov::ObjectId,
                                           Aov::SampleCount, Aov::Variance});
    Film original(s);
    const auto feed = [](Film& film, int round) {
        for (int y = 0; y < 2; ++y)
            for (int x = 0; x < 3; ++x)
                if ((x + y + round) % 3 != 0)
                    film.add_sample(x, y, hit(Rgb(0.1f * float(round) + 1.0f / 3, 0.7f / float(x + 1), 1e-3f * float(y)),
                                              0.3f + 0.1f * float(round), 1.5f + float(x), std::uint32_t(round),
                                              std::uint32_t(x), 0.01f * float((round * 7) % 5)));
        film.add_sample(0, 0, miss(Rgb(2, 2, 2), 0.9f));
    };
    for (int round = 0; round < 3; ++round) feed(original, round);
    Film restored(s);
    restored.restore_state(original.state());
    EXPECT_EQ(restored.state(), original.state());
    for (int round = 3; round < 6; ++round) {
        feed(original, round);
        feed(restored, round);
    }
    const ImageBuffer a = original.resolve(), b = restored.resolve();
    ASSERT_EQ(a.pixels.size(), b.pixels.size());
    EXPECT_EQ(std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(float)), 0);
    EXPECT_EQ(restored.sample_count_range().total, original.sample_count_range().total);
}

TEST(Film, StateOfOtherSettingsIsRefused) {
    Film small(settings(2, 2)), large(settings(3, 2)), with_aovs(settings(2, 2, {Aov::Normal}));
    EXPECT_THROW(large.restore_state(small.state()), std::invalid_argument);
    EXPECT_THROW(with_aovs.restore_state(small.state()), std::invalid_argument);
    EXPECT_THROW(small.restore_state(small.state() + "x"), std::invalid_argument);
    EXPECT_NO_THROW(small.restore_state(Film(settings(2, 2)).state()));
}

// A checkpoint's checksum says only that its bytes are the ones written: restore_state checks the values behind it.
// A count beyond the render's target never finished the render; a NaN sum gave NaN pixels.
TEST(Film, HoldsRadianceWhoseSquareItsSumsKeepFinite) {
    EXPECT_TRUE(Film::holds(Rgb(0, 1, 2)));
    EXPECT_TRUE(Film::holds(Rgb(-Film::kLargestRadiance, Film::kLargestRadiance, 0)));
    EXPECT_FALSE(Film::holds(Rgb(0, 0, 3e30f)));  // finite, but its square is not in single precision
    EXPECT_FALSE(Film::holds(Rgb(0, -2 * Film::kLargestRadiance, 0)));
    EXPECT_FALSE(Film::holds(Rgb(std::numeric_limits<float>::quiet_NaN(), 0, 0)));
    EXPECT_FALSE(Film::holds(Rgb(0, std::numeric_limits<float>::infinity(), 0)));
    // The largest held value, squared and weighted by a generous filter weight, keeps the sums finite.
    const float most = Film::kLargestRadiance;
    EXPECT_TRUE(std::isfinite(32 * 100.0f * most * most));
}

TEST(Film, StateWithValuesNoRenderLeavesIsRefused) {
    const FilmSettings s = settings(2, 1, {Aov::Depth});
    Film film(s);
    film.add_sample(0, 0, hit(Rgb(1, 1, 1), 1, 2, 3, 4));
    film.add_sample(1, 0, miss(Rgb(1, 1, 1)));
    const std::string state = film.state();
    // A pixel's beauty state: 9 sums of the completed blocks (double), 9 of the open block (float), then the count.
    constexpr std::size_t kTotal = 9 * sizeof(double), kSums = kTotal + 9 * sizeof(float);
    constexpr std::size_t kPixel = kSums + sizeof(std::uint32_t);
    const auto refusal = [&](std::string bytes, std::uint32_t max_samples) -> std::string {
        try {
            Film(s).restore_state(bytes, max_samples);
        } catch (const std::invalid_argument& error) {
            return error.what();
        }
        return "restored";
    };
    const auto with = [&](std::size_t at, auto value) {
        std::string bytes = state;
        std::memcpy(bytes.data() + at, &value, sizeof value);
        return bytes;
    };
    EXPECT_EQ(refusal(state, 1), "restored");
    EXPECT_EQ(refusal(state, 0), "film state: pixel (0, 0) has a sample count of 1, above the render's target of 0");
    EXPECT_EQ(refusal(with(kPixel + kSums, std::uint32_t(0xFFFFFFFF)), 16),
              "film state: pixel (1, 0) has a sample count of 4294967295, above the render's target of 16");
    EXPECT_EQ(refusal(with(kPixel, std::numeric_limits<double>::quiet_NaN()), 16),
              "film state: pixel (1, 0) holds a sum that is not a finite number");
    EXPECT_EQ(refusal(with(kPixel + kTotal, std::numeric_limits<float>::infinity()), 16),
              "film state: pixel (1, 0) holds a sum that is not a finite number");
    EXPECT_EQ(refusal(with(2 * kPixel + 3 * sizeof(double), -std::numeric_limits<double>::infinity()), 16),
              "film state: pixel (0, 0) holds an AOV sum that is not a finite number");
}

// Sample s of pixel (x, y): values of very different magnitudes, so that any change in the order of the
// additions would change the rounded sums.
CameraSample varied_sample(int x, int y, std::uint32_t s) {
    const float v = float((s * 7919u + std::uint32_t(x) * 104729u + std::uint32_t(y) * 1299709u) % 1000u);
    CameraSample sample = hit(Rgb(v * 1e-3f, 1.0f / (v + 1.0f), v * v * 1e3f), 0.25f + 1e-4f * float(s % 17),
                              1.0f + v, s % 5, std::uint32_t(x), float(s % 3) * 0.1f);
    sample.primary.hit = s % 4 != 1;
    return sample;
}

void feed_samples(Film& film, std::uint32_t first, std::uint32_t last) {
    for (int y = film.bounds().y0; y < film.bounds().y1; ++y)
        for (int x = film.bounds().x0; x < film.bounds().x1; ++x)
            for (std::uint32_t s = first; s < last; ++s) film.add_sample(x, y, varied_sample(x, y, s));
}

// The distributed sample split: blocks of sample indices rendered into separate films and appended in order give
// the bits of one film that took every sample itself, also for a last block that is not full.
TEST(Film, AppendedBlocksEqualOneFilmBitForBit) {
    const FilmSettings s = settings(3, 2, {Aov::Albedo, Aov::Depth, Aov::ObjectId, Aov::Variance});
    constexpr std::uint32_t block = Film::kSampleBlock, last = 2 * block + 5;
    Film whole(s);
    feed_samples(whole, 0, last);
    Film merged(s);
    for (std::uint32_t first = 0; first < last; first += block) {
        Film part(s, first);
        feed_samples(part, first, std::min(first + block, last));
        merged.append_block(part);
    }
    EXPECT_EQ(merged.state(), whole.state());
    const ImageBuffer a = whole.resolve(), b = merged.resolve();
    EXPECT_EQ(std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(float)), 0);
}

TEST(Film, AppendingABlockThatDoesNotFollowIsRefused) {
    const FilmSettings s = settings(2, 1);
    Film merged(s);
    Film second_block(s, Film::kSampleBlock);
    feed_samples(second_block, Film::kSampleBlock, Film::kSampleBlock + 1);
    EXPECT_THROW(merged.append_block(second_block), std::invalid_argument);  // the first block is missing
    Film two_blocks(s, 0);
    feed_samples(two_blocks, 0, 2 * Film::kSampleBlock);
    EXPECT_THROW(merged.append_block(two_blocks), std::invalid_argument);  // more than one block
    EXPECT_THROW(Film(s, 1), std::invalid_argument);                      // not at a block boundary
}

// The distributed tile split: regions rendered separately and put back give the film rendered whole.
TEST(Film, RegionsReplacedEqualOneFilm) {
    const FilmSettings s = settings(5, 4, {Aov::Normal}, PixelBounds{1, 1, 5, 4});
    Film whole(s);
    feed_samples(whole, 0, 40);
    Film assembled(s);
    for (const PixelBounds& area : {PixelBounds{1, 1, 3, 4}, PixelBounds{3, 1, 5, 2}, PixelBounds{3, 2, 5, 4}}) {
        Film part = assembled.region(area);
        EXPECT_EQ(part.bounds().x0, area.x0);
        feed_samples(part, 0, 40);
        assembled.replace_region(part);
    }
    EXPECT_EQ(assembled.state(), whole.state());
    EXPECT_EQ(whole.region(PixelBounds{3, 2, 5, 4}).state(), assembled.region(PixelBounds{3, 2, 5, 4}).state());
}

TEST(Film, SampleCountRangeSpansThePixels) {
    Film film(settings(2, 2));
    EXPECT_EQ(film.sample_count_range().max, 0u);
    film.add_sample(1, 0, miss(Rgb(1, 1, 1)));
    film.add_sample(1, 0, miss(Rgb(1, 1, 1)));
    film.add_sample(0, 1, miss(Rgb(1, 1, 1)));
    const SampleCountRange range = film.sample_count_range();
    EXPECT_EQ(range.min, 0u);
    EXPECT_EQ(range.max, 2u);
    EXPECT_EQ(range.total, 3u);
}

}  // namespace
}  // namespace isotrace
