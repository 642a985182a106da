#include "nodes/texture_generators.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "nodes/value.hpp"

namespace wg {

namespace {

using Kind = GeneratorOption::Kind;
using Rgb = std::array<float, 3>;

// ---- Option table ---------------------------------------------------------------

constexpr int kMaxScale = 64;    // lattice cells across the tile
constexpr int kMaxOctaves = 8;   // a 128x frequency range; more only adds sub-texel detail
constexpr float kMaxStrength = 16.f;  // slopes beyond this give near-horizontal normals

GeneratorOption scaleOption(float defaultScale) {
  return {"scale", Kind::Integer, {defaultScale, 0.f, 0.f}, 1.f, static_cast<float>(kMaxScale),
          "lattice cells across the tile (larger: finer features)"};
}
GeneratorOption octavesOption(float defaultOctaves) {
  return {"octaves", Kind::Integer, {defaultOctaves, 0.f, 0.f}, 1.f,
          static_cast<float>(kMaxOctaves), "noise layers, each at twice the previous frequency"};
}
GeneratorOption gainOption() {
  return {"gain", Kind::Number, {0.5f, 0.f, 0.f}, 0.f, 1.f,
          "amplitude of each octave relative to the previous one (larger: rougher)"};
}
GeneratorOption colorOption(std::string_view name, float grey, std::string_view doc) {
  return {name, Kind::Color3, {grey, grey, grey}, 0.f, 1.f, doc};
}

const std::vector<GeneratorSpec>& generatorTable() {
  static const std::vector<GeneratorSpec> table = {
      {"fbm",
       "periodic value-noise fBm: rgb = mix(colorA, colorB, noise), alpha = noise (height/mask)",
       {scaleOption(8), octavesOption(5), gainOption(),
        colorOption("colorA", 0.2f, "colour where the noise is 0"),
        colorOption("colorB", 0.8f, "colour where the noise is 1")}},
      {"fbm_normal",
       "tangent-space normal map of the fbm height (x along +u, y along +v): "
       "rgb = normal*0.5+0.5, alpha = height",
       {scaleOption(8), octavesOption(5), gainOption(),
        {"strength", Kind::Number, {2.f, 0.f, 0.f}, 0.f, kMaxStrength,
         "bump height: slope multiplier (0: flat)"}}},
      {"voronoi",
       "periodic cellular noise: rgb = per-cell mix(colorA, colorB) darkened in the cracks, "
       "alpha = crack mask, 1 on cell borders (cobbles, rock cracks, asphalt aggregate)",
       {scaleOption(8), colorOption("colorA", 0.3f, "colour of cells with random value 0"),
        colorOption("colorB", 0.6f, "colour of cells with random value 1"),
        {"edgeWidth", Kind::Number, {0.1f, 0.f, 0.f}, 0.f, 1.f,
         "crack width across the border, in cells (F2-F1 scale; 0: no cracks)"}}},
      {"flow",
       "smooth flow noise for wind panning: r, g = two decorrelated fbm fields, "
       "b = their average, alpha = 1",
       {scaleOption(4), octavesOption(3)}},
  };
  return table;
}

// Options after validation: each of the spec's options with its given or default value.
class ResolvedOptions {
 public:
  ResolvedOptions(const GeneratorSpec& spec, const nlohmann::json& options) : spec_(spec) {
    for (const GeneratorOption& option : spec.options) {
      Rgb value = option.defaultValue;
      if (options.is_object() && options.contains(option.name)) {
        const nlohmann::json& given = options.at(option.name);
        if (option.kind == Kind::Color3) {
          for (int c = 0; c < 3; ++c) value[c] = given.at(c).get<float>();
        } else {
          value[0] = given.get<float>();
        }
      }
      values_.push_back(value);
    }
  }
  float number(std::string_view name) const { return color(name)[0]; }
  int integer(std::string_view name) const { return static_cast<int>(number(name)); }
  const Rgb& color(std::string_view name) const {
    for (std::size_t i = 0; i < spec_.options.size(); ++i)
      if (spec_.options[i].name == name) return values_[i];
    throw std::logic_error("generator option not in spec: " + std::string(name));
  }

