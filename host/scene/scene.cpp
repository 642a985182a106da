#include "host/scene/scene.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <utility>

#include <glm/gtc/matrix_transform.hpp>

#include "nodes/lattice_noise.hpp"
#include "nodes/weather_model.hpp"
#include "nodes/weather_noise.hpp"
#include "host/scene/horizon_apron.hpp"
#include "host/scene/probe_visibility.hpp"
#include "host/scene/shapes.hpp"

namespace wg::scene {

namespace {

constexpr glm::vec3 kUp{0.f, 1.f, 0.f};

// Terrain: 128^2 cells (32k triangles) keeps a scene well inside lavapipe's budget.
constexpr int kTerrainResolution = 128;
constexpr float kTerrainUvTiling = 8.f;  // metres per terrain uv unit
// Beyond the terrain, rolling hills out to the horizon; haze thins them into the sky.
// Gentle: steep far hills seen edge-on made lavapipe's anisotropic filtering, which CPU
// devices no longer use, slow tenfold (40 m hills took a 160x90 frame from 0.8 s to 40 s).
constexpr float kHorizonHillWavelength = 300.f;
constexpr float kHorizonHillHeight = 12.f;

// Rivers: a flat-bottomed channel cut below the bank, the water a little below the bank
// top, and the water strip reaching under the bank top on both sides so its v = 0 and
// v = 1 edges are buried in the banks.
constexpr float kChannelBedHalfWidth = 3.f;
constexpr float kChannelTopHalfWidth = 5.f;
constexpr float kChannelDepth = 1.2f;
constexpr float kWaterBelowBank = 0.35f;
constexpr float kRiverWidth = 2.f * kChannelTopHalfWidth;
constexpr float kBankFlat = 2.f;    // level bank beyond the channel's top edge
constexpr float kBankBlend = 6.f;   // then back to the natural ground
constexpr float kRiverSampleStep = 1.f;
// Where the bank probes sit: 3.9 m from the centre is inside the water's visible edge
// (the wall meets the water about 4.4 m out) and at v = 0.11 or 0.89, where ice forms
// first.
constexpr float kBankProbeOffset = 3.9f;

// Roads: the ground is graded this far below the surface (more than the grid's
// interpolation error at a 14 degree grade change), flat for a verge beside the edges,
// then blended back to the natural ground.
constexpr float kRoadBedDrop = 0.15f;
constexpr float kRoadVergeFlat = 3.f;
constexpr float kRoadVergeBlend = 8.f;
constexpr float kRoadWidth = 6.f;
// Puddles form within 8 degrees of horizontal: ramps and camber are well past it.
constexpr float kRampDegrees = 14.f;
constexpr float kCamberDegrees = 12.5f;

// Shelters: roof underside this far above the highest ground under it.
constexpr float kShelterClearance = 3.f;
// How finely the ground under a roof is sampled to find its highest point.
constexpr int kShelterGroundSamples = 12;

// Rocks: icosphere detail 4 (5120 triangles); the centre sits this fraction of the
// radius above the ground so the rock is bedded in, not balanced on it.
constexpr int kRockDetail = 4;
constexpr float kRockRaise = 0.2f;
// Side probes are taken clear of the ground and on steep faces.
constexpr float kRockSideClearance = 0.4f;
constexpr float kRockSideMaxUp = 0.35f;
// ... and face within about 40 degrees of the horizontal sun direction (or its opposite).
constexpr float kRockSideMinAlignment = 0.75f;
// Top probes are on faces within about 20 degrees of level.
constexpr float kRockTopMinUp = 0.94f;

float smoothStep(float e0, float e1, float x) {
  float t = std::clamp((x - e0) / (e1 - e0), 0.f, 1.f);
  return t * t * (3.f - 2.f * t);
}

// Gentle rolling ground, centred on 0, roughly within +-0.35 of `amplitude`.
float hills(float x, float z, float wavelength, float amplitude) {
  float sum = 0.f, amp = 1.f, norm = 0.f, f = 1.f / wavelength;
  for (int o = 0; o < 3; ++o) {
    sum += amp * (gradientNoise(x * f + 13.7f * o, z * f - 5.3f * o) - 0.5f);
    norm += amp;
    amp *= 0.5f;
    f *= 2.f;
  }
  return amplitude * sum / norm;
}

// A river: centreline at bank-top level, the channel it cuts and its water strip.
struct River {
  std::vector<glm::vec3> bankLine;  // ordered downstream, y = bank top

  // Horizontal distance to the centreline and the bank height at the nearest point.
  std::pair<float, float> nearest(float x, float z) const {
    float best = std::numeric_limits<float>::max(), bank = 0.f;
    for (std::size_t i = 1; i < bankLine.size(); ++i) {
      glm::vec2 a(bankLine[i - 1].x, bankLine[i - 1].z), b(bankLine[i].x, bankLine[i].z), p(x, z);
      glm::vec2 ab = b - a;
      float t = std::clamp(glm::dot(p - a, ab) / glm::dot(ab, ab), 0.f, 1.f);
      float d = glm::distance(p, a + ab * t);
      if (d < best) {
        best = d;
        bank = glm::mix(bankLine[i - 1].y, bankLine[i].y, t);
      }
    }
    return {best, bank};
  }
  float distance(float x, float z) const { return nearest(x, z).first; }

