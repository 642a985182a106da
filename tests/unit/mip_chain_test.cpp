// The textures' mip chains (host/image/mip_chain.hpp): full chains down to 1x1,
// sRGB averaged in linear light, other data averaged as stored.
#include <gtest/gtest.h>

#include "host/image/mip_chain.hpp"

namespace wg {
namespace {

Image checker(int width, int height, std::uint8_t dark, std::uint8_t light) {
  Image image = Image::blank(width, height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      std::uint8_t v = (x + y) % 2 ? light : dark;
      std::uint8_t* p = image.rgba.data() + image.texelOffset(x, y);
      p[0] = p[1] = p[2] = v;
      p[3] = 255;
    }
  return image;
}

TEST(MipChain, GoesDownToOneTexelHalvingEachAxis) {
  EXPECT_EQ(fullMipLevelCount(256, 256), 9u);
  EXPECT_EQ(fullMipLevelCount(300, 20), 9u);
  EXPECT_EQ(fullMipLevelCount(1, 1), 1u);
  const std::vector<Image> levels = mipLevelsBelow(checker(300, 20, 0, 255), true);
  ASSERT_EQ(levels.size(), 8u);
  EXPECT_EQ(levels[0].width, 150);
  EXPECT_EQ(levels[0].height, 10);
  EXPECT_EQ(levels[4].width, 9);
  EXPECT_EQ(levels[4].height, 1);  // the short axis stops at one texel
  EXPECT_EQ(levels.back().width, 1);
  EXPECT_EQ(levels.back().height, 1);
  for (const Image& level : levels) EXPECT_TRUE(level.valid());
  EXPECT_TRUE(mipLevelsBelow(Image::blank(1, 1), true).empty());
}

// Half black, half white is half the light: sRGB 188, not the 128 that averaging the
// encoded bytes gives (a chain averaged that way darkens textures with distance).
TEST(MipChain, SrgbIsAveragedInLinearLight) {
  const std::vector<Image> srgb = mipLevelsBelow(checker(4, 4, 0, 255), true);
  for (const Image& level : srgb) {
    EXPECT_NEAR(level.rgba[0], 188, 1);
    EXPECT_EQ(level.rgba[3], 255);  // alpha is linear
  }
  const std::vector<Image> data = mipLevelsBelow(checker(4, 4, 0, 255), false);
  for (const Image& level : data) EXPECT_NEAR(level.rgba[0], 128, 1);
}

// A flat texture stays exactly flat at every level, in both spaces.
TEST(MipChain, FlatTexturesKeepTheirValue) {
  for (bool srgb : {true, false})
    for (const Image& level : mipLevelsBelow(checker(6, 5, 77, 77), srgb))
      for (std::size_t i = 0; i < level.rgba.size(); i += 4) EXPECT_EQ(level.rgba[i], 77) << "srgb " << srgb;
}

}  // namespace
}  // namespace wg
