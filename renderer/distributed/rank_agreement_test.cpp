// Rank agreement: identities survive their message, and any difference from rank 0 (load error, version, build,
// scene) is reported naming the rank and its host.
#include "renderer/distributed/rank_agreement.h"

#include <gtest/gtest.h>

namespace isotrace {
namespace {

RankIdentity identity(const std::string& host) {
    RankIdentity id;
    id.host = host;
    id.version = "1.2.3";
    id.binary = 0x1234;
    id.scene = 0xabcd;
    return id;
}

TEST(RankAgreement, IdentityRoundTripsThroughItsMessage) {
    RankIdentity id = identity("node-7");
    id.load_error = "scene.json:3:5: objects[0].radius: must be positive";
    const RankIdentity back = decode_identity(encode_identity(id));
    EXPECT_EQ(back.host, id.host);
    EXPECT_EQ(back.version, id.version);
    EXPECT_EQ(back.binary, id.binary);
    EXPECT_EQ(back.scene, id.scene);
    EXPECT_EQ(back.load_error, id.load_error);
    EXPECT_THROW(decode_identity(encode_identity(id).substr(0, 10)), std::runtime_error);
}

TEST(RankAgreement, IdenticalRanksAgree) {
    EXPECT_EQ(disagreement({identity("a"), identity("b"), identity("c")}), "");
}

TEST(RankAgreement, EachDifferenceNamesTheRankAndHost) {
    const auto problem_of_rank_2 = [](RankIdentity third) {
        return disagreement({identity("a"), identity("b"), std::move(third)});
    };
    RankIdentity failed = identity("node-3");
    failed.load_error = "cannot open scene.json";
    EXPECT_NE(problem_of_rank_2(failed).find("rank 2 (on node-3) could not load the scene: cannot open scene.json"),
              std::string::npos);
    RankIdentity version = identity("node-3");
    version.version = "1.2.4";
    EXPECT_NE(problem_of_rank_2(version).find("rank 2 (on node-3) runs isotrace 1.2.4"), std::string::npos);
    RankIdentity build = identity("node-3");
    build.binary = 0x9999;
    EXPECT_NE(problem_of_rank_2(build).find("another isotrace build"), std::string::npos);
    RankIdentity scene = identity("node-3");
    scene.scene = 0x9999;
    EXPECT_NE(problem_of_rank_2(scene).find("rank 2 (on node-3) loaded another scene"), std::string::npos);
}

TEST(RankAgreement, ThisRankKnowsItsBuildAndSaysWhyItHasNoScene) {
    const RankIdentity id = identify_this_rank(nullptr, "no scene");
    EXPECT_FALSE(id.host.empty());
    EXPECT_NE(id.binary, 0u);
    EXPECT_EQ(id.scene, 0u);
    EXPECT_EQ(id.load_error, "no scene");
    EXPECT_EQ(identify_this_rank(nullptr, "").binary, id.binary);
}

}  // namespace
}  // namespace isotrace