  // The ground with the channel cut into it.
  float carve(float x, float z, float natural) const {
    auto [d, bank] = nearest(x, z);
    float channel = bank;
    if (d < kChannelBedHalfWidth) {
      channel = bank - kChannelDepth;
    } else if (d < kChannelTopHalfWidth) {
      channel = bank - kChannelDepth * (kChannelTopHalfWidth - d) / (kChannelTopHalfWidth - kChannelBedHalfWidth);
    }
    float w = smoothStep(kChannelTopHalfWidth + kBankFlat, kChannelTopHalfWidth + kBankFlat + kBankBlend, d);
    return glm::mix(channel, natural, w);
  }

  Mesh water() const {
    std::vector<glm::vec3> line = bankLine;
    for (auto& p : line) p.y -= kWaterBelowBank;
    float length = 0.f;
    for (std::size_t i = 1; i < line.size(); ++i) length += glm::distance(line[i - 1], line[i]);
    return riverStrip(line, kRiverWidth, std::max(1, static_cast<int>(std::round(length / kRiverSampleStep))));
  }

  // Centreline point and horizontal right-hand direction at the sample nearest x.
  std::pair<glm::vec3, glm::vec3> frameNear(float x) const {
    std::size_t best = 1;
    for (std::size_t i = 1; i < bankLine.size(); ++i)
      if (std::abs(bankLine[i].x - x) < std::abs(bankLine[best].x - x)) best = i;
    best = std::clamp<std::size_t>(best, 1, bankLine.size() - 1);
    glm::vec3 flow = bankLine[best] - bankLine[best - 1];
    flow.y = 0.f;
    glm::vec3 right = glm::normalize(glm::cross(glm::normalize(flow), kUp));
    return {bankLine[best], right};
  }
};

River makeRiver(float xMin, float xMax, const std::function<float(float)>& centreZ,
                const std::function<float(float)>& bankY) {
  River r;
  for (float x = xMin; x <= xMax + 1e-3f; x += kRiverSampleStep) r.bankLine.push_back({x, bankY(x), centreZ(x)});
  return r;
}

// The ground graded under and beside a road.
float gradeRoad(const RoadLayout& road, float x, float z, float natural) {
  glm::vec2 st = road.toRoad({x, z});
  float half = 0.5f * road.width;
  glm::vec2 clamped(std::clamp(st.x, 0.f, road.length()), std::clamp(st.y, -half, half));
  float d = glm::distance(st, clamped);
  float bed = road.surfaceHeight(clamped.x, clamped.y) - kRoadBedDrop;
  return glm::mix(bed, natural, smoothStep(kRoadVergeFlat, kRoadVergeFlat + kRoadVergeBlend, d));
}

float roadDistance(const RoadLayout& road, float x, float z) {
  glm::vec2 st = road.toRoad({x, z});
  float half = 0.5f * road.width;
  glm::vec2 clamped(std::clamp(st.x, 0.f, road.length()), std::clamp(st.y, -half, half));
  return glm::distance(st, clamped);
}

// Flat start, a 14 degree ramp up, a long flat stretch (for the shelter), a 12 degree
// crowned stretch with its transitions, a ramp back down and a flat end.
RoadLayout testRoad(glm::vec3 start, float shelterStretch) {
  RoadLayout road;
  road.start = start;
  road.direction = {1.f, 0.f};
  road.width = kRoadWidth;
  road.sections = {
      {18.f, 0.f, 0.f},
      {8.f, kRampDegrees, 0.f},
      {shelterStretch, 0.f, 0.f},
      {5.f, 0.f, kCamberDegrees},  // camber ramps in
      {12.f, 0.f, kCamberDegrees},
      {5.f, 0.f, 0.f},  // and out
      {8.f, -kRampDegrees, 0.f},
      {12.f, 0.f, 0.f},
  };
  return road;
}
// Road coordinates of the middle of section k.
float sectionMiddle(const RoadLayout& road, int k) {
  float s = 0.f;
  for (int i = 0; i < k; ++i) s += road.sections[i].length;
  return s + 0.5f * road.sections[k].length;
}
float sectionStart(const RoadLayout& road, int k) {
  float s = 0.f;
  for (int i = 0; i < k; ++i) s += road.sections[i].length;
  return s;
}
constexpr int kRoadRampSection = 1, kRoadShelterSection = 2, kRoadCamberSection = 4, kRoadFlatStart = 0;
// Road probes keep this far from section ends, the road's edges and the roof's edges.
constexpr float kProbeMargin = 2.f;
constexpr float kProbeRoofMargin = 3.f;

// Where puddles form first on a stretch of road, by the weather model's own puddle
// coverage on level ground: the spot that stays covered, a probe-radius round it, at
// the most of a ladder of low puddle levels. A flat-road probe there is wet as soon as
// any puddle forms (not on a blob's edge), and a sheltered one tests the shelter, not
// the noise.
constexpr float kProbeSearchStep = 0.5f;
constexpr float kProbeSpotRadius = 0.75f;
constexpr int kProbePuddleLevels = 10;
constexpr float kProbePuddleLevelStep = 0.05f;
glm::vec2 wettestSpot(const RoadLayout& road, float alongFrom, float alongTo, float acrossFrom, float acrossTo) {
  const std::array<glm::vec2, 5> around = {
      {{0.f, 0.f}, {kProbeSpotRadius, 0.f}, {-kProbeSpotRadius, 0.f}, {0.f, kProbeSpotRadius}, {0.f, -kProbeSpotRadius}}};
  glm::vec2 best(alongFrom, acrossFrom);
  float bestScore = -1.f;
  for (float s = alongFrom; s <= alongTo; s += kProbeSearchStep) {
    for (float t = acrossFrom; t <= acrossTo; t += kProbeSearchStep) {
      float score = 0.f;
      for (int k = 1; k <= kProbePuddleLevels; ++k) {
        FrameState frame;
        frame.puddleLevel = kProbePuddleLevelStep * static_cast<float>(k);
        float covered = 1.f;
        for (glm::vec2 o : around) {
          float noise = weather::noiseAt(road.surfacePoint(s + o.x, t + o.y)).w;  // the puddle channel
          covered = std::min(covered, weather::puddleCoverage(frame, kUp, noise, 1.f));
        }
        score += covered;
      }
      if (score > bestScore) bestScore = score, best = {s, t};
    }
  }
  return best;
}

// The wettest spot of the first flat stretch, clear of its ends and the road's edges.
glm::vec2 flatRoadSpot(const RoadLayout& road) {
  float from = sectionStart(road, kRoadFlatStart) + kProbeMargin;
  float to = sectionStart(road, kRoadFlatStart) + road.sections[kRoadFlatStart].length - kProbeMargin;
  float edge = 0.5f * road.width - kProbeMargin;
  return wettestSpot(road, from, to, -edge, edge);
}

// Triangles of `mesh` whose centroid satisfies `keep`, as a compact mesh.
template <typename Pred>
Mesh selectTriangles(const Mesh& mesh, Pred keep) {
  Mesh out;
  std::vector<std::int64_t> remap(mesh.positions.size(), -1);
  for (std::size_t t = 0; t < triangleCount(mesh); ++t) {
    glm::vec3 c(0.f);
    for (int k = 0; k < 3; ++k) c += mesh.positions[mesh.indices[t * 3 + k]] / 3.f;
    if (!keep(c)) continue;
    for (int k = 0; k < 3; ++k) {
      std::uint32_t v = mesh.indices[t * 3 + k];
      if (remap[v] < 0) {
        remap[v] = static_cast<std::int64_t>(out.positions.size());
        out.positions.push_back(mesh.positions[v]);
        out.normals.push_back(mesh.normals[v]);
        out.tangents.push_back(mesh.tangents[v]);
        out.texcoords.push_back(mesh.texcoords[v]);
        out.colors.push_back(mesh.colors[v]);
      }
      out.indices.push_back(static_cast<std::uint32_t>(remap[v]));
    }
  }
  return out;
}

float hashUnit(std::uint32_t seed, std::int32_t stream) {
  return static_cast<float>(latticeHash(static_cast<std::int32_t>(seed), stream) >> 8) / 16777216.f;
}

// Eq. 3.8's range from the terrain ("MinHeight and MaxHeight are determined by the
// ground level and peak position of the terrain"), on every object: the ground level at
// f_height 0.5, where the default weights balance it (w3 = 2), and the peak at 0.75, so
// summits hold more snow and less moss (eq. 3.9) and level ground keeps the cover the
// weights give it (docs/weather-model.md, "Eq. 3.8-3.9: height").
void setTerrainHeightRange(Scene& scene) {
  const float ground = scene.terrainHeightOffset, relief = scene.terrainHeightScale;
  for (SceneObject& o : scene.objects) {
    o.parameters["weather.minHeight"] = ground - 2.f * relief;
    o.parameters["weather.maxHeight"] = ground + 2.f * relief;
  }
}

class SceneBuilder {
 public:
  SceneBuilder(std::string name, glm::vec3 towardsSun) {
    scene_.name = std::move(name);
    scene_.towardsSun = glm::normalize(towardsSun);
    scene_.hazeDistance = kHorizonHazeDistance;
  }

