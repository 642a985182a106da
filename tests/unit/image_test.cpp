// Runtime image utilities: PNG files, text overlay, contact sheets, image comparison
// and reference-image tolerances.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

#include "host/image/contact_sheet.hpp"
#include "host/image/image_compare.hpp"
#include "host/image/png_file.hpp"
#include "host/image/reference_images.hpp"
#include "host/image/text_overlay.hpp"

namespace wg::image {
namespace {

namespace fs = std::filesystem;

constexpr double kExact = 1e-12;  // error statistics are ratios of small integers

Image solid(int width, int height, Rgba8 color) {
  Image image = Image::blank(width, height);
  fillRect(image, {0, 0, width, height}, color);
  return image;
}

Rgba8 pixelAt(const Image& image, int x, int y) {
  const std::uint8_t* p = image.rgba.data() + image.texelOffset(x, y);
  return {p[0], p[1], p[2], p[3]};
}

void setPixel(Image& image, int x, int y, Rgba8 color) { fillRect(image, {x, y, 1, 1}, color); }

// A small image with distinct values everywhere, so a transposed or shifted copy shows.
Image gradient(int width, int height) {
  Image image = Image::blank(width, height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      setPixel(image, x, y,
               {static_cast<std::uint8_t>(x * 7), static_cast<std::uint8_t>(y * 11),
                static_cast<std::uint8_t>((x + y) * 3), static_cast<std::uint8_t>(200 + x % 50)});
  return image;
}

bool anyPixelDiffers(const Image& image, const PixelRect& rect, Rgba8 background) {
  for (int y = rect.y; y < rect.y + rect.height; ++y)
    for (int x = rect.x; x < rect.x + rect.width; ++x)
      if (!(pixelAt(image, x, y) == background)) return true;
  return false;
}

class ImageFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() / ("wg_image_test_" + std::to_string(::getpid()) + "_" + info->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  std::vector<std::string> entries() const {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(dir_)) names.push_back(entry.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
  }
  fs::path dir_;
};

// --- PNG files ---------------------------------------------------------------------

TEST_F(ImageFiles, PngRoundTripIsExactAndLeavesNoTemporary) {
  const Image image = gradient(13, 7);
  ASSERT_EQ(writePng(path("frame.png"), image), "");
  EXPECT_EQ(entries(), std::vector<std::string>{"frame.png"});

  std::string error;
  std::optional<Image> read = readPng(path("frame.png"), error);
  ASSERT_TRUE(read) << error;
  EXPECT_EQ(read->width, image.width);
  EXPECT_EQ(read->height, image.height);
  EXPECT_EQ(read->rgba, image.rgba);
}

TEST_F(ImageFiles, PngOverwriteReplacesTheWholeFile) {
  ASSERT_EQ(writePng(path("frame.png"), gradient(32, 32)), "");
  const Image smaller = solid(3, 2, {1, 2, 3, 255});
  ASSERT_EQ(writePng(path("frame.png"), smaller), "");
  std::string error;
  std::optional<Image> read = readPng(path("frame.png"), error);
  ASSERT_TRUE(read) << error;
  EXPECT_EQ(read->rgba, smaller.rgba);
  EXPECT_EQ(entries(), std::vector<std::string>{"frame.png"});
}

TEST_F(ImageFiles, FailedPngWriteLeavesNothingBehind) {
  // The rename cannot replace a directory: the encoded temporary must be cleaned up.
  fs::create_directories(dir_ / "taken.png");
  const std::string error = writePng(path("taken.png"), gradient(4, 4));
  EXPECT_NE(error, "");
  EXPECT_NE(error.find("taken.png"), std::string::npos) << error;
  EXPECT_EQ(entries(), std::vector<std::string>{"taken.png"});
  EXPECT_TRUE(fs::is_directory(dir_ / "taken.png"));

  EXPECT_NE(writePng(path("missing-dir/frame.png"), gradient(4, 4)), "");
  EXPECT_NE(writePng(path("empty.png"), Image{}), "");
  EXPECT_EQ(entries(), std::vector<std::string>{"taken.png"});
}

TEST_F(ImageFiles, ReadPngReportsMissingAndNonPngFiles) {
  std::string error;
  EXPECT_FALSE(readPng(path("absent.png"), error));
  EXPECT_NE(error.find("absent.png"), std::string::npos) << error;
  EXPECT_NE(error.find("not found"), std::string::npos) << error;

  std::ofstream(path("text.png")) << "definitely not a PNG";
  EXPECT_FALSE(readPng(path("text.png"), error));
  EXPECT_NE(error.find("not a PNG"), std::string::npos) << error;
}

// --- Text overlay --------------------------------------------------------------------

constexpr Rgba8 kGrey{90, 100, 110, 255};

TEST(TextOverlay, WidthScalesWithTheFontAndNonAsciiIsOneGlyph) {
  EXPECT_EQ(textWidth("A", 1), 6);  // stb_easy_font's advance for capitals
  EXPECT_EQ(textWidth("t = 2.0 h", 3), 3 * textWidth("t = 2.0 h", 1));
  EXPECT_EQ(textWidth("", 2), 0);
  EXPECT_EQ(textWidth("-5 \xC2\xB0" "C", 1), textWidth("-5 ?C", 1));  // "°" is one '?'
  EXPECT_EQ(textWidth("ab\nabcd", 1), textWidth("abcd", 1));
  EXPECT_EQ(textHeight("x", 2), kFontGlyphHeight * 2);
  EXPECT_EQ(textHeight("x\ny", 1), kFontLineAdvance + kFontGlyphHeight);
  EXPECT_EQ(textWidth("A", 0), textWidth("A", 1));  // scales below 1 act as 1
}

TEST(TextOverlay, ChangesPixelsInsideTheTextBoxOnly) {
  for (bool backing : {false, true}) {
    SCOPED_TRACE(backing ? "with backing box" : "plain");
    const Image before = solid(128, 40, kGrey);  // the whole box fits
    Image image = before;
    const TextStyle style{.scale = 2, .color = {255, 255, 0, 255}, .backing = backing};
    const PixelRect box = drawText(image, 10, 12, "Snow 42", style);
    EXPECT_EQ(box, textBounds(10, 12, "Snow 42", style));
    int changed = 0;
    for (int y = 0; y < image.height; ++y)
      for (int x = 0; x < image.width; ++x)
        if (!(pixelAt(image, x, y) == pixelAt(before, x, y))) {
          ++changed;
          EXPECT_TRUE(box.contains(x, y)) << "pixel (" << x << ", " << y << ") outside the text box";
        }
    EXPECT_GT(changed, 40);
    // Glyph pixels are exactly the text colour; with a backing, the box corner is darker.
    bool sawTextColor = false;
    for (int y = box.y; y < box.y + box.height; ++y)
      for (int x = box.x; x < box.x + box.width; ++x) sawTextColor |= pixelAt(image, x, y) == style.color;
    EXPECT_TRUE(sawTextColor);
    if (backing) {
      EXPECT_LT(pixelAt(image, box.x, box.y).r, kGrey.r);
    }
  }
}

TEST(TextOverlay, TranslucentTextBlendsOncePerPixel) {
  // Glyph segments overlap where strokes meet ("+" and "#" cross); each pixel is still
  // blended exactly once, so all ink has one value.
  Image image = solid(64, 24, {0, 0, 0, 255});
  drawText(image, 2, 2, "+#HT", {.scale = 2, .color = {255, 255, 255, 128}});
  std::vector<std::uint8_t> inks;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x)
      if (pixelAt(image, x, y).r != 0) inks.push_back(pixelAt(image, x, y).r);
  ASSERT_FALSE(inks.empty());
  EXPECT_EQ(std::count(inks.begin(), inks.end(), 128), static_cast<long>(inks.size()));
}

TEST(TextOverlay, ClipsAtTheImageEdges) {
  const Image before = solid(20, 10, kGrey);
  Image image = before;
  const PixelRect box = drawText(image, -7, -3, "WWWWWWWW", {.scale = 2, .backing = true});
  EXPECT_EQ(box, (PixelRect{0, 0, 20, 10}));
  EXPECT_NE(image.rgba, before.rgba);
  EXPECT_TRUE(drawText(image, 100, 100, "far away").empty());
}

// --- Contact sheets ------------------------------------------------------------------

std::vector<LabelledFrame> labelledFrames(int count, int width, int height) {
  std::vector<LabelledFrame> frames;
  for (int i = 0; i < count; ++i)
    frames.push_back({solid(width, height, {static_cast<std::uint8_t>(40 * i + 20), 150, 200, 255}),
                      {"t = " + std::to_string(i) + ".0 h", "T = -5.0 C  P = 0.8"}});
  return frames;
}

TEST(ContactSheet, FrameStripPlacesFramesSideBySide) {
  const Image strip = frameStrip({solid(10, 8, {255, 0, 0, 255}), solid(6, 8, {0, 255, 0, 255}),
                                  solid(4, 8, {0, 0, 255, 255})});
  EXPECT_EQ(strip.width, 10 + 6 + 4 + 2 * kStripGap);
  EXPECT_EQ(strip.height, 8);
  EXPECT_EQ(pixelAt(strip, 9, 7), (Rgba8{255, 0, 0, 255}));
  EXPECT_EQ(pixelAt(strip, 10, 0), kSheetBackground);
  EXPECT_EQ(pixelAt(strip, 10 + kStripGap, 0), (Rgba8{0, 255, 0, 255}));
  EXPECT_EQ(pixelAt(strip, strip.width - 1, 3), (Rgba8{0, 0, 255, 255}));
  EXPECT_FALSE(frameStrip({}).valid());
}

TEST(ContactSheet, DimensionsFollowFramesAndColumns) {
  constexpr int kFrameWidth = 256, kFrameHeight = 144;
  for (auto [count, columns, expectedColumns, expectedRows] :
       std::vector<std::array<int, 4>>{{5, 3, 3, 2}, {6, 3, 3, 2}, {7, 3, 3, 3}, {1, 4, 1, 1}, {4, 0, 1, 4}}) {
    SCOPED_TRACE(std::to_string(count) + " frames, " + std::to_string(columns) + " columns");
    const auto frames = labelledFrames(count, kFrameWidth, kFrameHeight);
    const ContactSheetLayout layout = layoutContactSheet("valley-snowfall", frames, columns);
    EXPECT_EQ(layout.columns, expectedColumns);
    EXPECT_EQ(layout.rows, expectedRows);
    EXPECT_EQ(layout.labelScale, kMaxLabelScale);  // the labels fit under 256-pixel frames
    EXPECT_EQ(layout.cellWidth, kFrameWidth);
    EXPECT_GT(layout.cellHeight, kFrameHeight + 2 * textHeight("", layout.labelScale));
    EXPECT_EQ(layout.width, 2 * kSheetMargin + expectedColumns * kFrameWidth + (expectedColumns - 1) * kCellGap);
    EXPECT_EQ(layout.height, layout.titleBar.height + 2 * kSheetMargin + expectedRows * layout.cellHeight +
                                 (expectedRows - 1) * kCellGap);
    const Image sheet = contactSheet("valley-snowfall", frames, columns);
    EXPECT_EQ(sheet.width, layout.width);
    EXPECT_EQ(sheet.height, layout.height);
    ASSERT_EQ(layout.frames.size(), frames.size());
    for (std::size_t i = 0; i < frames.size(); ++i) {
      const PixelRect& rect = layout.frames[i];
      EXPECT_EQ(rect.width, kFrameWidth);
      EXPECT_EQ(pixelAt(sheet, rect.x, rect.y), pixelAt(frames[i].image, 0, 0));
      EXPECT_EQ(pixelAt(sheet, rect.x + rect.width - 1, rect.y + rect.height - 1), pixelAt(frames[i].image, 0, 0));
    }
  }
}

// The CLI sizes a timeline's sheet from cells before rendering anything; the layout
// must be the one the rendered frames get.
TEST(ContactSheet, CellsWithoutPixelsLayOutAsTheRenderedFrames) {
  const auto frames = labelledFrames(7, 96, 64);
  std::vector<SheetCell> cells;
  for (const auto& frame : frames) cells.push_back({frame.image.width, frame.image.height, frame.lines});
  const ContactSheetLayout fromFrames = layoutContactSheet("timeline", frames, 3);
  const ContactSheetLayout fromCells = layoutContactSheet("timeline", cells, 3);
  EXPECT_EQ(fromCells.width, fromFrames.width);
  EXPECT_EQ(fromCells.height, fromFrames.height);
  EXPECT_EQ(fromCells.labelScale, fromFrames.labelScale);
  ASSERT_EQ(fromCells.frames.size(), fromFrames.frames.size());
  for (std::size_t i = 0; i < frames.size(); ++i) {
    EXPECT_EQ(fromCells.frames[i].x, fromFrames.frames[i].x);
    EXPECT_EQ(fromCells.frames[i].y, fromFrames.frames[i].y);
    EXPECT_EQ(fromCells.labels[i].y, fromFrames.labels[i].y);
  }
  EXPECT_EQ(contactSheet("timeline", frames, 3).height, fromCells.height);
}

TEST(ContactSheet, TitleAndLabelsAreDrawn) {
  const auto frames = labelledFrames(5, 128, 96);
  const ContactSheetLayout layout = layoutContactSheet("Weather timeline", frames, 3);
  const Image sheet = contactSheet("Weather timeline", frames, 3);
  EXPECT_TRUE(anyPixelDiffers(sheet, layout.titleBar, kTitleBarColor));
  for (std::size_t i = 0; i < frames.size(); ++i) {
    SCOPED_TRACE("frame " + std::to_string(i));
    const PixelRect& frame = layout.frames[i];
    const PixelRect& labels = layout.labels[i];
    EXPECT_GE(labels.y, frame.y + frame.height);  // under the frame
    EXPECT_TRUE(anyPixelDiffers(sheet, labels, kSheetBackground));
    // Each of the two lines has its own ink.
    const int lineHeight = textHeight("", layout.labelScale);
    EXPECT_TRUE(anyPixelDiffers(sheet, {labels.x, labels.y, labels.width, lineHeight}, kSheetBackground));
    EXPECT_TRUE(anyPixelDiffers(
        sheet, {labels.x, labels.y + labels.height - lineHeight, labels.width, lineHeight}, kSheetBackground));
  }
}

TEST(ContactSheet, LongLabelsUseTheSmallFontThenWidenCells) {
  std::vector<LabelledFrame> frames = {{solid(64, 64, kGrey), {"a label much wider than sixty-four pixels"}}};
  const ContactSheetLayout layout = layoutContactSheet("", frames, 1);
  EXPECT_EQ(layout.labelScale, 1);
  EXPECT_EQ(layout.cellWidth, textWidth(frames[0].lines[0], 1));
  EXPECT_TRUE(layout.titleBar.empty());
  EXPECT_EQ(layout.frames[0].y, kSheetMargin);
}

// --- Comparison ------------------------------------------------------------------------

TEST(ImageCompare, IdenticalImagesHaveNoError) {
  const Image image = gradient(9, 5);
  const ImageDifference d = compareImages(image, image, 0.0);
  EXPECT_EQ(d.maxError, 0.0);
  EXPECT_EQ(d.meanError, 0.0);
  EXPECT_EQ(d.pixelsOverThreshold, 0u);
  EXPECT_FALSE(d.sizeMismatch);
}

TEST(ImageCompare, OnePixelChangeGivesExactStatistics) {
  const Image a = solid(4, 4, {100, 100, 100, 255});
  Image b = a;
  setPixel(b, 1, 2, {151, 202, 100, 255});  // R +51, G +102: the pixel's error is 102/255
  setPixel(b, 3, 3, {100, 100, 100, 0});    // alpha alone is not compared
  const ImageDifference d = compareImages(a, b, 0.3);
  EXPECT_NEAR(d.maxError, 0.4, kExact);
  EXPECT_NEAR(d.meanError, 0.4 / 16, kExact);
  EXPECT_EQ(d.pixelsOverThreshold, 1u);
  EXPECT_EQ(compareImages(a, b, 0.4).pixelsOverThreshold, 0u);  // "over" is strict
  EXPECT_EQ(compareImages(b, a, 0.3).maxError, d.maxError);     // symmetric

  const Image diff = differenceImage(a, b);
  EXPECT_EQ(pixelAt(diff, 0, 0), (Rgba8{0, 0, 0, 255}));
  EXPECT_EQ(pixelAt(diff, 1, 2), (Rgba8{255, 255, 0, 255}));  // 51 and 102 amplified, clamped
  EXPECT_EQ(pixelAt(diff, 3, 3), (Rgba8{0, 0, 0, 255}));
  Image c = a;
  setPixel(c, 0, 0, {101, 100, 100, 255});
  EXPECT_EQ(pixelAt(differenceImage(a, c), 0, 0).r, kDifferenceGain);
}

TEST(ImageCompare, SizeMismatchIsTheWorstDifference) {
  const Image a = solid(4, 4, kGrey);
  const Image b = solid(4, 3, kGrey);
  const ImageDifference d = compareImages(a, b, 0.5);
  EXPECT_TRUE(d.sizeMismatch);
  EXPECT_EQ(d.maxError, 1.0);
  EXPECT_EQ(d.meanError, 1.0);
  EXPECT_EQ(d.pixelsOverThreshold, 16u);
  EXPECT_TRUE(compareImages(a, Image{}, 0.5).sizeMismatch);

  const Image diff = differenceImage(a, b);
  EXPECT_EQ(diff.width, 4);
  EXPECT_EQ(diff.height, 4);
  EXPECT_EQ(pixelAt(diff, 0, 0), (Rgba8{0, 0, 0, 255}));
  EXPECT_EQ(pixelAt(diff, 2, 3), (Rgba8{kMismatchRgb[0], kMismatchRgb[1], kMismatchRgb[2], 255}));
}

TEST(ImageCompare, DownsampleAveragesBlocks) {
  Image image = Image::blank(4, 2);
  // Left 2x2 block: R = 0, 10, 20, 31 -> mean 15.25 -> 15; right block: all 200.
  setPixel(image, 0, 0, {0, 0, 0, 255});
  setPixel(image, 1, 0, {10, 1, 0, 255});
  setPixel(image, 0, 1, {20, 1, 0, 255});
  setPixel(image, 1, 1, {31, 0, 255, 255});
  fillRect(image, {2, 0, 2, 2}, {200, 200, 200, 255});
  std::optional<Image> small = downsample(image, 2);
  ASSERT_TRUE(small);
  EXPECT_EQ(small->width, 2);
  EXPECT_EQ(small->height, 1);
  EXPECT_EQ(pixelAt(*small, 0, 0), (Rgba8{15, 1, 64, 255}));  // G 0.5 and B 63.75 round to nearest
  EXPECT_EQ(pixelAt(*small, 1, 0), (Rgba8{200, 200, 200, 255}));

  EXPECT_EQ(downsample(image, 1)->rgba, image.rgba);
  EXPECT_FALSE(downsample(image, 0));
  EXPECT_FALSE(downsample(image, 3));  // 4x2 is not a multiple of 3
  EXPECT_FALSE(downsample(Image{}, 2));
}

// --- Reference images ------------------------------------------------------------------

constexpr const char* kToleranceJson = R"({
  "_comment": "test table",
  "default": {"maxError": 0.25, "meanError": 0.02},
  "images": {
    "valley-snowfall-glsl": {"maxError": 0.3, "meanError": 0.03},
    "valley-rain-hlsl": {"meanError": 0.05, "_comment": "inherits maxError"}
  }
})";