 private:
  const GeneratorSpec& spec_;
  std::vector<Rgb> values_;
};

// ---- Deterministic noise ---------------------------------------------------------

// Chris Wellons' "lowbias32" integer hash: full avalanche, no tables, no state.
constexpr std::uint32_t hash32(std::uint32_t x) {
  x ^= x >> 16;
  x *= 0x7feb352du;
  x ^= x >> 15;
  x *= 0x846ca68bu;
  x ^= x >> 16;
  return x;
}

// A key for one independent noise field: the seed, a stream (which field of a
// generator) and a layer (octave).
constexpr std::uint32_t fieldKey(std::uint32_t seed, std::uint32_t stream, std::uint32_t layer) {
  return hash32(seed ^ hash32(stream ^ hash32(layer)));
}

constexpr std::uint32_t latticeHash(std::uint32_t key, int i, int j) {
  return hash32(hash32(key ^ static_cast<std::uint32_t>(i)) + static_cast<std::uint32_t>(j));
}

// The top 24 bits as a float in [0, 1), exactly representable.
constexpr float unitFloat(std::uint32_t h) {
  constexpr int kMantissaBits = 24;
  constexpr float kInvRange = 1.f / static_cast<float>(1u << kMantissaBits);
  return static_cast<float>(h >> (32 - kMantissaBits)) * kInvRange;
}

// Quintic fade 6t^5 - 15t^4 + 10t^3: C2 continuous, so the normal map has no creases.
float fade(float t) { return t * t * t * (t * (t * 6.f - 15.f) + 10.f); }
float lerp(float a, float b, float t) { return a + (b - a) * t; }

float smoothstep01(float x) {
  const float t = x < 0.f ? 0.f : (x > 1.f ? 1.f : x);
  return t * t * (3.f - 2.f * t);
}

int wrapIndex(int i, int period) {
  const int r = i % period;
  return r < 0 ? r + period : r;
}

// Value noise on a lattice of `period` x `period` cells spanning the tile; (x, y) are in
// cells, in [0, period). Lattice indices wrap by the period, so the field tiles.
float periodicValueNoise(std::uint32_t key, float x, float y, int period) {
  const float fx = std::floor(x), fy = std::floor(y);
  const int i0 = wrapIndex(static_cast<int>(fx), period);
  const int j0 = wrapIndex(static_cast<int>(fy), period);
  const int i1 = wrapIndex(i0 + 1, period), j1 = wrapIndex(j0 + 1, period);
  const float tx = fade(x - fx), ty = fade(y - fy);
  const float a = unitFloat(latticeHash(key, i0, j0)), b = unitFloat(latticeHash(key, i1, j0));
  const float c = unitFloat(latticeHash(key, i0, j1)), d = unitFloat(latticeHash(key, i1, j1));
  return lerp(lerp(a, b, tx), lerp(c, d, tx), ty);
}

struct FbmSettings {
  int scale;
  int octaves;
  float gain;
};

// Normalized fBm in [0, 1] at tile coordinates (u, v) in [0, 1). Each octave doubles
// the integer period, so every octave, and the sum, tiles.
float periodicFbm(std::uint32_t seed, std::uint32_t stream, const FbmSettings& s, float u,
                  float v) {
  float sum = 0.f, norm = 0.f, amplitude = 1.f;
  for (int octave = 0; octave < s.octaves; ++octave) {
    const int period = s.scale << octave;
    const float p = static_cast<float>(period);
    const std::uint32_t key = fieldKey(seed, stream, static_cast<std::uint32_t>(octave));
    sum += amplitude * periodicValueNoise(key, u * p, v * p, period);
    norm += amplitude;
    amplitude *= s.gain;
  }
  return norm > 0.f ? sum / norm : 0.f;
}

// Tile coordinate of texel centre i, the point the texel's value represents.
float texelCentre(int i, int size) {
  constexpr float kHalfTexel = 0.5f;
  return (static_cast<float>(i) + kHalfTexel) / static_cast<float>(size);
}

// Noise streams, so generators that need several fields get independent ones.
constexpr std::uint32_t kHeightStream = 0;  // fbm and fbm_normal share it (same height)
constexpr std::uint32_t kFlowStreamR = 1;
constexpr std::uint32_t kFlowStreamG = 2;
constexpr std::uint32_t kCellJitterXStream = 3;
constexpr std::uint32_t kCellJitterYStream = 4;
constexpr std::uint32_t kCellValueStream = 5;

FbmSettings fbmSettings(const ResolvedOptions& o) {
  return {o.integer("scale"), o.integer("octaves"), o.number("gain")};
}

std::vector<float> heightField(std::uint32_t seed, int size, const FbmSettings& s) {
  std::vector<float> height(static_cast<std::size_t>(size) * static_cast<std::size_t>(size));
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x)
      height[static_cast<std::size_t>(y) * size + x] =
          periodicFbm(seed, kHeightStream, s, texelCentre(x, size), texelCentre(y, size));
  return height;
}

Rgb mixRgb(const Rgb& a, const Rgb& b, float t) {
  return {lerp(a[0], b[0], t), lerp(a[1], b[1], t), lerp(a[2], b[2], t)};
}

// ---- Generators ------------------------------------------------------------------

Image generateFbm(std::uint32_t seed, int size, const ResolvedOptions& o) {
  const std::vector<float> height = heightField(seed, size, fbmSettings(o));
  const Rgb& a = o.color("colorA");
  const Rgb& b = o.color("colorB");
  Image image = Image::blank(size, size);
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      const float h = height[static_cast<std::size_t>(y) * size + x];
      const Rgb c = mixRgb(a, b, h);
      image.setTexel(x, y, {c[0], c[1], c[2], h});
    }
  return image;
}

