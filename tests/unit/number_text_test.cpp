// Numbers typed on the command line follow the graphs' (JSON's) number rules exactly.
#include "cli/number_text.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace wg {
namespace {

TEST(NumberText, AcceptsJsonNumbers) {
  EXPECT_EQ(parseNumberText("0"), 0.0);
  EXPECT_EQ(parseNumberText("-1"), -1.0);
  EXPECT_EQ(parseNumberText("2.5"), 2.5);
  EXPECT_EQ(parseNumberText("-0.25e1"), -2.5);
  EXPECT_EQ(parseNumberText("1E+2"), 100.0);
  EXPECT_EQ(parseNumberText("1e-2"), 0.01);
}

TEST(NumberText, RejectsWhatGraphsReject) {
  for (const char* text : {"", "+1", "+-1", "-+1", "--1", "01", "-01", ".5", "1.", "1e", "1e+", "0x10", "inf", "-inf",
                           "nan", " 1", "1 ", "1junk", "1,5", "1.5.5", "\xef\xbc\x91"})
    EXPECT_FALSE(parseNumberText(text)) << "'" << text << "'";
}

TEST(NumberText, OverflowReadsAsInfiniteAndUnderflowAsZero) {
  EXPECT_TRUE(std::isinf(*parseNumberText("1e999")));
  EXPECT_LT(*parseNumberText("-1e999"), 0.0);
  EXPECT_EQ(*parseNumberText("1e-999"), 0.0);
}

TEST(NumberText, CountsAreDigitsWithinRangeNeverWrapped) {
  EXPECT_EQ(parseCountText("1", 1, 256), 1u);
  EXPECT_EQ(parseCountText("256", 1, 256), 256u);
  EXPECT_EQ(parseCountText("4294967295", 0, 4294967295u), 4294967295u);
  for (const char* text : {"0", "257", "-1", "+1", "01", "1.0", "1e2", "4294967297", "99999999999", "", " 1", "0x10"})
    EXPECT_FALSE(parseCountText(text, 1, 256)) << "'" << text << "'";
}

TEST(NumberText, PixelSizesAreTwoCountsAndNothingElse) {
  auto size = parsePixelSizeText("1920x1080", 8192);
  ASSERT_TRUE(size);
  EXPECT_EQ(size->width, 1920u);
  EXPECT_EQ(size->height, 1080u);
  for (const char* text : {"4294967297x1", "16x16junk", "16x", "x16", "16X16", "16x16x16", "0x16", "16x0",
                           "8193x1", "-16x16", "16 x 16", "16x+16"})
    EXPECT_FALSE(parsePixelSizeText(text, 8192)) << "'" << text << "'";
}

}  // namespace
}  // namespace wg