TEST(ReferenceImages, ToleranceTableParsesAndLooksUp) {
  std::string error;
  std::optional<ToleranceTable> table = parseToleranceTable("tolerances.json", kToleranceJson, error);
  ASSERT_TRUE(table) << error;
  EXPECT_EQ(table->defaults, (Tolerance{0.25, 0.02}));
  EXPECT_EQ(table->lookup("valley-snowfall-glsl"), (Tolerance{0.3, 0.03}));
  EXPECT_EQ(table->lookup("valley-rain-hlsl"), (Tolerance{0.25, 0.05}));
  EXPECT_EQ(table->lookup("not-listed"), table->defaults);
  EXPECT_EQ(table->perImage.size(), 2u);
}

TEST(ReferenceImages, CheckedInToleranceFileParses) {
  std::string error;
  std::optional<ToleranceTable> table =
      loadToleranceTable(std::string(WG_SOURCE_DIR) + "/" + std::string(kToleranceFile), error);
  ASSERT_TRUE(table) << error;
  EXPECT_EQ(table->defaults, (Tolerance{0.25, 0.01}));
}

TEST(ReferenceImages, ToleranceErrorsNameTheJsonPointer) {
  struct Case {
    const char* json;
    const char* expected;  // a substring of the error
  };
  const std::vector<Case> cases = {
      {R"({"default": {"maxError": 0.25, "meanError": 0.02},
           "images": {"valley/snow": {"maxError": "high"}}})",
       "tolerances.json:2:51: /images/valley~1snow/maxError: expected a number in [0, 1], got \"high\""},
      {R"({"default": {"maxError": 1.5, "meanError": 0.02}})", "/default/maxError: expected a number in [0, 1]"},
      {R"({"default": {"maxError": 0.25, "meanErorr": 0.02}})",
       "/default/meanErorr: unknown field 'meanErorr'; did you mean 'meanError'?"},
      {R"({"default": {"maxError": 0.25}})", "/default: missing field 'meanError'"},
      {R"({"images": {}})", "(document root): missing field 'default'"},
      {R"({"default": {"maxError": 0.25, "meanError": 0.02}, "images": []})",
       "/images: expected an object, got array"},
      {R"({"default": {"maxError": 0.25, "meanError": 0.02},
  "images": {"a": {"maxError": 0.1}, "a": {"maxError": 0.2}}})",
       "tolerances.json:2:"},  // duplicate key, located by the JSON document parser
      {"{\"default\": {\"maxError\": 0.25,,}}", "tolerances.json:1:"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.json);
    std::string error;
    EXPECT_FALSE(parseToleranceTable("tolerances.json", c.json, error));
    EXPECT_NE(error.find(c.expected), std::string::npos) << error;
  }
}

