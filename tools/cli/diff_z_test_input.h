#pragma once
// isotrace diff --ztest: the reference's mean, variance and sample-count channels and the test's colour and
// sample count, gathered from the two files.
#include <optional>
#include <string>

#include "renderer/image_compare/image_file.h"
#include "renderer/image_compare/z_test.h"

namespace isotrace::cli {

// The reference needs R, G, B, variance.R/G/B and sampleCount (isotrace render --aov variance,sample_count).
// The test's sample count comes from its sampleCount channel, else `test_spp`, else its isotrace:spp metadata;
// its variance from its variance channels when it has them. Throws InputError naming the file and what is
// missing, or when both files record the same isotrace:seed (the test would repeat the reference's samples).
ZTestInput z_test_input(const ImageFile& reference, const std::string& reference_path, const ImageFile& test,
                        const std::string& test_path, std::optional<int> test_spp);

}  // namespace isotrace::cli
