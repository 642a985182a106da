#include "nodes/frame_fields.hpp"

#include <array>
#include <limits>

namespace wg {

namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();
using T = FrameFieldType;

constexpr std::size_t components(FrameFieldType type) {
  switch (type) {
    case T::Float:
    case T::Uint: return 1;
    case T::Vec2: return 2;
    case T::Vec3: return 3;
    case T::Vec4: return 4;
    case T::Mat4: return 16;
  }
  return 0;
}

template <auto Member>
std::byte* memberBytes(FrameState& frame) {
  return reinterpret_cast<std::byte*>(&(frame.*Member));
}

// One row; the member's size must match the declared type, so the table cannot point a
// field at a member of another shape.
template <auto Member, FrameFieldType Type>
constexpr FrameField field(std::string_view name, std::string_view doc, float min = -kInf, float max = kInf,
                           FrameFieldOwner owner = FrameFieldOwner::Host) {
  static_assert(sizeof(FrameState{}.*Member) == 4 * components(Type), "member and field type disagree");
  return {name, Type, &memberBytes<Member>, min, max, doc, owner};
}

template <std::size_t I>
std::byte* skyIrradianceBytes(FrameState& frame) {
  return reinterpret_cast<std::byte*>(frame.skyIrradiance[I].data());
}

// One of the sky's nine irradiance coefficients: `doc` names its polynomial in the
// world normal (host/sky_irradiance.hpp).
template <std::size_t I>
constexpr FrameField skyIrradianceField(std::string_view name, std::string_view doc) {
  static_assert(sizeof(FrameState{}.skyIrradiance[I]) == 4 * components(T::Vec4));
  return {name, T::Vec4, &skyIrradianceBytes<I>, -kInf, kInf, doc, FrameFieldOwner::Host};
}

constexpr FrameFieldOwner kWeather = FrameFieldOwner::Weather;
using F = FrameState;

// Ordered so std140 packs without holes: matrices and vec4s first, then each vec3
// followed by a float, then the scalars.
constexpr std::array<FrameField, 36> kFrameFields = {{
    field<&F::model, T::Mat4>("model", "object to world"),
    field<&F::viewProjection, T::Mat4>("viewProjection", "world to clip space"),
    field<&F::normalMatrix, T::Mat4>("normalMatrix", "inverse transpose of model"),
    field<&F::lightViewProjection, T::Mat4>("lightViewProjection", "world to sun shadow-map clip space"),
    field<&F::skyExposureRegion, T::Vec4>("skyExposureRegion", "xz origin, 1/size: world to exposure-map uv",
                                          -kInf, kInf, FrameFieldOwner::MapPlace),
    field<&F::terrainRegion, T::Vec4>("terrainRegion", "xz origin, 1/size: world to height-map uv (eq. 3.11)", -kInf,
                                      kInf, FrameFieldOwner::MapPlace),
    skyIrradianceField<0>("skyIrradiance0", "sky irradiance / pi, spherical harmonics: rgb times 1 (w unused)"),
    skyIrradianceField<1>("skyIrradiance1", "sky irradiance / pi, spherical harmonics: rgb times n.x"),
    skyIrradianceField<2>("skyIrradiance2", "sky irradiance / pi, spherical harmonics: rgb times n.y (up)"),
    skyIrradianceField<3>("skyIrradiance3", "sky irradiance / pi, spherical harmonics: rgb times n.z"),
    skyIrradianceField<4>("skyIrradiance4", "sky irradiance / pi, spherical harmonics: rgb times n.x n.y"),
    skyIrradianceField<5>("skyIrradiance5", "sky irradiance / pi, spherical harmonics: rgb times n.y n.z"),
    skyIrradianceField<6>("skyIrradiance6", "sky irradiance / pi, spherical harmonics: rgb times 3 n.y^2 - 1"),
    skyIrradianceField<7>("skyIrradiance7", "sky irradiance / pi, spherical harmonics: rgb times n.x n.z"),
    skyIrradianceField<8>("skyIrradiance8", "sky irradiance / pi, spherical harmonics: rgb times n.z^2 - n.x^2"),
    field<&F::cameraPosition, T::Vec3>("cameraPosition", "world position of the eye"),
    field<&F::time, T::Float>("time", "seconds since the scene started (pans wind, ripples, panners)", 0.f, kInf,
                              kWeather),
    field<&F::sunDirection, T::Vec3>("sunDirection", "towards the sun, world x:y:z, y up (normalised)", -kInf, kInf,
                                     kWeather),
    field<&F::sunIntensity, T::Float>("sunIntensity", "the sun light's brightness (radiance = sunColor * sunIntensity)",
                                      0.f, 1.f, kWeather),
    field<&F::sunColor, T::Vec3>("sunColor", "linear radiance at full intensity; radiance = sunColor * sunIntensity"),
    field<&F::ambientIntensity, T::Float>("ambientIntensity", "sky light scale"),
    field<&F::skyColor, T::Vec3>("skyColor", "linear sky radiance"),
    field<&F::temperature, T::Float>("temperature", "air temperature, degrees C", kMinTemperatureC, kMaxTemperatureC,
                                     kWeather),
    field<&F::windDirection, T::Vec2>("windDirection", "where the wind blows to, world x:z (normalised; 0:0 is calm)",
                                      -kInf, kInf, kWeather),
    field<&F::windIntensity, T::Float>("windIntensity", "0 calm .. 1 blizzard", 0.f, 1.f, kWeather),
    field<&F::precipitation, T::Float>("precipitation", "0 dry .. 1 heavy (about 10 mm/h of rain)", 0.f, 1.f, kWeather),
    field<&F::sunMelt, T::Float>("sunMelt",
                                 "eq. 3.5's SunIntensity: how strongly direct sun melts snow and dries moss on the faces "
                                 "it shines on (not the light)",
                                 0.f, 1.f, kWeather),
    field<&F::snowLevel, T::Float>("snowLevel", "accumulated snow", 0.f, 1.f, kWeather),
    field<&F::wetnessLevel, T::Float>("wetnessLevel", "accumulated wetness", 0.f, 1.f, kWeather),
    field<&F::mossLevel, T::Float>("mossLevel", "moss growth", 0.f, 1.f, kWeather),
    field<&F::frostLevel, T::Float>("frostLevel", "how frozen water is", 0.f, 1.f, kWeather),
    field<&F::puddleLevel, T::Float>("puddleLevel", "standing water", 0.f, 1.f, kWeather),
    field<&F::exposure, T::Float>("exposure", "tone-mapping exposure"),
    field<&F::debugView, T::Uint>("debugView", "0 = lit; others select an AOV (compiler/debug_views.hpp)"),
    field<&F::terrainHeightScale, T::Float>("terrainHeightScale",
                                            "metres per unit of the terrain height map (none is bound: flat)", 0.f,
                                            kInf, kWeather),
    field<&F::shadowMapTexel, T::Float>("shadowMapTexel", "1 / shadow-map size; 0 turns sun shadows off"),
}};

}  // namespace

std::span<const FrameField> frameFields() { return kFrameFields; }

const FrameField* findFrameField(std::string_view name) {
  for (const auto& f : kFrameFields)
    if (f.name == name) return &f;
  return nullptr;
}

std::size_t componentCount(FrameFieldType type) { return components(type); }

std::string_view glslTypeName(FrameFieldType type) {
  switch (type) {
    case T::Float: return "float";
    case T::Uint: return "uint";
    case T::Vec2: return "vec2";
    case T::Vec3: return "vec3";
    case T::Vec4: return "vec4";
    case T::Mat4: return "mat4";
  }
  return "";
}

std::span<std::byte> fieldBytes(const FrameField& field, FrameState& frame) {
  return {field.member(frame), 4 * components(field.type)};
}

std::span<const std::byte> fieldBytes(const FrameField& field, const FrameState& frame) {
  // The accessor only takes the member's address; nothing is written through it.
  return fieldBytes(field, const_cast<FrameState&>(frame));
}

std::span<float> fieldFloats(const FrameField& field, FrameState& frame) {
  return {reinterpret_cast<float*>(field.member(frame)), components(field.type)};
}

}  // namespace wg
