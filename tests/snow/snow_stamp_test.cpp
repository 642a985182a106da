// Stamp shapes: oriented footprints with heel and toe and a raised rim, capsules, and
// the depth limit of the local snow.
#include "snow/snow_stamp.hpp"

#include <gtest/gtest.h>

#include "snow/deformation_texel.hpp"

namespace wg::snow {
namespace {

const SnowCover kDeep{0.3f};
const FootShape kFoot;

TEST(SnowStamp, FootprintIsDeeperAtTheHeelThanAtTheToe) {
  glm::vec2 heading(0.f, 1.f);
  Stamp s = footprint({0.f, 0.f}, heading, kFoot, kDeep, 0.1f);
  float heel = stampProfile(s, heading * (-0.5f * kFoot.length + kFoot.heelRadius)).depth;
  float toe = stampProfile(s, heading * (0.5f * kFoot.length - kFoot.toeRadius)).depth;
  EXPECT_NEAR(heel, 0.1f, 1e-5f);
  EXPECT_NEAR(toe, 0.1f * kFoot.toeDepthFraction, 1e-5f);
  // Heel and toe ends lie on the length, not across it.
  EXPECT_GT(stampProfile(s, heading * 0.13f).depth, 0.f);
  EXPECT_EQ(stampProfile(s, glm::vec2(0.13f, 0.f)).depth, 0.f);
}

// A boot sole: the arch carries less weight than heel and ball, so it is shallower,
// and the sole is narrower there (its waist) than across the heel or the ball.
TEST(SnowStamp, FootprintIsShallowAndNarrowAtTheArch) {
  Stamp s = footprint({0.f, 0.f}, {0.f, 1.f}, kFoot, kDeep, 0.1f);
  float heelY = -0.5f * kFoot.length + kFoot.heelRadius, toeY = 0.5f * kFoot.length - kFoot.toeRadius;
  float archY = 0.5f * (heelY + toeY);
  auto depth = [&](float x, float y) { return stampProfile(s, {x, y}).depth; };
  EXPECT_NEAR(depth(0.f, archY), 0.1f * kFoot.archDepthFraction, 1e-5f);
  EXPECT_LT(depth(0.f, archY), 0.7f * depth(0.f, heelY));
  EXPECT_LT(depth(0.f, archY), 0.7f * depth(0.f, toeY));
  auto width = [&](float y) {
    int mm = 0;
    for (int x = -100; x <= 100; ++x) mm += depth(0.001f * float(x), y) > 0.f;
    return 0.001f * float(mm);
  };
  EXPECT_NEAR(width(heelY), 2.f * kFoot.heelRadius, 0.003f);
  EXPECT_NEAR(width(archY), 2.f * kFoot.waist, 0.003f);
  EXPECT_NEAR(width(toeY), 2.f * kFoot.toeRadius, 0.003f);
  // A capsule has no waist: as deep and as wide in its middle as at its ends.
  Stamp c = capsule({0.f, -0.1f}, {0.f, 0.1f}, 0.05f, kDeep, 0.1f);
  EXPECT_NEAR(stampProfile(c, {0.f, 0.f}).depth, 0.1f, 1e-5f);
  EXPECT_GT(stampProfile(c, {0.045f, 0.f}).depth, 0.f);
}

TEST(SnowStamp, FootprintTurnsWithTheHeading) {
  glm::vec2 east(1.f, 0.f), north(0.f, 1.f);
  Stamp a = footprint({2.f, 3.f}, north, kFoot, kDeep, 0.1f);
  Stamp b = footprint({2.f, 3.f}, east, kFoot, kDeep, 0.1f);
  for (float along : {-0.12f, -0.05f, 0.f, 0.06f, 0.12f})
    for (float across : {-0.05f, 0.f, 0.04f})
      EXPECT_NEAR(stampProfile(a, glm::vec2(2.f - across, 3.f + along)).depth,
                  stampProfile(b, glm::vec2(2.f + along, 3.f + across)).depth, 1e-5f);
}

TEST(SnowStamp, RimRisesJustOutsideThePrintOnly) {
  Stamp s = footprint({0.f, 0.f}, {0.f, 1.f}, kFoot, kDeep, 0.1f);
  float side = kFoot.toeRadius + 0.5f * s.rimWidth;  // mid-rim, beside the toe
  glm::vec2 mid(side, 0.5f * kFoot.length - kFoot.toeRadius);
  StampProfile rim = stampProfile(s, mid);
  EXPECT_EQ(rim.depth, 0.f);
  EXPECT_NEAR(rim.rim, s.rimHeight, 1e-5f);
  EXPECT_NEAR(s.rimHeight, kRimHeightFraction * 0.1f, 1e-6f);
  EXPECT_EQ(stampProfile(s, {side + s.rimWidth, 0.f}).rim, 0.f);
  EXPECT_EQ(stampProfile(s, {0.f, 0.f}).rim, 0.f);
}

TEST(SnowStamp, DepthIsLimitedByTheLocalSnow) {
  EXPECT_NEAR(deepestPrint({0.09f}), 0.06f, 1e-6f);  // two thirds: packed to 3x density
  Stamp shallow = footprint({0.f, 0.f}, {0.f, 1.f}, kFoot, {0.03f}, 0.1f);
  EXPECT_NEAR(shallow.depthA, 0.02f, 1e-6f);
  Stamp none = capsule({0.f, 0.f}, {1.f, 0.f}, 0.1f, {0.f}, 0.5f);
  EXPECT_EQ(none.depthA, 0.f);
  EXPECT_EQ(none.rimHeight, 0.f);
  EXPECT_EQ(packTexel(stampProfile(none, {0.5f, 0.f}).depth, stampProfile(none, {0.5f, 0.f}).rim), 0u);
}

TEST(SnowStamp, CapsuleCoversItsWholeSegment) {
  Stamp s = capsule({-1.f, 0.f}, {1.f, 0.f}, 0.1f, kDeep, 0.1f);
  for (float x = -1.f; x <= 1.f; x += 0.05f) EXPECT_NEAR(stampProfile(s, {x, 0.f}).depth, 0.1f, 1e-5f) << x;
  EXPECT_EQ(stampProfile(s, {0.f, 0.1f + s.rimWidth}).depth, 0.f);
  // A body standing still stamps a disc.
  Stamp still = capsule({3.f, 3.f}, {3.f, 3.f}, 0.1f, kDeep, 0.1f);
  EXPECT_NEAR(stampProfile(still, {3.f, 3.f}).depth, 0.1f, 1e-5f);
  EXPECT_EQ(stampProfile(still, {3.2f, 3.f}).depth, 0.f);
}

TEST(SnowStamp, BoundsHoldEveryTouchedTexel) {
  SnowWindow w({128, 0.04f, 16});
  w.setOrigin(w.originFor({0.f, 0.f}));
  Stamp s = footprint({0.3f, -0.2f}, {1.f, 1.f}, kFoot, kDeep, 0.1f);
  TexelRect box = stampBounds(s, w);
  for (int z = w.origin().y; z < w.origin().y + 128; ++z)
    for (int x = w.origin().x; x < w.origin().x + 128; ++x) {
      StampProfile p = stampProfile(s, w.texelCentre({x, z}));
      if (p.depth > 0.f || p.rim > 0.f) {
        EXPECT_TRUE(box.contains({x, z})) << x << "," << z;
      }
    }
}

TEST(DeformationTexel, MaxMergesDeeperPrintsAndHigherRims) {
  std::uint32_t print = packTexel(0.05f, 0.f), deeper = packTexel(0.08f, 0.f), rim = packTexel(0.f, 0.01f);
  EXPECT_EQ(std::max(print, deeper), deeper);
  EXPECT_EQ(std::max(print, rim), print);  // a print flattens a rim
  EXPECT_NEAR(texelHeight(print), -0.05f, kDepthQuantum);
  EXPECT_NEAR(texelHeight(rim), 0.01f, kDepthQuantum);
  EXPECT_EQ(refillTexel(packTexel(0.05f, 0.f), toQuanta(0.02f)), packTexel(0.03f, 0.f));
  EXPECT_EQ(refillTexel(packTexel(0.01f, 0.002f), toQuanta(0.02f)), 0u);
}

}  // namespace
}  // namespace wg::snow
