#include "nodes/weather_maps.hpp"

#include <array>

namespace wg {

namespace {

constexpr std::array<std::string_view, 1> kTerrainAccessors = {"wg_terrain_height_texel"};
constexpr std::array<std::string_view, 2> kExposureAccessors = {"wg_sky_exposure_texel", "wg_sky_exposure_gather"};
constexpr std::array<std::string_view, 1> kDeformationAccessors = {"wg_snow_deformation_texel"};
constexpr std::array<std::string_view, 1> kNoiseAccessors = {"wg_weather_noise"};

constexpr std::array<WeatherMap, 6> kWeatherMaps = {{
    {"terrainHeight", "wg_terrain_height_map", "wg_terrain_height_sampler", 1, "WG_NO_TERRAIN_HEIGHT_MAP",
     "vec4(0.0)", "level ground at y = 0", "r: terrain height in units of weather terrainHeightScale (eq. 3.8-3.12)",
     true, kTerrainAccessors},
    {"skyExposure", "wg_sky_exposure_map", "wg_sky_exposure_sampler", 3, "WG_NO_SKY_EXPOSURE_MAP", "vec4(-1.0e6)",
     "nothing above any point: open sky, exposure 1", "r: height of the highest occluder above the texel (m)", true,
     kExposureAccessors},
    {"sunShadow", "wg_sun_shadow_map", "wg_sun_shadow_sampler", 5, "", "vec4(1.0)", "fully lit",
     "r: depth from the sun (the reference host's lighting, read by wg_sun_shadow)", false, {}},
    {"snowDeformation", "wg_snow_deformation_map", "wg_snow_deformation_sampler", 7, "WG_NO_SNOW_DEFORMATION_MAP",
     "vec4(0.0, 0.0, 1.0, 0.0)", "undisturbed snow: no prints",
     "height offset (m) and world normal x, y, z (docs/deformable-snow.md)", true, kDeformationAccessors},
    {"weatherNoise", "wg_weather_noise_map", "wg_weather_noise_sampler", 9, "WG_NO_WEATHER_NOISE_MAP", "vec4(0.5)",
     "uniform weather: transitions, flow, ripples and puddles without their spatial variation",
     "r transition, g flow, b ripple, a puddles (weathergen::weatherNoiseTexture())", true, kNoiseAccessors},
    {"skyReflection", "wg_sky_reflection_map", "wg_sky_reflection_sampler", 11, "", "vec4(0.0)", "no reflection",
     "rgb: the sky's radiance prefiltered for roughness lod / 5, a level per lod (the reference host's lighting, "
     "read by wg_shade)",
     false, {}, true},
}};

}  // namespace

std::span<const WeatherMap> weatherMaps() { return kWeatherMaps; }

const WeatherMap* findWeatherMap(std::string_view name) {
  for (const auto& map : kWeatherMaps)
    if (map.name == name) return &map;
  return nullptr;
}

const WeatherMap* weatherMapOfAccessor(std::string_view function) {
  for (const auto& map : kWeatherMaps)
    for (std::string_view accessor : map.accessors)
      if (accessor == function) return &map;
  return nullptr;
}

const ShaderLibrary kWeatherMapLibrary = {
    "weather_maps",
    R"(// The shared weather maps (set 0), read at LOD 0: each has one level.
vec4 wg_terrain_height_texel(const vec2 uv) { return textureLod(sampler2D(wg_terrain_height_map, wg_terrain_height_sampler), uv, 0.0); }
vec4 wg_sky_exposure_texel(const vec2 uv) { return textureLod(sampler2D(wg_sky_exposure_map, wg_sky_exposure_sampler), uv, 0.0); }
vec4 wg_sky_exposure_gather(const vec2 uv) { return textureGather(sampler2D(wg_sky_exposure_map, wg_sky_exposure_sampler), uv); }
vec4 wg_snow_deformation_texel(const vec2 uv) { return textureLod(sampler2D(wg_snow_deformation_map, wg_snow_deformation_sampler), uv, 0.0); }
vec4 wg_weather_noise(const vec2 uv) { return textureLod(sampler2D(wg_weather_noise_map, wg_weather_noise_sampler), uv, 0.0); }
)",
    {}};

}  // namespace wg