Image generateFbmNormal(std::uint32_t seed, int size, const ResolvedOptions& o) {
  const FbmSettings s = fbmSettings(o);
  const std::vector<float> height = heightField(seed, size, s);
  const float strength = o.number("strength");
  auto at = [&](int x, int y) {
    return height[static_cast<std::size_t>(wrapIndex(y, size)) * size + wrapIndex(x, size)];
  };
  // Central differences over wrapped neighbours (so the normals tile too), expressed
  // per base lattice cell so the bumpiness does not depend on the texture size.
  const float cellsPerTexelPair = 2.f * static_cast<float>(s.scale) / static_cast<float>(size);
  constexpr float kEncodeHalf = 0.5f;  // maps [-1,1] to [0,1]
  Image image = Image::blank(size, size);
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      const float dhdu = (at(x + 1, y) - at(x - 1, y)) / cellsPerTexelPair;
      const float dhdv = (at(x, y + 1) - at(x, y - 1)) / cellsPerTexelPair;
      // Normal of the surface z = strength * h: (-dh/du, -dh/dv, 1), normalized.
      const float nx = -strength * dhdu, ny = -strength * dhdv;
      const float invLength = 1.f / std::sqrt(nx * nx + ny * ny + 1.f);
      image.setTexel(x, y,
                     {nx * invLength * kEncodeHalf + kEncodeHalf,
                      ny * invLength * kEncodeHalf + kEncodeHalf, invLength * kEncodeHalf + kEncodeHalf,
                      at(x, y)});
    }
  return image;
}