  const SceneObject& add(std::string name, std::string graph, Mesh mesh, glm::mat4 model = glm::mat4(1.f),
                         bool castsShadow = true, bool occludesSky = true) {
    world_.push_back(transformed(mesh, model));
    scene_.objects.push_back({std::move(name), std::move(graph), std::move(mesh), model, castsShadow, occludesSky});
    return scene_.objects.back();
  }

  // The height field, its height map, and (if `meadow` is given) the triangles it picks
  // split off as a "grass" object over the same surface.
  template <typename Pred>
  void terrain(float size, const HeightFn& height, Pred meadow) {
    Mesh ground = heightFieldTerrain(size, kTerrainResolution, height, kTerrainUvTiling);
    terrainSize_ = size;
    const int n = kTerrainResolution + 1;
    HorizonApronSettings apron;
    apron.uvTiling = kTerrainUvTiling;
    horizon_ = horizonApron(ground, n, [](float x, float z) { return hills(x, z, kHorizonHillWavelength, kHorizonHillHeight); },
                            apron);
    const float cell = size / kTerrainResolution;
    float lo = std::numeric_limits<float>::max(), hi = std::numeric_limits<float>::lowest();
    for (glm::vec3 p : ground.positions) {
      lo = std::min(lo, p.y);
      hi = std::max(hi, p.y);
    }
    scene_.terrainHeightResolution = n;
    scene_.terrainHeightOffset = lo;
    scene_.terrainHeightScale = std::max(hi - lo, 1e-3f);
    scene_.terrainHeights.resize(static_cast<std::size_t>(n) * n);
    // heightFieldTerrain lays vertices out row-major with rows along z, as the map is.
    for (std::size_t i = 0; i < scene_.terrainHeights.size(); ++i)
      scene_.terrainHeights[i] = (ground.positions[i].y - lo) / scene_.terrainHeightScale;
    // Texel centres on the vertices: the map covers one extra cell, half on each side.
    float origin = -0.5f * size - 0.5f * cell, extent = size + cell;
    scene_.terrainRegion = glm::vec4(origin, origin, 1.f / extent, 1.f / extent);

    Mesh grass = selectTriangles(ground, meadow);
    if (grass.positions.empty()) {
      add("terrain", "terrain", std::move(ground));
    } else {
      add("terrain", "terrain", selectTriangles(ground, [&](glm::vec3 c) { return !meadow(c); }));
      add("meadow", "grass", std::move(grass));
    }
  }

