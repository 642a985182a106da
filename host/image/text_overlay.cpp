#include "host/image/text_overlay.hpp"

// stb_easy_font defines everything static, so this is the one file that includes it;
// the helpers this file does not call would otherwise warn.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#include <stb_easy_font.h>
#pragma GCC diagnostic pop

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>
#include <utility>
#include <vector>

namespace wg::image {

namespace {

constexpr char kFirstPrintable = ' ';   // stb_easy_font covers ' '..'~'
constexpr char kLastPrintable = '~';
constexpr char kReplacement = '?';
constexpr int kVerticesPerQuad = 4;
constexpr int kBytesPerVertex = 16;      // x, y, z floats + RGBA8 colour
constexpr int kBytesPerQuad = kVerticesPerQuad * kBytesPerVertex;
constexpr int kMaxQuadsPerGlyph = 16;    // the densest glyph has 11 segments
constexpr int kOpaque = 255;

bool isUtf8Continuation(unsigned char c) { return (c & 0xC0) == 0x80; }

// Maps `text` onto the characters the font has, so stb_easy_font never indexes past
// its tables.
std::string printable(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (char ch : text) {
    const auto c = static_cast<unsigned char>(ch);
    if (ch == '\n') out += '\n';
    else if (ch == '\t') out += ' ';
    else if (ch == '\r' || isUtf8Continuation(c)) continue;  // one '?' per UTF-8 sequence
    else if (ch >= kFirstPrintable && ch <= kLastPrintable) out += ch;
    else out += kReplacement;
  }
  return out;
}

int effectiveScale(int scale) { return std::max(scale, 1); }

int lineCount(const std::string& text) {
  return 1 + static_cast<int>(std::count(text.begin(), text.end(), '\n'));
}

std::uint8_t blendChannel(std::uint8_t src, std::uint8_t dst, int alpha) {
  // Rounded integer "over": src*a + dst*(1-a), a in [0, 255].
  return static_cast<std::uint8_t>((src * alpha + dst * (kOpaque - alpha) + kOpaque / 2) / kOpaque);
}

void blendPixel(Image& image, int x, int y, Rgba8 color) {
  std::uint8_t* p = image.rgba.data() + image.texelOffset(x, y);
  if (color.a == kOpaque) {
    p[0] = color.r, p[1] = color.g, p[2] = color.b, p[3] = color.a;
    return;
  }
  p[0] = blendChannel(color.r, p[0], color.a);
  p[1] = blendChannel(color.g, p[1], color.a);
  p[2] = blendChannel(color.b, p[2], color.a);
  p[3] = static_cast<std::uint8_t>(color.a + (p[3] * (kOpaque - color.a) + kOpaque / 2) / kOpaque);
}

// The integer position (font units) of vertex `index`; the font's coordinates are
// whole numbers because we print at the origin with no extra spacing.
std::pair<int, int> vertexPosition(const std::vector<char>& vertices, int index) {
  float xy[2];
  std::memcpy(xy, vertices.data() + static_cast<std::size_t>(index) * kBytesPerVertex, sizeof xy);
  return {static_cast<int>(std::lround(xy[0])), static_cast<int>(std::lround(xy[1]))};
}

PixelRect intersect(const PixelRect& a, const PixelRect& b) {
  const int x0 = std::max(a.x, b.x), y0 = std::max(a.y, b.y);
  const int x1 = std::min(a.x + a.width, b.x + b.width);
  const int y1 = std::min(a.y + a.height, b.y + b.height);
  if (x1 <= x0 || y1 <= y0) return {};
  return {x0, y0, x1 - x0, y1 - y0};
}

}  // namespace

int textWidth(std::string_view text, int scale) {
  std::string chars = printable(text);
  return stb_easy_font_width(chars.data()) * effectiveScale(scale);
}

int textHeight(std::string_view text, int scale) {
  const int lines = lineCount(printable(text));
  return ((lines - 1) * kFontLineAdvance + kFontGlyphHeight) * effectiveScale(scale);
}

PixelRect textBounds(int x, int y, std::string_view text, const TextStyle& style) {
  PixelRect bounds{x, y, textWidth(text, style.scale), textHeight(text, style.scale)};
  if (style.backing) {
    // The width already ends in one blank spacing unit, so the right side needs one
    // unit less padding for the box to look centred.
    const int scale = effectiveScale(style.scale);
    const int pad = kBackingPaddingUnits * scale;
    bounds.x -= pad;
    bounds.y -= pad;
    bounds.width += 2 * pad - scale;
    bounds.height += 2 * pad;
  }
  return bounds;
}

PixelRect clipToImage(const Image& image, const PixelRect& rect) {
  return intersect(rect, {0, 0, image.width, image.height});
}

void fillRect(Image& image, const PixelRect& rect, Rgba8 color) {
  if (!image.valid()) return;
  const PixelRect clipped = clipToImage(image, rect);
  for (int y = clipped.y; y < clipped.y + clipped.height; ++y)
    for (int x = clipped.x; x < clipped.x + clipped.width; ++x) blendPixel(image, x, y, color);
}

PixelRect drawText(Image& image, int x, int y, std::string_view text, const TextStyle& style) {
  if (!image.valid()) return {};
  const PixelRect bounds = textBounds(x, y, text, style);
  const PixelRect clipped = clipToImage(image, bounds);
  if (clipped.empty()) return {};
  if (style.backing) fillRect(image, bounds, style.backingColor);

  std::string chars = printable(text);
  std::vector<char> vertices(std::max<std::size_t>(chars.size(), 1) * kMaxQuadsPerGlyph * kBytesPerQuad);
  // Laid out at the origin in font units, then scaled and moved in integers, so
  // glyph edges land exactly on pixel boundaries.
  const int quads = stb_easy_font_print(0.f, 0.f, chars.data(), nullptr, vertices.data(),
                                        static_cast<int>(vertices.size()));
  // Segments of one glyph overlap at their ends, so the quads are first merged into a
  // coverage mask over the clipped box: a translucent colour is blended once per pixel.
  const int scale = effectiveScale(style.scale);
  std::vector<bool> covered(static_cast<std::size_t>(clipped.width) * static_cast<std::size_t>(clipped.height));
  for (int q = 0; q < quads; ++q) {
    // Vertices 0 and 2 of each quad are opposite corners of an axis-aligned rectangle.
    const auto [x0, y0] = vertexPosition(vertices, q * kVerticesPerQuad);
    const auto [x1, y1] = vertexPosition(vertices, q * kVerticesPerQuad + 2);
    const PixelRect quad =
        intersect(clipped, {x + x0 * scale, y + y0 * scale, (x1 - x0) * scale, (y1 - y0) * scale});
    for (int py = quad.y; py < quad.y + quad.height; ++py)
      for (int px = quad.x; px < quad.x + quad.width; ++px)
        covered[static_cast<std::size_t>(py - clipped.y) * clipped.width + (px - clipped.x)] = true;
  }
  for (int py = clipped.y; py < clipped.y + clipped.height; ++py)
    for (int px = clipped.x; px < clipped.x + clipped.width; ++px)
      if (covered[static_cast<std::size_t>(py - clipped.y) * clipped.width + (px - clipped.x)])
        blendPixel(image, px, py, style.color);
  return clipped;
}

}  // namespace wg::image
