#include "host/image/contact_sheet.hpp"

#include <algorithm>
#include <cstdint>
#include <cstring>

namespace wg::image {

namespace {

constexpr int kTitlePadding = 12;  // above and below the title text in its bar
constexpr int kBorderWidth = 1;    // outline that separates dark frames from the sheet

Image filledImage(int width, int height, Rgba8 color) {
  Image image = Image::blank(width, height);
  fillRect(image, {0, 0, width, height}, color);
  return image;
}

// Copies `src` into `dst` with its top-left at (x, y); the caller keeps it inside.
void blit(Image& dst, const Image& src, int x, int y) {
  const std::size_t rowBytes = static_cast<std::size_t>(src.width) * kImageChannels;
  for (int row = 0; row < src.height; ++row)
    std::memcpy(dst.rgba.data() + dst.texelOffset(x, y + row), src.rgba.data() + src.texelOffset(0, row),
                rowBytes);
}

int widestLine(const std::vector<SheetCell>& cells, int scale) {
  int widest = 0;
  for (const SheetCell& cell : cells)
    for (const std::string& line : cell.lines) widest = std::max(widest, textWidth(line, scale));
  return widest;
}

// The largest scale in [1, maxScale] at which `width(scale)` fits in `available`.
template <typename Width>
int fittingScale(int maxScale, int available, Width width) {
  for (int scale = maxScale; scale > 1; --scale)
    if (width(scale) <= available) return scale;
  return 1;
}

// Height of `lines` label lines, and of the space they take under a frame.
int labelTextHeight(int lines, int scale) {
  if (lines == 0) return 0;
  return lines * textHeight("", scale) + (lines - 1) * kLabelLineGap;
}
int labelBlockHeight(int lines, int scale) {
  return lines == 0 ? 0 : kLabelGap + labelTextHeight(lines, scale);
}

// Frames are shown opaque: a sheet is for looking at, and transparent pixels would
// take whatever colour the viewer puts behind them.
void blitOpaque(Image& dst, const Image& src, int x, int y) {
  constexpr std::uint8_t kOpaqueAlpha = 255;
  blit(dst, src, x, y);
  for (int row = 0; row < src.height; ++row)
    for (int column = 0; column < src.width; ++column)
      dst.rgba[dst.texelOffset(x + column, y + row) + 3] = kOpaqueAlpha;
}

}  // namespace

Image frameStrip(const std::vector<Image>& frames) {
  int width = 0, height = 0, count = 0;
  for (const Image& frame : frames) {
    if (!frame.valid()) continue;
    width += frame.width;
    height = std::max(height, frame.height);
    ++count;
  }
  if (count == 0) return {};
  Image strip = filledImage(width + (count - 1) * kStripGap, height, kSheetBackground);
  int x = 0;
  for (const Image& frame : frames) {
    if (!frame.valid()) continue;
    blit(strip, frame, x, (height - frame.height) / 2);
    x += frame.width + kStripGap;
  }
  return strip;
}

ContactSheetLayout layoutContactSheet(const std::string& title, const std::vector<SheetCell>& cells, int columns) {
  ContactSheetLayout layout;
  const int count = static_cast<int>(cells.size());
  layout.columns = std::clamp(columns, 1, std::max(count, 1));
  layout.rows = (count + layout.columns - 1) / layout.columns;

  int frameWidth = 0, frameHeight = 0;
  std::size_t maxLines = 0;
  for (const SheetCell& cell : cells) {
    frameWidth = std::max(frameWidth, cell.width);
    frameHeight = std::max(frameHeight, cell.height);
    maxLines = std::max(maxLines, cell.lines.size());
  }
  // Labels get the larger font when they fit under the frames; otherwise the small one,
  // widening the cells only if even that does not fit.
  layout.labelScale = fittingScale(kMaxLabelScale, frameWidth,
                                   [&](int scale) { return widestLine(cells, scale); });
  layout.cellWidth = std::max(frameWidth, widestLine(cells, layout.labelScale));
  layout.cellHeight = frameHeight + labelBlockHeight(static_cast<int>(maxLines), layout.labelScale);

  const int gridWidth = layout.columns * layout.cellWidth + (layout.columns - 1) * kCellGap;
  const int gridHeight = layout.rows * layout.cellHeight + std::max(layout.rows - 1, 0) * kCellGap;
  layout.width = std::max(gridWidth, textWidth(title, 1)) + 2 * kSheetMargin;

  int gridTop = kSheetMargin;
  if (!title.empty()) {
    layout.titleScale = fittingScale(kMaxTitleScale, layout.width - 2 * kSheetMargin,
                                     [&](int scale) { return textWidth(title, scale); });
    layout.titleBar = {0, 0, layout.width, textHeight(title, layout.titleScale) + 2 * kTitlePadding};
    gridTop += layout.titleBar.height;
  }
  layout.height = gridTop + gridHeight + kSheetMargin;

  for (int i = 0; i < count; ++i) {
    const int cellX = kSheetMargin + (i % layout.columns) * (layout.cellWidth + kCellGap);
    const int cellY = gridTop + (i / layout.columns) * (layout.cellHeight + kCellGap);
    layout.frames.push_back({cellX, cellY, cells[i].width, cells[i].height});
    const int lines = static_cast<int>(cells[i].lines.size());
    layout.labels.push_back({cellX, cellY + frameHeight + kLabelGap, layout.cellWidth,
                             labelTextHeight(lines, layout.labelScale)});
  }
  return layout;
}

ContactSheetLayout layoutContactSheet(const std::string& title, const std::vector<LabelledFrame>& frames,
                                      int columns) {
  std::vector<SheetCell> cells;
  for (const LabelledFrame& frame : frames) {
    const bool valid = frame.image.valid();
    cells.push_back({valid ? frame.image.width : 0, valid ? frame.image.height : 0, frame.lines});
  }
  return layoutContactSheet(title, cells, columns);
}

Image contactSheet(const std::string& title, const std::vector<LabelledFrame>& frames, int columns) {
  const ContactSheetLayout layout = layoutContactSheet(title, frames, columns);
  Image sheet = filledImage(layout.width, layout.height, kSheetBackground);

  if (!layout.titleBar.empty()) {
    fillRect(sheet, layout.titleBar, kTitleBarColor);
    drawText(sheet, kSheetMargin, kTitlePadding, title, {.scale = layout.titleScale, .color = kTitleColor});
  }
  const int lineAdvance = textHeight("", layout.labelScale) + kLabelLineGap;
  for (std::size_t i = 0; i < frames.size(); ++i) {
    const PixelRect& rect = layout.frames[i];
    if (!rect.empty()) {
      fillRect(sheet, {rect.x - kBorderWidth, rect.y - kBorderWidth, rect.width + 2 * kBorderWidth,
                       rect.height + 2 * kBorderWidth},
               kFrameBorderColor);
      blitOpaque(sheet, frames[i].image, rect.x, rect.y);
    }
    const PixelRect& labels = layout.labels[i];
    for (std::size_t line = 0; line < frames[i].lines.size(); ++line) {
      const Rgba8 color = line == 0 ? kPrimaryLabelColor : kSecondaryLabelColor;
      drawText(sheet, labels.x, labels.y + static_cast<int>(line) * lineAdvance, frames[i].lines[line],
               {.scale = layout.labelScale, .color = color});
    }
  }
  return sheet;
}

}  // namespace wg::image