  // Height of the terrain mesh's surface (meadow included) at (x, z): the triangle of
  // the grid cell that holds the point, exactly as heightFieldTerrain splits it.
  float groundAt(float x, float z) const {
    const int n = scene_.terrainHeightResolution;
    if (n < 2) return 0.f;
    const float cell = terrainSize_ / static_cast<float>(n - 1);
    float gx = std::clamp((x + 0.5f * terrainSize_) / cell, 0.f, static_cast<float>(n - 1));
    float gz = std::clamp((z + 0.5f * terrainSize_) / cell, 0.f, static_cast<float>(n - 1));
    int i = std::min(static_cast<int>(gx), n - 2), j = std::min(static_cast<int>(gz), n - 2);
    float fx = gx - static_cast<float>(i), fz = gz - static_cast<float>(j);
    auto h = [&](int a, int c) {
      return scene_.terrainHeightOffset +
             scene_.terrainHeightScale * scene_.terrainHeights[static_cast<std::size_t>(c) * n + a];
    };
    if (fx + fz <= 1.f) return h(i, j) + fx * (h(i + 1, j) - h(i, j)) + fz * (h(i, j + 1) - h(i, j));
    return h(i + 1, j + 1) + (1.f - fx) * (h(i, j + 1) - h(i + 1, j + 1)) +
           (1.f - fz) * (h(i + 1, j) - h(i + 1, j + 1));
  }

  const Mesh& worldMesh(std::string_view object) const {
    for (std::size_t i = 0; i < scene_.objects.size(); ++i)
      if (scene_.objects[i].name == object) return world_[i];
    static const Mesh kEmpty;
    return kEmpty;
  }

  // A probe where the vertical line through (x, z) meets the top of `object`.
  void probeOnTop(std::string name, std::string expect, std::string object, float x, float z) {
    if (auto hit = topSurfaceAt(worldMesh(object), x, z))
      scene_.probes.push_back({std::move(name), hit->position, hit->normal, std::move(expect), std::move(object), {}});
  }
  // A probe at a vertex of `object`.
  void probeAt(std::string name, std::string expect, std::string object, std::size_t vertex) {
    const Mesh& m = worldMesh(object);
    scene_.probes.push_back({std::move(name), m.positions[vertex], m.normals[vertex], std::move(expect),
                             std::move(object), {}});
  }

  // A rock bedded into the ground at (x, z), turned by a seeded angle; returns its name.
  std::string rockAt(int index, float x, float z, float radius, std::uint32_t seed) {
    std::string name = "rock-" + std::to_string(index);
    float y = groundAt(x, z) + kRockRaise * radius;
    float yaw = hashUnit(seed, 11) * glm::two_pi<float>();
    glm::mat4 model = glm::rotate(glm::translate(glm::mat4(1.f), glm::vec3(x, y, z)), yaw, kUp);
    add(name, "rock", rock(seed, radius, kRockDetail), model);
    return name;
  }

  // Top, sun-side and shade-side probes of a rock. A side probe is the vertex facing
  // most nearly along (or against) the horizontal sun among those the given camera sees,
  // clear of the ground and on a steep face; cameras must be placed first.
  void rockProbes(const std::string& rockName, const std::string& prefix, const std::string& sunCamera,
                  const std::string& shadeCamera) {
    if (!scene_.find(rockName)) return;
    const Mesh& m = worldMesh(rockName);
    // The top: the highest vertex on a near-level face, else the most level vertex.
    std::optional<std::size_t> top;
    for (std::size_t v = 0; v < m.positions.size(); ++v)
      if (m.normals[v].y >= kRockTopMinUp && (!top || m.positions[v].y > m.positions[*top].y)) top = v;
    if (!top) {
      top = 0;
      for (std::size_t v = 1; v < m.positions.size(); ++v)
        if (m.normals[v].y > m.normals[*top].y) top = v;
    }
    probeAt(prefix + "top", "rock-top", rockName, *top);
    glm::vec3 sun = glm::normalize(glm::vec3(scene_.towardsSun.x, 0.f, scene_.towardsSun.z));
    for (float side : {1.f, -1.f}) {
      std::vector<std::pair<float, std::size_t>> candidates;
      for (std::size_t v = 0; v < m.positions.size(); ++v) {
        glm::vec3 p = m.positions[v], n = m.normals[v];
        if (std::abs(n.y) > kRockSideMaxUp || p.y < groundAt(p.x, p.z) + kRockSideClearance) continue;
        float alignment = side * glm::dot(n, sun);
        if (alignment >= kRockSideMinAlignment) candidates.push_back({-alignment, v});
      }
      if (candidates.empty()) continue;
      std::sort(candidates.begin(), candidates.end());
      const CameraPreset* cam = scene_.camera(side > 0.f ? sunCamera : shadeCamera);
      std::size_t chosen = candidates.front().second;
      for (const auto& [score, v] : candidates) {
        Probe trial{"", m.positions[v], m.normals[v], "", rockName, {}};
        if (cam && sees(*cam, trial)) {
          chosen = v;
          break;
        }
      }
      if (side > 0.f) probeAt(prefix + "sun-side", "rock-sun-side", rockName, chosen);
      else probeAt(prefix + "shade-side", "rock-shade-side", rockName, chosen);
    }
  }

