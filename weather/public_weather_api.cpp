// weathergen::weather (include/weathergen/weather.hpp): the engine's view of the
// weather library. Plain structs in, the internal types (weather_state.hpp, the frame
// table, the noise image, the sky-exposure builder) behind it.
#include <weathergen/weather.hpp>

#include <algorithm>
#include <cmath>
#include <exception>
#include <limits>

#include "nodes/frame_fields.hpp"
#include "nodes/frame_state.hpp"
#include "nodes/weather_noise.hpp"
#include "weather/frame_weather.hpp"
#include "weather/sky_exposure_builder.hpp"
#include "weather/weather_simulation.hpp"

namespace weathergen::weather {

namespace {

wg::WeatherState internalState(const State& state) {
  wg::WeatherState s;
  const Conditions& c = state.conditions;
  s.conditions = {c.temperature, c.precipitation, c.windDirection, c.windIntensity, c.sunDirection, c.sunIntensity,
                  c.sunMelt};
  if (c.sunMelt < 0.f) s.conditions.sunMelt = wg::sunMeltStrength(s.conditions);  // derived, as timelines do
  s.time = state.time;
  const Levels& l = state.levels;
  s.levels = {l.snow, l.wetness, l.moss, l.frost, l.puddles, l.rainMemory};
  return s;
}

Levels publicLevels(const wg::WeatherLevels& l) { return {l.snow, l.wetness, l.moss, l.frost, l.puddles, l.rainMemory}; }

template <std::size_t N>
std::array<float, N> normalised(std::array<float, N> v) {
  float length = 0.f;
  for (float x : v) length += x * x;
  length = std::sqrt(length);
  if (length > 0.f && std::isfinite(length))
    for (float& x : v) x /= length;
  return v;
}

// A triangle list's world-space positions; false when an index or pointer is bad.
bool worldTriangles(const Occluder& occluder, std::vector<glm::vec3>& world, std::string& error) {
  if ((occluder.vertexCount > 0 && !occluder.positions) || (occluder.indexCount > 0 && !occluder.indices)) {
    error = "an occluder has a null pointer with a non-zero count";
    return false;
  }
  if (occluder.strideFloats < 3) {
    error = "an occluder's strideFloats is below 3";
    return false;
  }
  for (std::size_t i = 0; i < occluder.indexCount; ++i)
    if (occluder.indices[i] >= occluder.vertexCount) {
      error = "an occluder's index " + std::to_string(i) + " is " + std::to_string(occluder.indices[i]) +
              ", beyond its " + std::to_string(occluder.vertexCount) + " vertices";
      return false;
    }
  glm::mat4 model;
  std::copy(occluder.model.begin(), occluder.model.end(), &model[0][0]);
  world.resize(occluder.vertexCount);
  for (std::size_t v = 0; v < occluder.vertexCount; ++v) {
    const float* p = occluder.positions + v * occluder.strideFloats;
    world[v] = glm::vec3(model * glm::vec4(p[0], p[1], p[2], 1.f));
    if (!std::isfinite(world[v].x) || !std::isfinite(world[v].y) || !std::isfinite(world[v].z)) {
      error = "an occluder's vertex " + std::to_string(v) + " is not finite in world space";
      return false;
    }
  }
  return true;
}

}  // namespace

std::string step(State& state, double realSeconds, double timeScale) noexcept {
  try {
    wg::WeatherState s = internalState(state);
    if (std::string reason = wg::validate(s); !reason.empty()) return reason;
    wg::WeatherSimulation simulation;
    simulation.timeScale = timeScale;
    simulation.step(s, realSeconds);
    state.time = s.time;
    state.levels = publicLevels(s.levels);
    return "";
  } catch (const std::exception& e) {
    return e.what();
  }
}

std::vector<BlockField> weatherBlock(const State& state) noexcept {
  try {
    wg::WeatherState s = internalState(state);
    s.conditions.sunDirection = normalised(s.conditions.sunDirection);
    s.conditions.windDirection = normalised(s.conditions.windDirection);
    wg::FrameState frame;
    frame.terrainHeightScale = 0.f;
    wg::writeWeather(s, frame);
    std::vector<BlockField> fields;
    for (const wg::FrameField& field : wg::frameFields()) {
      if (field.owner != wg::FrameFieldOwner::Weather) continue;
      BlockField& out = fields.emplace_back();
      out.name = std::string(field.name);
      const std::span<float> values = wg::fieldFloats(field, frame);
      out.components = static_cast<std::uint32_t>(values.size());
      std::copy(values.begin(), values.end(), out.value.begin());
    }
    return fields;
  } catch (const std::exception&) {
    return {};
  }
}

NoiseTexture noiseTexture() noexcept {
  try {
    const wg::Image& image = wg::weather::noiseImage();
    return {static_cast<int>(image.width), static_cast<int>(image.height), image.rgba};
  } catch (const std::exception&) {
    return {};
  }
}

SkyExposureMap buildSkyExposureMap(const std::vector<Occluder>& occluders, std::uint32_t resolution, float margin,
                                   std::string& error) noexcept {
  try {
    error.clear();
    if (resolution < 16 || resolution > 4096) {
      error = "resolution " + std::to_string(resolution) + " is outside [16, 4096]";
      return {};
    }
    if (!(margin >= 0.f) || !std::isfinite(margin)) {
      error = "margin must be finite and at least 0";
      return {};
    }
    std::vector<std::vector<glm::vec3>> world(occluders.size());
    std::vector<wg::OccluderTriangles> triangles;
    for (std::size_t k = 0; k < occluders.size(); ++k) {
      if (!worldTriangles(occluders[k], world[k], error)) {
        error = "occluder " + std::to_string(k) + ": " + error;
        return {};
      }
      triangles.push_back({world[k], {occluders[k].indices, occluders[k].indexCount}});
    }
    auto [lo, hi] = wg::occluderBounds(triangles);
    wg::SkyExposureHeights map =
        wg::buildSkyExposure(triangles, lo - glm::vec3(margin), hi + glm::vec3(margin), static_cast<int>(resolution));
    return {resolution, {map.region.x, map.region.y, map.region.z, map.region.w}, map.floor, std::move(map.heights)};
  } catch (const std::exception& e) {
    error = e.what();
    return {};
  }
}

}  // namespace weathergen::weather
