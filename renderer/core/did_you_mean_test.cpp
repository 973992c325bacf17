#include "renderer/core/did_you_mean.h"

#include <gtest/gtest.h>

namespace isotrace {
namespace {

const std::vector<std::string> kNames = {"ACEScg", "ACES2065-1", "Raw", "sRGB - Texture", "lin_rec709"};

TEST(DidYouMean, SuggestsCloseMisspelling) {
    EXPECT_EQ(did_you_mean("ACEScgg", kNames), " (did you mean \"ACEScg\"?)");
    EXPECT_EQ(did_you_mean("lin_rec_709", kNames), " (did you mean \"lin_rec709\"?)");
}

TEST(DidYouMean, IgnoresCase) {
    EXPECT_EQ(did_you_mean("acescg", kNames), " (did you mean \"ACEScg\"?)");
    EXPECT_EQ(did_you_mean("SRGB - TEXTURE", kNames), " (did you mean \"sRGB - Texture\"?)");
}

TEST(DidYouMean, CountsSwappedNeighboursAsOneEdit) {
    EXPECT_EQ(did_you_mean("ACESgc", kNames), " (did you mean \"ACEScg\"?)");
    EXPECT_EQ(did_you_mean("Rwa", kNames), " (did you mean \"Raw\"?)");
}

TEST(DidYouMean, PicksTheClosestCandidate) {
    EXPECT_EQ(did_you_mean("ACES2065", kNames), " (did you mean \"ACES2065-1\"?)");
}

TEST(DidYouMean, StaysSilentWhenNothingIsClose) {
    EXPECT_EQ(did_you_mean("Rec.2020 PQ", kNames), "");
    EXPECT_EQ(did_you_mean("xyz", kNames), "");
    EXPECT_EQ(did_you_mean("", kNames), "");
    EXPECT_EQ(did_you_mean("ACEScg", {}), "");
}

TEST(DidYouMean, ToleratesMoreTyposInLongerWords) {
    EXPECT_EQ(did_you_mean("srgb-textur", kNames), " (did you mean \"sRGB - Texture\"?)");
    EXPECT_EQ(did_you_mean("Rxx", kNames), "");  // two edits in a three-letter word is a different word
}

TEST(DidYouMean, LongWordsAndFarCandidatesCostNoQuadraticWork) {
    const std::string long_word(1 << 16, 'a');
    std::vector<std::string> candidates(100, std::string(1 << 16, 'b'));
    candidates.push_back("radius");
    EXPECT_EQ(did_you_mean(long_word, candidates), "");  // would be 100 * 4e9 steps without the bounds
    EXPECT_EQ(did_you_mean("raduis", candidates), " (did you mean \"radius\"?)");
}

}  // namespace
}  // namespace isotrace