  // A shelter whose footprint is centred on (x, z): posts grounded on the lowest ground
  // they stand on, roof kShelterClearance above the highest ground under it.
  glm::vec3 shelterAt(float x, float z, glm::vec2 size) {
    glm::vec3 centre(x, 0.f, z);
    float lowest = std::numeric_limits<float>::max();
    for (glm::vec2 p : shelterPostPositions(centre, size)) lowest = std::min(lowest, groundAt(p.x, p.y));
    float highest = std::numeric_limits<float>::lowest();
    for (int i = 0; i <= kShelterGroundSamples; ++i) {
      for (int j = 0; j <= kShelterGroundSamples; ++j) {
        float sx = x + size.x * (static_cast<float>(i) / kShelterGroundSamples - 0.5f);
        float sz = z + size.y * (static_cast<float>(j) / kShelterGroundSamples - 0.5f);
        highest = std::max(highest, groundAt(sx, sz));
        if (auto hit = topSurfaceAt(worldMesh("road"), sx, sz)) highest = std::max(highest, hit->position.y);
      }
    }
    centre.y = lowest;
    add("shelter", "rock", shelter(centre, size, highest + kShelterClearance - lowest));
    return centre;
  }

  void camera(std::string name, glm::vec3 eye, glm::vec3 target, float fovYDegrees) {
    scene_.cameras.push_back({std::move(name), eye, target, fovYDegrees});
  }

  Scene finish() {
    Bounds all;
    for (const Mesh& m : world_) all.include(bounds(m));
    scene_.boundsMin = all.min;
    scene_.boundsMax = all.max;
    markProbeVisibility(scene_, world_);
    // After the bounds and the probes' sight lines: the apron lies outside the one and
    // never between a camera and a probe.
    if (!horizon_.positions.empty()) {
      SceneObject apron{"horizon", "terrain", std::move(horizon_), glm::mat4(1.f), false, false};
      apron.horizon = true;
      scene_.objects.push_back(std::move(apron));
    }
    if (scene_.terrainHeightResolution > 0) setTerrainHeightRange(scene_);
    return std::move(scene_);
  }

 private:
  bool sees(const CameraPreset& c, const Probe& p) const { return cameraSees(c, p, world_); }

