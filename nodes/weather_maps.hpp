// The shared weather maps, defined once: each map's name, emitted identifiers, binding
// in the frame set (set 0), the accessor functions every shader reads it through, and
// the value a surface reads in its place when the host binds none. The material
// interface, the reflection, the surface contract and the docs derive from this table.
#pragma once
#include <cstdint>
#include <span>
#include <string_view>

#include "nodes/op_definition.hpp"

namespace wg {

struct WeatherMap {
  std::string_view name;                // reflection's weatherMaps[].name and OpDef::weatherMaps
  std::string_view texture, sampler;    // emitted identifiers
  std::uint32_t binding;                // the texture's binding in set 0; the sampler's is binding + 1
  std::string_view fallbackMacro;       // defined by a surface host that binds no such map
  std::string_view fallback;            // GLSL vec4 every accessor returns then
  std::string_view fallbackMeaning;     // what the fallback does to the weather
  std::string_view texel;               // what one texel holds
  bool surface;                         // read by a surface; the sun shadow is the host's own
  std::span<const std::string_view> accessors;  // wg_ functions in kWeatherMapLibrary: vec4 f(const vec2 uv)
  bool cube = false;                    // a cube map (textureCube), else a 2D texture
};

std::span<const WeatherMap> weatherMaps();
const WeatherMap* findWeatherMap(std::string_view name);
// The map an accessor function reads, or null.
const WeatherMap* weatherMapOfAccessor(std::string_view function);

// GLSL: every accessor of every map, each a plain lookup at LOD 0 (the maps have one
// level) or a gather. Ops sample the maps only through these, so a surface can swap
// an accessor for its map's fallback.
extern const ShaderLibrary kWeatherMapLibrary;

}  // namespace wg