Image generateVoronoi(std::uint32_t seed, int size, const ResolvedOptions& o) {
  const int period = o.integer("scale");
  const Rgb& colorA = o.color("colorA");
  const Rgb& colorB = o.color("colorB");
  const float edgeWidth = o.number("edgeWidth");
  constexpr float kCrackDarkening = 0.75f;  // cracks keep a quarter of the cell colour
  // Feature points are jittered anywhere inside their cell, so the nearest point and
  // its Voronoi neighbours can be up to two cells away: search a 5x5 block.
  constexpr int kSearchRadius = 2;
  constexpr int kSearchSide = 2 * kSearchRadius + 1;
  const std::uint32_t jitterX = fieldKey(seed, kCellJitterXStream, 0);
  const std::uint32_t jitterY = fieldKey(seed, kCellJitterYStream, 0);
  const std::uint32_t cellValue = fieldKey(seed, kCellValueStream, 0);
  const float p = static_cast<float>(period);

  struct Feature {
    float x, y;   // position in cells, unwrapped (relative to this texel's block)
    float value;  // the cell's random colour mix
  };
  std::array<Feature, kSearchSide * kSearchSide> block{};

  Image image = Image::blank(size, size);
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      const float px = texelCentre(x, size) * p, py = texelCentre(y, size) * p;
      const int ci = static_cast<int>(std::floor(px)), cj = static_cast<int>(std::floor(py));
      // F1: the nearest feature point decides which cell (colour) the texel is in.
      std::size_t nearest = 0;
      float f1Squared = std::numeric_limits<float>::infinity();
      std::size_t k = 0;
      for (int dj = -kSearchRadius; dj <= kSearchRadius; ++dj)
        for (int di = -kSearchRadius; di <= kSearchRadius; ++di, ++k) {
          // Unwrapped position, wrapped identity: the cell left of column 0 is the
          // last column's cell, seen one period to the left. This is what tiles.
          const int i = ci + di, j = cj + dj;
          const int wi = wrapIndex(i, period), wj = wrapIndex(j, period);
          Feature& f = block[k];
          f.x = static_cast<float>(i) + unitFloat(latticeHash(jitterX, wi, wj));
          f.y = static_cast<float>(j) + unitFloat(latticeHash(jitterY, wi, wj));
          f.value = unitFloat(latticeHash(cellValue, wi, wj));
          const float dSquared = (f.x - px) * (f.x - px) + (f.y - py) * (f.y - py);
          if (dSquared < f1Squared) {
            f1Squared = dSquared;
            nearest = k;
          }
        }
      // Distance to the cell border: the nearest bisector between the F1 point and any
      // other point. Unlike F2-F1 itself, it does not widen into wedges where two
      // feature points are close together. On the segment between the two points
      // F2-F1 is exactly twice this distance, so edgeWidth keeps F2-F1's scale.
      const Feature& a = block[nearest];
      float border = std::numeric_limits<float>::infinity();
      for (std::size_t b = 0; b < block.size(); ++b) {
        if (b == nearest) continue;
        const float ex = block[b].x - a.x, ey = block[b].y - a.y;
        const float midX = 0.5f * (a.x + block[b].x), midY = 0.5f * (a.y + block[b].y);
        const float distance = ((midX - px) * ex + (midY - py) * ey) / std::sqrt(ex * ex + ey * ey);
        if (distance < border) border = distance;
      }
      const float edgeMetric = 2.f * border;  // F2-F1 equivalent
      const float crack = edgeWidth > 0.f ? 1.f - smoothstep01(edgeMetric / edgeWidth) : 0.f;
      const Rgb base = mixRgb(colorA, colorB, a.value);
      const float shade = 1.f - kCrackDarkening * crack;
      image.setTexel(x, y, {base[0] * shade, base[1] * shade, base[2] * shade, crack});
    }
  return image;
}

Image generateFlow(std::uint32_t seed, int size, const ResolvedOptions& o) {
  constexpr float kFlowGain = 0.5f;  // the classic 1/f falloff: smooth, no speckle
  const FbmSettings s{o.integer("scale"), o.integer("octaves"), kFlowGain};
  Image image = Image::blank(size, size);
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      const float u = texelCentre(x, size), v = texelCentre(y, size);
      const float r = periodicFbm(seed, kFlowStreamR, s, u, v);
      const float g = periodicFbm(seed, kFlowStreamG, s, u, v);
      image.setTexel(x, y, {r, g, (r + g) * 0.5f, 1.f});
    }
  return image;
}

using GenerateFn = Image (*)(std::uint32_t seed, int size, const ResolvedOptions& options);

GenerateFn generatorFunction(std::string_view name) {
  if (name == "fbm") return &generateFbm;
  if (name == "fbm_normal") return &generateFbmNormal;
  if (name == "voronoi") return &generateVoronoi;
  if (name == "flow") return &generateFlow;
  return nullptr;
}

// ---- Validation helpers ------------------------------------------------------------