  Scene scene_;
  float terrainSize_ = 0.f;
  Mesh horizon_;  // the terrain's apron, added last
  std::vector<Mesh> world_;  // each object's mesh in world space
};

// Deterministic spots for card clumps: seeded candidates in a square, kept where
// `allowed` says, until `count` are found (or the candidates run out).
template <typename Pred>
std::vector<glm::vec2> scatter(std::uint32_t seed, float halfSize, int count, Pred allowed) {
  std::vector<glm::vec2> spots;
  constexpr int kCandidatesPerSpot = 40;
  for (int i = 0; i < count * kCandidatesPerSpot && static_cast<int>(spots.size()) < count; ++i) {
    glm::vec2 p((hashUnit(seed, 2 * i) * 2.f - 1.f) * halfSize, (hashUnit(seed, 2 * i + 1) * 2.f - 1.f) * halfSize);
    if (allowed(p)) spots.push_back(p);
  }
  return spots;
}

// Card clumps for bushes and grass tufts.
constexpr glm::vec2 kBushSize{2.2f, 1.8f};
constexpr int kBushCards = 3;
constexpr glm::vec2 kTuftSize{0.9f, 0.55f};
constexpr int kTuftCards = 2;
constexpr float kCardSink = 0.05f;  // cards start a little below ground: no floating edge

Mesh clumps(const SceneBuilder& b, const std::vector<glm::vec2>& spots, glm::vec2 size, int cards,
            std::uint32_t seed) {
  Mesh m;
  for (std::size_t i = 0; i < spots.size(); ++i) {
    glm::vec3 base(spots[i].x, b.groundAt(spots[i].x, spots[i].y) - kCardSink, spots[i].y);
    append(m, crossedCards(base, size, cards, seed + static_cast<std::uint32_t>(i)));
  }
  return m;
}

// ------------------------------------------------------------------------- valley

Scene valley() {
  constexpr float kSize = 160.f;
  // The river meanders along x; the valley floor rises gently for 35 m either side of
  // it, then the sides steepen to about 30 degrees (where the rocks lie).
  auto riverZ = [](float x) { return -8.f + 5.f * std::sin(x / 18.f); };
  auto natural = [riverZ](float x, float z) {
    float dz = std::abs(z - riverZ(x));
    constexpr float kFloor = 35.f;
    float floor = dz < kFloor ? 0.0025f * dz * dz : 0.0025f * kFloor * kFloor + 0.175f * (dz - kFloor);
    return floor + 12.f * smoothStep(32.f, 70.f, dz) + hills(x, z, 35.f, 6.f) * smoothStep(8.f, 30.f, dz);
  };
  River river = makeRiver(-kSize / 2, kSize / 2, riverZ, [](float) { return 0.f; });
  constexpr float kRoadZ = 16.f, kRoadStartX = -62.f;
  RoadLayout road = testRoad({kRoadStartX, 0.f, kRoadZ}, 26.f);
  road.start.y = natural(kRoadStartX, kRoadZ);
  auto height = [&](float x, float z) { return gradeRoad(road, x, z, river.carve(x, z, natural(x, z))); };

  SceneBuilder b("valley", {0.8f, 0.55f, -0.1f});
  // A meadow on the gently rising valley floor south of the river.
  constexpr glm::vec2 kMeadowCentre{8.f, -27.f}, kMeadowRadii{16.f, 5.f};
  auto inMeadow = [&](glm::vec2 p, float grow) {
    glm::vec2 e = (p - kMeadowCentre) / (kMeadowRadii + grow);
    return glm::dot(e, e) < 1.f;
  };
  b.terrain(kSize, height, [&](glm::vec3 c) {
    return inMeadow({c.x, c.z}, 0.f) && river.distance(c.x, c.z) > kChannelTopHalfWidth + kBankFlat &&
           roadDistance(road, c.x, c.z) > 2.f;
  });
  b.add("river", "river", river.water(), glm::mat4(1.f), false, true);
  b.add("road", "road", roadStrip(road));

  // Rocks on both valley sides, 47-58 m from the river, where the ground is steep.
  struct RockSpot {
    float x, z, radius;
  };
  constexpr std::array<RockSpot, 7> kRocks = {{{-40.f, 44.f, 2.2f},
                                               {-10.f, 47.f, 2.8f},
                                               {25.f, 44.f, 2.f},
                                               {50.f, 48.f, 2.5f},
                                               {-55.f, -60.f, 2.6f},
                                               {5.f, -61.f, 3.f},
                                               {38.f, -58.f, 2.2f}}};
  std::vector<std::string> rockNames;
  for (std::size_t i = 0; i < kRocks.size(); ++i)
    rockNames.push_back(b.rockAt(static_cast<int>(i), kRocks[i].x, kRocks[i].z, kRocks[i].radius,
                                 101u + static_cast<std::uint32_t>(i)));

  // The shelter stands over the flat stretch of road and the verge uphill of it.
  constexpr glm::vec2 kShelterSize{18.f, 12.f};
  const float shelterX = road.start.x + sectionMiddle(road, kRoadShelterSection);
  constexpr float kShelterZ = kRoadZ + 2.f;
  const glm::vec3 shelterBase = b.shelterAt(shelterX, kShelterZ, kShelterSize);
  const float roofTop = bounds(b.worldMesh("shelter")).max.y;

  auto clear = [&](glm::vec2 p, float margin) {
    if (river.distance(p.x, p.y) < kChannelTopHalfWidth + kBankFlat + margin) return false;
    if (roadDistance(road, p.x, p.y) < kRoadVergeFlat + margin) return false;
    if (std::abs(p.x - shelterX) < 0.5f * kShelterSize.x + margin &&
        std::abs(p.y - kShelterZ) < 0.5f * kShelterSize.y + margin)
      return false;
    for (const auto& r : kRocks)
      if (glm::distance(p, glm::vec2(r.x, r.z)) < r.radius * 1.4f + margin) return false;
    return std::abs(p.x) < 0.5f * kSize - 4.f && std::abs(p.y) < 0.5f * kSize - 4.f;
  };
  auto bushes = scatter(7u, 0.5f * kSize, 14, [&](glm::vec2 p) { return clear(p, 2.f); });
  b.add("bushes", "foliage", clumps(b, bushes, kBushSize, kBushCards, 300u), glm::mat4(1.f), true, false);
  // Grass tufts along the river banks and round the meadow.
  auto tufts = scatter(8u, 0.5f * kSize, 40, [&](glm::vec2 p) {
    return clear(p, 0.f) && (river.distance(p.x, p.y) < 16.f || inMeadow(p, 3.f));
  });
  b.add("grass-tufts", "foliage", clumps(b, tufts, kTuftSize, kTuftCards, 500u), glm::mat4(1.f), true, false);

  // Cameras.
  auto [riverPoint, riverRight] = river.frameNear(10.f);
  // Over the shoulder of a walker on the hillside, not from an aircraft: low enough for
  // the horizon and the sky, high enough to see the road and the shelter.
  b.camera("overview", {-35.f, 38.f, 80.f}, {-8.f, 2.f, 5.f}, 55.f);
  b.camera("aerial", {-40.f, 75.f, 115.f}, {-8.f, 3.f, 5.f}, 55.f);  // the whole valley from above
  glm::vec3 shelterTarget(shelterX, shelterBase.y + 1.5f, kShelterZ);
  b.camera("shelter", shelterTarget + glm::vec3(15.f, roofTop - shelterBase.y + 1.f, -14.f), shelterTarget, 50.f);
  b.camera("river", {riverPoint.x - 45.f, 5.f, riverZ(riverPoint.x - 45.f) + 12.f},
           {riverPoint.x, -0.5f, riverPoint.z}, 50.f);
  Bounds focus = bounds(b.worldMesh(rockNames[1]));
  glm::vec3 rockCentre = (focus.min + focus.max) * 0.5f;
  b.camera("rocks", rockCentre + glm::vec3(0.f, 8.f, -22.f), rockCentre, 50.f);
  // Eye level on the verge, across the road's puddles to a rock on the slope beyond,
  // clear of the shelter.
  Bounds far = bounds(b.worldMesh(rockNames[2]));
  const glm::vec3 farRock = (far.min + far.max) * 0.5f;
  const glm::vec2 verge(farRock.x - 6.f, kRoadZ - 12.f);
  b.camera("puddle", {verge.x, natural(verge.x, verge.y) + 2.f, verge.y}, farRock - glm::vec3(0.f, 6.f, 0.f), 45.f);

  // Probes.
  glm::vec2 dry = wettestSpot(road, shelterX - road.start.x - 0.5f * kShelterSize.x + kProbeRoofMargin,
                              shelterX - road.start.x + 0.5f * kShelterSize.x - kProbeRoofMargin,
                              kShelterZ - 0.5f * kShelterSize.y + kProbeRoofMargin - kRoadZ,
                              0.5f * kRoadWidth - kProbeMargin + 1.f);
  glm::vec3 dryPoint = road.surfacePoint(dry.x, dry.y);
  b.probeOnTop("shelter-road", "sheltered", "road", dryPoint.x, dryPoint.z);
  b.probeOnTop("shelter-ground", "sheltered", "terrain", shelterX, kRoadZ + 0.5f * kRoadWidth + 2.f);
  b.probeOnTop("roof-top", "open", "shelter", shelterX, kShelterZ);
  glm::vec3 wet = road.surfacePoint(flatRoadSpot(road).x, flatRoadSpot(road).y);
  b.probeOnTop("flat-road", "flat-road", "road", wet.x, wet.z);
  b.probeOnTop("sloped-road", "sloped-road", "road", road.start.x + sectionMiddle(road, kRoadRampSection), kRoadZ);
  b.probeOnTop("cambered-road", "sloped-road", "road", road.start.x + sectionMiddle(road, kRoadCamberSection),
               kRoadZ - 0.25f * kRoadWidth);
  // Level verge beside the same flat stretch, 3 m clear of the roof's edge.
  b.probeOnTop("open-ground", "open", "terrain", shelterX - 0.5f * kShelterSize.x - 3.f,
               kRoadZ + 0.5f * kRoadWidth + 2.f);
  b.probeOnTop("meadow", "open", "meadow", kMeadowCentre.x, kMeadowCentre.y);
  glm::vec3 bank = riverPoint - riverRight * kBankProbeOffset;
  b.probeOnTop("river-bank", "river-bank", "river", bank.x, bank.z);
  b.probeOnTop("river-centre", "river-centre", "river", riverPoint.x, riverPoint.z);
  b.rockProbes(rockNames[1], "rock-", "rocks", "rocks");
  return b.finish();
}

// -------------------------------------------------------------------------- rocks

Scene rocks() {
  constexpr float kSize = 120.f;
  // One long 31 degree slope falling towards +z, from about +36 m to -36 m, so rocks
  // sit near both ends of eq. 3.8's default height range [-50, 50].
  constexpr float kFall = 0.6f;
  auto height = [](float x, float z) { return -kFall * z + hills(x, z, 25.f, 3.f); };
  const glm::vec3 towardsSun(0.85f, 0.5f, 0.15f);
  SceneBuilder b("rocks", towardsSun);
  b.terrain(kSize, height, [](glm::vec3) { return false; });
  struct RockSpot {
    float x, z, radius;
  };
  // Big boulders, so their sun and shade sides cover plenty of pixels from afar.
  constexpr std::array<RockSpot, 7> kRocks = {{{-16.f, 50.f, 5.f},
                                               {16.f, 47.f, 4.f},
                                               {-14.f, -50.f, 5.f},
                                               {17.f, -47.f, 4.f},
                                               {0.f, 0.f, 5.5f},
                                               {-28.f, 20.f, 3.5f},
                                               {28.f, -20.f, 4.f}}};
  std::vector<std::string> names;
  for (std::size_t i = 0; i < kRocks.size(); ++i)
    names.push_back(
        b.rockAt(static_cast<int>(i), kRocks[i].x, kRocks[i].z, kRocks[i].radius, 201u + static_cast<std::uint32_t>(i)));

  // Cameras above the slope's top, so rock tops face them: from the foot of the slope,
  // and from the sun's side and the shade side.
  b.camera("front", {0.f, 48.f, 100.f}, {0.f, -6.f, 5.f}, 55.f);
  glm::vec3 sun = glm::normalize(glm::vec3(towardsSun.x, 0.f, towardsSun.z));
  b.camera("sun-side", sun * 112.f + glm::vec3(0.f, 50.f, 0.f), {0.f, 0.f, 0.f}, 60.f);
  b.camera("shade-side", -sun * 112.f + glm::vec3(0.f, 50.f, 0.f), {0.f, 0.f, 0.f}, 60.f);

  b.rockProbes(names[0], "low-rock-", "sun-side", "shade-side");
  b.rockProbes(names[2], "high-rock-", "sun-side", "shade-side");
  b.rockProbes(names[4], "middle-rock-", "sun-side", "shade-side");
  b.probeOnTop("slope", "open", "terrain", 10.f, 10.f);
  return b.finish();
}

// -------------------------------------------------------------------------- river

Scene riverScene() {
  constexpr float kSize = 80.f;
  auto riverZ = [](float x) { return 3.f * std::sin(x / 14.f); };
  auto natural = [riverZ](float x, float z) {
    float dz = std::abs(z - riverZ(x));
    return 0.004f * dz * dz + hills(x, z, 20.f, 1.5f) * smoothStep(8.f, 20.f, dz);
  };
  River river = makeRiver(-kSize / 2, kSize / 2, riverZ, [](float) { return 0.f; });
  SceneBuilder b("river", {0.3f, 0.6f, 0.74f});
  b.terrain(kSize, [&](float x, float z) { return river.carve(x, z, natural(x, z)); },
            [](glm::vec3) { return false; });
  b.add("river", "river", river.water(), glm::mat4(1.f), false, true);
  auto tufts = scatter(9u, 0.5f * kSize - 3.f, 30, [&](glm::vec2 p) {
    float d = river.distance(p.x, p.y);
    return d > kChannelTopHalfWidth + 0.8f && d < 14.f;
  });
  b.add("grass-tufts", "foliage", clumps(b, tufts, kTuftSize, kTuftCards, 700u), glm::mat4(1.f), true, false);

  auto [c, right] = river.frameNear(0.f);
  glm::vec3 left = c - right * kBankProbeOffset, rightBank = c + right * kBankProbeOffset;
  b.probeOnTop("river-bank-left", "river-bank", "river", left.x, left.z);
  b.probeOnTop("river-bank-right", "river-bank", "river", rightBank.x, rightBank.z);
  b.probeOnTop("river-centre", "river-centre", "river", c.x, c.z);
  glm::vec3 ground = c + right * (kChannelTopHalfWidth + 4.f);
  b.probeOnTop("bank-ground", "open", "terrain", ground.x, ground.z);

  b.camera("overhead", {0.f, 36.f, 4.f}, {0.f, 0.f, 0.f}, 50.f);
  b.camera("bank", {-22.f, 2.5f, riverZ(-22.f) + 10.f}, {8.f, -0.5f, riverZ(8.f)}, 50.f);
  return b.finish();
}

// --------------------------------------------------------------------------- road

Scene roadScene() {
  constexpr float kSize = 100.f;
  auto natural = [](float x, float z) { return hills(x, z, 30.f, 2.f); };
  RoadLayout road = testRoad({-45.f, 0.f, 0.f}, 24.f);
  road.start.y = natural(road.start.x, road.start.z);
  SceneBuilder b("road", {-0.4f, 0.7f, 0.6f});
  b.terrain(kSize, [&](float x, float z) { return gradeRoad(road, x, z, natural(x, z)); },
            [](glm::vec3) { return false; });
  b.add("road", "road", roadStrip(road));

  constexpr glm::vec2 kShelterSize{18.f, 12.f};
  constexpr float kShelterZ = 2.f;  // over the road and the verge on its right
  float shelterX = road.start.x + sectionMiddle(road, kRoadShelterSection);
  glm::vec3 base = b.shelterAt(shelterX, kShelterZ, kShelterSize);

  b.camera("overview", {35.f, 28.f, -42.f}, {-2.f, base.y, 0.f}, 55.f);
  // Standing under the roof, looking down the road past the shelter's far end.
  float shelterStart = road.start.x + sectionStart(road, kRoadShelterSection);
  b.camera("under-shelter", {shelterStart + 4.f, base.y + 1.6f, 1.5f},
           {shelterStart + 30.f, base.y + 0.3f, 0.f}, 60.f);

  glm::vec2 dry = wettestSpot(road, shelterX - road.start.x - 0.5f * kShelterSize.x + kProbeRoofMargin,
                              shelterX - road.start.x + 0.5f * kShelterSize.x - kProbeRoofMargin,
                              kShelterZ - 0.5f * kShelterSize.y + kProbeRoofMargin, 0.5f * kRoadWidth - kProbeMargin + 1.f);
  glm::vec3 dryPoint = road.surfacePoint(dry.x, dry.y);
  b.probeOnTop("under-shelter", "sheltered", "road", dryPoint.x, dryPoint.z);
  b.probeOnTop("shelter-ground", "sheltered", "terrain", shelterX, 0.5f * kRoadWidth + 2.f);
  b.probeOnTop("roof-top", "open", "shelter", shelterX, kShelterZ);
  glm::vec3 wet = road.surfacePoint(flatRoadSpot(road).x, flatRoadSpot(road).y);
  b.probeOnTop("flat-road", "flat-road", "road", wet.x, wet.z);
  b.probeOnTop("sloped-road", "sloped-road", "road", road.start.x + sectionMiddle(road, kRoadRampSection), 0.f);
  b.probeOnTop("cambered-road", "sloped-road", "road", road.start.x + sectionMiddle(road, kRoadCamberSection),
               -0.25f * kRoadWidth);
  // South of the road, away from the roof.
  b.probeOnTop("open-ground", "open", "terrain", shelterX, -(0.5f * kRoadWidth + kRoadVergeFlat + 4.f));
  return b.finish();
}

}  // namespace

const SceneObject* Scene::find(std::string_view objectName) const {
  for (const auto& o : objects)
    if (o.name == objectName) return &o;
  return nullptr;
}

const CameraPreset* Scene::camera(std::string_view cameraName) const {
  for (const auto& c : cameras)
    if (c.name == cameraName) return &c;
  return nullptr;
}

Bounds Scene::framedBounds() const {
  if (subject) return *subject;
  Bounds b;
  b.include(boundsMin);
  b.include(boundsMax);
  return b;
}

namespace {
// The bundled scenes: --scene's names, the CLI's help, list-scenes and the scripts
// that render every scene all read this table.
struct SceneEntry {
  std::string_view name;
  Scene (*build)();
  std::string_view summary;
};
constexpr std::array<SceneEntry, 4> kScenes = {{
    {"valley", valley, "a river valley: a road, a shelter, rocks, bushes and grass tufts"},
    {"rocks", rocks, "rocks on a slope"},
    {"river", riverScene, "a meandering river between grassy banks"},
    {"road", roadScene, "a road past a shelter"},
}};
}  // namespace

std::vector<std::string_view> sceneNames() {
  std::vector<std::string_view> names;
  for (const SceneEntry& s : kScenes) names.push_back(s.name);
  return names;
}

std::string_view sceneSummary(std::string_view name) {
  for (const SceneEntry& s : kScenes)
    if (s.name == name) return s.summary;
  return {};
}

std::optional<Scene> makeScene(std::string_view name) {
  for (const SceneEntry& s : kScenes)
    if (s.name == name) return s.build();
  return std::nullopt;
}

}  // namespace wg::scene
