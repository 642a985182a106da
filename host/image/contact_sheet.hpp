// Contact sheets: many rendered frames (a weather timeline, a backend comparison) laid
// out in one labelled picture. This is the image users look at first, so the layout
// favours legibility: a title bar, a regular grid, captions under every frame.
#pragma once
#include <string>
#include <vector>

#include "nodes/texture_image.hpp"
#include "host/image/text_overlay.hpp"

namespace wg::image {

// Neutral dark greys: frames read as they are, without a coloured surround biasing them.
inline constexpr Rgba8 kSheetBackground{32, 33, 36, 255};
inline constexpr Rgba8 kTitleBarColor{20, 21, 23, 255};
inline constexpr Rgba8 kFrameBorderColor{72, 74, 80, 255};
inline constexpr Rgba8 kTitleColor{245, 245, 245, 255};
inline constexpr Rgba8 kPrimaryLabelColor{235, 235, 235, 255};    // a frame's first line
inline constexpr Rgba8 kSecondaryLabelColor{170, 173, 180, 255};  // its other lines

inline constexpr int kStripGap = 4;         // between frames in frameStrip
inline constexpr int kSheetMargin = 16;     // around the grid and the title text
inline constexpr int kCellGap = 16;         // between grid cells, both directions
inline constexpr int kLabelGap = 8;         // from a frame's bottom edge to its first line
inline constexpr int kLabelLineGap = 4;     // between label lines
inline constexpr int kMaxTitleScale = 3;    // font scales tried, largest first, until the
inline constexpr int kMaxLabelScale = 2;    // text fits the width available

struct LabelledFrame {
  Image image;
  std::vector<std::string> lines;  // e.g. "t = 2.0 h", "T = -5.0 C  P = 0.8"
};

// Frames side by side, kStripGap pixels apart on the sheet background; the strip is as
// tall as the tallest frame and shorter ones are centred vertically. Invalid (empty)
// images are skipped; no valid frame gives an empty Image.
Image frameStrip(const std::vector<Image>& frames);

// Where contactSheet puts everything; exposed so callers and tests can find a frame.
struct ContactSheetLayout {
  int width = 0, height = 0;
  int columns = 0, rows = 0;
  int cellWidth = 0, cellHeight = 0;  // frame area plus label block
  int titleScale = 0, labelScale = 0;
  PixelRect titleBar;                 // empty when the title is
  std::vector<PixelRect> frames;      // per frame, its own size, top-left of its cell
  std::vector<PixelRect> labels;      // per frame, its label lines (empty if it has none)
};

// A frame's place on the sheet before it is rendered: its size (0 x 0 for none) and
// label lines. Lets a caller check the sheet's size before rendering anything.
struct SheetCell {
  int width = 0, height = 0;
  std::vector<std::string> lines;
};
ContactSheetLayout layoutContactSheet(const std::string& title, const std::vector<SheetCell>& cells, int columns);

// Columns are clamped to [1, frames.size()]. Cells are as wide as the widest frame
// (or its widest label, if a label does not fit even at scale 1) and as tall as the
// tallest frame plus the most label lines any frame has, so rows and columns line up.
ContactSheetLayout layoutContactSheet(const std::string& title, const std::vector<LabelledFrame>& frames,
                                      int columns);

// The sheet itself: title bar on top, frames row by row with a 1-pixel border and
// their label lines underneath. Frames are drawn opaque (their alpha is ignored).
Image contactSheet(const std::string& title, const std::vector<LabelledFrame>& frames, int columns);

}  // namespace wg::image