std::string formatBound(const GeneratorOption& option, float x) {
  if (option.kind == Kind::Integer) return std::to_string(static_cast<int>(x));
  std::string s = formatFloat(x);
  if (s.size() > 2 && s.ends_with(".0")) s.resize(s.size() - 2);  // "1" reads better than "1.0"
  return s;
}

std::string expectation(const GeneratorOption& option) {
  const std::string range = "from " + formatBound(option, option.min) + " to " +
                            formatBound(option, option.max);
  switch (option.kind) {
    case Kind::Integer: return "an integer " + range;
    case Kind::Number: return "a number " + range;
    case Kind::Color3:
      return "an array of 3 numbers (r, g, b) each " + range + ", e.g. [" +
             formatBound(option, option.defaultValue[0]) + ", " +
             formatBound(option, option.defaultValue[1]) + ", " +
             formatBound(option, option.defaultValue[2]) + "]";
  }
  return {};
}

bool numberInRange(const nlohmann::json& value, const GeneratorOption& option, bool integral) {
  if (!value.is_number()) return false;
  const double x = value.get<double>();
  if (!std::isfinite(x) || x < option.min || x > option.max) return false;
  return !integral || std::floor(x) == x;
}

bool optionValueValid(const nlohmann::json& value, const GeneratorOption& option) {
  switch (option.kind) {
    case Kind::Integer: return numberInRange(value, option, true);
    case Kind::Number: return numberInRange(value, option, false);
    case Kind::Color3:
      if (!value.is_array() || value.size() != 3) return false;
      for (const nlohmann::json& component : value)
        if (!numberInRange(component, option, false)) return false;
      return true;
  }
  return false;
}

std::string optionList(const GeneratorSpec& spec) {
  std::string list;
  for (const GeneratorOption& option : spec.options) {
    if (!list.empty()) list += ", ";
    list += option.name;
  }
  return list;
}

}  // namespace

bool isValidGeneratorSize(int size) {
  return size >= kMinGeneratorSize && size <= kMaxGeneratorSize && (size & (size - 1)) == 0;
}

const GeneratorOption* GeneratorSpec::findOption(std::string_view option) const {
  for (const GeneratorOption& o : options)
    if (o.name == option) return &o;
  return nullptr;
}

std::span<const GeneratorSpec> textureGenerators() { return generatorTable(); }

const GeneratorSpec* findTextureGenerator(std::string_view name) {
  for (const GeneratorSpec& spec : generatorTable())
    if (spec.name == name) return &spec;
  return nullptr;
}

std::string validateGeneratorOptions(const GeneratorSpec& spec, const nlohmann::json& options) {
  const std::string prefix = "generator '" + std::string(spec.name) + "': ";
  if (options.is_null()) return {};
  if (!options.is_object())
    return prefix + "options must be a JSON object of option names to values, got " +
           options.dump();
  for (const auto& [key, value] : options.items()) {
    const GeneratorOption* option = spec.findOption(key);
    if (!option) {
      return prefix + "unknown option '" + key + "'; valid options: " +
             (spec.options.empty() ? std::string("none") : optionList(spec));
    }
    if (!optionValueValid(value, *option))
      return prefix + "option '" + key + "' must be " + expectation(*option) + ", got " +
             value.dump();
  }
  return {};
}

Image generateTexture(const GeneratorSpec& spec, std::uint32_t seed, int size,
                      const nlohmann::json& options) {
  if (!isValidGeneratorSize(size))
    throw std::invalid_argument("generator '" + std::string(spec.name) + "': size " +
                                std::to_string(size) + " is not a power of two from " +
                                std::to_string(kMinGeneratorSize) + " to " +
                                std::to_string(kMaxGeneratorSize));
  const GenerateFn generate = generatorFunction(spec.name);
  if (!generate)
    throw std::invalid_argument("unknown texture generator '" + std::string(spec.name) + "'");
  if (std::string error = validateGeneratorOptions(spec, options); !error.empty())
    throw std::invalid_argument(error);
  return generate(seed, size, ResolvedOptions(spec, options));
}

}  // namespace wg
