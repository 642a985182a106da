// Text drawn into images (titles and labels on contact sheets, captions on debug
// output) with stb_easy_font: a tiny built-in vector font, so no font file is needed.
#pragma once
#include <cstdint>
#include <string_view>

#include "nodes/texture_image.hpp"

namespace wg::image {

// An 8-bit straight-alpha colour; alpha below 255 blends "over" what is underneath.
struct Rgba8 {
  std::uint8_t r = 0, g = 0, b = 0, a = 255;
  bool operator==(const Rgba8&) const = default;
};

// A rectangle of pixels: columns [x, x + width), rows [y, y + height).
struct PixelRect {
  int x = 0, y = 0, width = 0, height = 0;
  bool empty() const { return width <= 0 || height <= 0; }
  bool contains(int px, int py) const {
    return px >= x && px < x + width && py >= y && py < y + height;
  }
  bool operator==(const PixelRect&) const = default;
};

// The font's own units: every glyph (descenders included) lies in a cell this many
// units tall, and a '\n' moves down kFontLineAdvance units. Multiplied by the scale.
inline constexpr int kFontGlyphHeight = 9;
inline constexpr int kFontLineAdvance = 12;

inline constexpr Rgba8 kDefaultTextColor{236, 236, 236, 255};
// Black at ~70%: keeps light text legible over snow and sky without hiding the image.
inline constexpr Rgba8 kDefaultBackingColor{0, 0, 0, 180};
// Backing-box margin around the glyphs, in font units (so it grows with the scale).
inline constexpr int kBackingPaddingUnits = 2;

struct TextStyle {
  int scale = 1;  // integer magnification of the font; values below 1 act as 1
  Rgba8 color = kDefaultTextColor;
  bool backing = false;  // draw a dark box behind the text first
  Rgba8 backingColor = kDefaultBackingColor;
};

// Width and height in pixels of `text` at `scale` (multi-line text: the widest line and
// all lines). The width includes the one-unit spacing after the last glyph.
int textWidth(std::string_view text, int scale);
int textHeight(std::string_view text, int scale);

// The rectangle drawText may change for this text at (x, y), before clipping: the
// glyph cells, grown by the backing padding when the style has a backing box.
PixelRect textBounds(int x, int y, std::string_view text, const TextStyle& style);

// Draws `text` with the top-left corner of its first glyph cell at (x, y). The font is
// ASCII only: other characters (each UTF-8 sequence as a whole) are drawn as '?', tabs
// as spaces. Everything is clipped to the image. Returns textBounds clipped to the
// image: no pixel outside it is changed.
PixelRect drawText(Image& image, int x, int y, std::string_view text, const TextStyle& style = {});

// Fills `rect` (clipped to the image) with `color`, blending when its alpha is below 255.
void fillRect(Image& image, const PixelRect& rect, Rgba8 color);

// `rect` restricted to the image's pixels (empty if they do not overlap).
PixelRect clipToImage(const Image& image, const PixelRect& rect);

}  // namespace wg::image