TEST_F(ImageFiles, ReferenceCheckPassesWithinToleranceAndFailsOutside) {
  const Image reference = solid(8, 8, {100, 120, 140, 255});
  ASSERT_EQ(writePng(path("ref.png"), reference), "");
  const Tolerance tolerance{0.25, 0.01};

  ReferenceCheck same = checkAgainstReference(reference, path("ref.png"), tolerance);
  EXPECT_TRUE(same.passed) << same.message;
  EXPECT_EQ(same.difference.maxError, 0.0);
  EXPECT_EQ(same.tolerance, tolerance);

  Image close = reference;
  setPixel(close, 3, 3, {110, 120, 140, 255});  // max 10/255, mean 10/255/64
  ReferenceCheck near = checkAgainstReference(close, path("ref.png"), tolerance);
  EXPECT_TRUE(near.passed) << near.message;

  Image far = reference;
  setPixel(far, 3, 3, {255, 120, 140, 255});  // max 155/255 > 0.25
  ReferenceCheck failed = checkAgainstReference(far, path("ref.png"), tolerance);
  EXPECT_FALSE(failed.passed);
  EXPECT_EQ(failed.difference.pixelsOverThreshold, 1u);
  EXPECT_NE(failed.message.find("max error 0.6078 > 0.25"), std::string::npos) << failed.message;
  EXPECT_NE(failed.message.find(kUpdateReferenceCommand), std::string::npos) << failed.message;

  Image tinted = solid(8, 8, {104, 124, 144, 255});  // every pixel 4/255 off: mean > 0.01
  ReferenceCheck meanFailed = checkAgainstReference(tinted, path("ref.png"), tolerance);
  EXPECT_FALSE(meanFailed.passed);
  EXPECT_NE(meanFailed.message.find("mean error 0.01569 > 0.01"), std::string::npos) << meanFailed.message;

  ReferenceCheck resized = checkAgainstReference(solid(4, 4, kGrey), path("ref.png"), tolerance);
  EXPECT_FALSE(resized.passed);
  EXPECT_TRUE(resized.difference.sizeMismatch);
  EXPECT_NE(resized.message.find("4x4"), std::string::npos) << resized.message;
}

TEST_F(ImageFiles, MissingReferenceNamesTheRegenerateCommand) {
  ReferenceCheck check = checkAgainstReference(solid(4, 4, kGrey), path("absent.png"), {0.25, 0.01});
  EXPECT_FALSE(check.passed);
  EXPECT_NE(check.message.find("absent.png"), std::string::npos) << check.message;
  EXPECT_NE(check.message.find("scripts/update-reference-images.sh"), std::string::npos) << check.message;

  std::ofstream(path("corrupt.png")) << "not an image";
  check = checkAgainstReference(solid(4, 4, kGrey), path("corrupt.png"), {0.25, 0.01});
  EXPECT_FALSE(check.passed);
  EXPECT_NE(check.message.find("scripts/update-reference-images.sh"), std::string::npos) << check.message;
}

}  // namespace
}  // namespace wg::image
