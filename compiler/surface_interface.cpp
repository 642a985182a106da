#include "compiler/surface_interface.hpp"

#include <algorithm>
#include <array>
#include <cctype>

#include "compiler/identifier.hpp"
#include "compiler/name_mark.hpp"
#include "compiler/pbr_output.hpp"
#include "nodes/frame_fields.hpp"
#include "nodes/weather_maps.hpp"

namespace wg {

namespace {

constexpr std::array<SurfaceLanguageInfo, 3> kSurfaceLanguages = {{
    {SurfaceLanguage::Glsl, "glsl", "surface.glsl"},
    {SurfaceLanguage::GlslEs, "glsles", "surface.es.glsl"},
    {SurfaceLanguage::Hlsl, "hlsl", "surface.hlsl"},
}};

UniformBlock makeWeatherBlock() {
  UniformBlock block;
  block.name = "Weather";
  block.identifier = "WeatherBlock";
  for (const auto& field : frameFields())
    if (field.owner != FrameFieldOwner::Host)
      block.members.push_back({std::string(field.name), frameMemberIdentifier(field), interfaceTypeOf(field.type)});
  layoutStd140(block);
  return block;
}

bool startsLikeIgnoringCase(std::string_view text, std::string_view start) {
  return text.size() >= start.size() && std::equal(start.begin(), start.end(), text.begin(), [](char a, char b) {
           return a == std::tolower(static_cast<unsigned char>(b));
         });
}

// Prefixes that could meet a reserved or weathergen name (gl_, wg_...).
bool startsLikeReserved(std::string_view text) {
  return startsLikeIgnoringCase(text, "gl") || startsLikeIgnoringCase(text, "wg") ||
         startsLikeIgnoringCase(text, "weather") || startsLikeIgnoringCase(text, "frame");
}

// A stem that is already a safe prefix as it is: a letter, then letters and digits in
// words joined by single '_', not starting like a reserved name, not looking marked.
bool isCleanStem(std::string_view stem) {
  if (stem.empty() || !std::isalpha(static_cast<unsigned char>(stem[0])) || stem.back() == '_') return false;
  for (std::size_t i = 0; i < stem.size(); ++i) {
    const char c = stem[i];
    if (c == '_' ? stem[i - 1] == '_' : !std::isalnum(static_cast<unsigned char>(c))) return false;
  }
  return !startsLikeReserved(stem) && !endsWithNameMark(stem, '_');
}

// A file stem as the start of GLSL and HLSL identifiers. Two surfaces in one shader need
// distinct prefixes, so the map is one-to-one: a clean stem is kept ("rock_"); any other
// ('-', '.', "__", a leading digit or '_', gl_/wg_...) is made an identifier and marked
// with its hash, as file stems are ("a-b" and "a_b" would both read "a_b").
std::string identifierPrefix(std::string_view stem) {
  if (isCleanStem(stem)) return std::string(stem) + '_';
  std::string base;
  for (char c : stem) {
    char ch = std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
    if (ch == '_' && (base.empty() || base.back() == '_')) continue;
    base += ch;
  }
  if (base.empty() || !std::isalpha(static_cast<unsigned char>(base[0])) || startsLikeReserved(base)) base.insert(0, "m");
  const std::string mark = '_' + nameMark(stem) + '_';
  base.resize(std::min(base.size(), IdentifierScope::kMaxLength - mark.size()));
  while (base.back() == '_') base.pop_back();
  return base + mark;
}

std::string_view glslType(InterfaceType type) { return interfaceTypeName(type); }
std::string_view glslType(ValueType type) {
  switch (type) {
    case ValueType::Vec2: return "vec2";
    case ValueType::Vec3: return "vec3";
    case ValueType::Vec4: return "vec4";
    case ValueType::Bool: return "bool";
    default: return "float";
  }
}

// The geometry a host hands the vertex function (world space: the host owns the
// object transform, skinning and instancing) and the values it interpolates.
std::vector<SurfaceField> geometryFields(const MaterialInterface& mi) {
  std::vector<SurfaceField> fields;
  for (const auto& v : mi.varyings) fields.push_back({v.name, glslType(v.type)});
  return fields;
}

constexpr std::size_t fieldSlotOf(PbrField field) { return static_cast<std::size_t>(field); }

std::string bindingMacro(std::string_view identifier) { return "WG_BINDING_" + std::string(identifier); }

}  // namespace

std::string_view surfaceResourceKindName(SurfaceResourceKind kind) {
  switch (kind) {
    case SurfaceResourceKind::UniformBlock: return "uniformBlock";
    case SurfaceResourceKind::Texture: return "texture";
    case SurfaceResourceKind::Sampler: return "sampler";
  }
  return "";
}

std::span<const SurfaceLanguageInfo> surfaceLanguages() { return kSurfaceLanguages; }

// The normal leaves in world space (the function applies the tangent frame).
std::string_view surfaceOutputField(std::size_t slot) {
  if (slot >= kPbrFieldCount) return coverageTerms()[slot - kPbrFieldCount].name;
  const PbrFieldInfo& f = pbrFields()[slot];
  return f.field == PbrField::AmbientOcclusion ? "occlusion" : f.name;
}

const UniformBlock& surfaceWeatherBlock() {
  static const UniformBlock kBlock = makeWeatherBlock();
  return kBlock;
}

namespace {

SurfaceInterface buildWithPrefix(const MaterialInterface& mi, std::string prefix) {
  SurfaceInterface s;
  s.prefix = std::move(prefix);
  s.vertexFunction = s.prefix + "surfaceVertex";
  s.fragmentFunction = s.prefix + "surfaceFragment";

  // Inputs: the interpolated geometry (the vertex-rate values among it) and the eye.
  s.vertexInput = {s.prefix + "VertexInput", {}};
  for (const auto& v : mi.varyings)
    if (v.name.rfind("interpolant", 0) != 0) s.vertexInput.fields.push_back({v.name, glslType(v.type)});
  s.vertexInput.fields.push_back({"cameraPosition", "vec3"});
  s.vertexOutput = {s.prefix + "VertexOutput", geometryFields(mi)};
  s.fragmentInput = {s.prefix + "FragmentInput", geometryFields(mi)};
  s.fragmentInput.fields.push_back({"frontFacing", "bool"});
  s.fragmentInput.fields.push_back({"cameraPosition", "vec3"});
  s.fragmentOutput = {s.prefix + "FragmentOutput", {}};
  for (const auto& f : pbrFields())
    if (f.stage == ShaderStage::Fragment)
      s.fragmentOutput.fields.push_back({std::string(surfaceOutputField(fieldSlotOf(f.field))), glslType(f.type)});
  for (std::size_t k = 0; k < kCoverageCount; ++k)
    s.fragmentOutput.fields.push_back({std::string(surfaceOutputField(kPbrFieldCount + k)), "float"});

  // Per-material identifiers carry the prefix; the weather's are shared.
  s.prefixed = mi;
  s.prefixed.material.identifier = s.prefix + mi.material.identifier;
  for (auto& m : s.prefixed.material.members) m.identifier = s.prefix + m.identifier;
  for (auto& t : s.prefixed.textures) {
    t.textureIdentifier = s.prefix + t.textureIdentifier;
    t.samplerIdentifier = s.prefix + t.samplerIdentifier;
  }

  const UniformBlock& weather = surfaceWeatherBlock();
  s.resources.push_back({weather.name, weather.identifier, SurfaceResourceKind::UniformBlock, true, 0, 0,
                         "WG_WEATHER_SET", bindingMacro(weather.identifier), {}});
  for (const auto& used : mi.weatherMaps) {
    const WeatherMap* map = findWeatherMap(used.name);
    if (!map || !map->surface) continue;
    s.resources.push_back({used.name, used.textureIdentifier, SurfaceResourceKind::Texture, true, 0, used.textureBinding,
                           "WG_WEATHER_SET", bindingMacro(used.textureIdentifier), map->fallbackMacro});
    s.resources.push_back({used.name, used.samplerIdentifier, SurfaceResourceKind::Sampler, true, 0, used.samplerBinding,
                           "WG_WEATHER_SET", bindingMacro(used.samplerIdentifier), map->fallbackMacro});
  }
  const std::string materialSet = "WG_SET_" + (s.prefix.empty() ? "material" : s.prefix.substr(0, s.prefix.size() - 1));
  const auto& block = s.prefixed.material;
  if (!block.members.empty())
    s.resources.push_back({block.name, block.identifier, SurfaceResourceKind::UniformBlock, false, block.set,
                           block.binding, materialSet, bindingMacro(block.identifier), {}});
  for (const auto& t : s.prefixed.textures) {
    s.resources.push_back({t.name, t.textureIdentifier, SurfaceResourceKind::Texture, false, t.set, t.textureBinding,
                           materialSet, bindingMacro(t.textureIdentifier), {}});
    s.resources.push_back({t.name, t.samplerIdentifier, SurfaceResourceKind::Sampler, false, t.set, t.samplerBinding,
                           materialSet, bindingMacro(t.samplerIdentifier), {}});
  }
  return s;
}

}  // namespace

SurfaceInterface buildSurfaceInterface(const MaterialInterface& mi, std::string_view fileStem) {
  return buildWithPrefix(mi, identifierPrefix(fileStem));
}

SurfaceInterface buildEmbeddedSurfaceInterface(const MaterialInterface& mi) { return buildWithPrefix(mi, ""); }

}  // namespace wg
