#include "host/scene/shapes.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <utility>

#include "nodes/lattice_noise.hpp"

namespace wg::scene {

namespace {
constexpr glm::vec3 kUp{0.f, 1.f, 0.f};
constexpr float kPi = 3.14159265358979f;

// A face frame: outward normal n and in-plane axes with cross(u, v) = n, so uv
// projected onto (u, v) is never mirrored.
struct FaceFrame {
  glm::vec3 n, u, v;
};
constexpr std::array<FaceFrame, 6> kAxisFrames = {{
    {{1.f, 0.f, 0.f}, {0.f, 0.f, -1.f}, {0.f, 1.f, 0.f}},
    {{-1.f, 0.f, 0.f}, {0.f, 0.f, 1.f}, {0.f, 1.f, 0.f}},
    {{0.f, 1.f, 0.f}, {1.f, 0.f, 0.f}, {0.f, 0.f, -1.f}},
    {{0.f, -1.f, 0.f}, {1.f, 0.f, 0.f}, {0.f, 0.f, 1.f}},
    {{0.f, 0.f, 1.f}, {1.f, 0.f, 0.f}, {0.f, 1.f, 0.f}},
    {{0.f, 0.f, -1.f}, {-1.f, 0.f, 0.f}, {0.f, 1.f, 0.f}},
}};

// The axis frame whose normal is closest to direction d.
int dominantAxis(glm::vec3 d) {
  glm::vec3 a = glm::abs(d);
  if (a.x >= a.y && a.x >= a.z) return d.x >= 0.f ? 0 : 1;
  if (a.y >= a.z) return d.y >= 0.f ? 2 : 3;
  return d.z >= 0.f ? 4 : 5;
}

// A deterministic number in [0, 1) from a seed and a stream index.
float hashUnit(std::uint32_t seed, std::int32_t stream) {
  return static_cast<float>(latticeHash(static_cast<std::int32_t>(seed), stream) >> 8) / 16777216.f;
}
}  // namespace

// ---------------------------------------------------------------------------- box

Mesh box(glm::vec3 min, glm::vec3 max) {
  Mesh m;
  glm::vec3 centre = (min + max) * 0.5f, half = (max - min) * 0.5f;
  for (const FaceFrame& f : kAxisFrames) {
    glm::vec3 c = centre + f.n * glm::dot(glm::abs(f.n), half);
    glm::vec3 eu = f.u * glm::dot(glm::abs(f.u), half), ev = f.v * glm::dot(glm::abs(f.v), half);
    std::array<std::uint32_t, 4> q{};
    const std::array<glm::vec2, 4> corners = {{{-1.f, -1.f}, {1.f, -1.f}, {1.f, 1.f}, {-1.f, 1.f}}};
    for (int k = 0; k < 4; ++k) {
      glm::vec3 p = c + eu * corners[k].x + ev * corners[k].y;
      q[k] = addVertex(m, p, f.n, {glm::dot(p, f.u), glm::dot(p, f.v)});
    }
    addQuadFacing(m, q[0], q[1], q[2], q[3], f.n);
  }
  computeTangents(m);
  return m;
}

// ------------------------------------------------------------------ sphere

Mesh sphere(float radius, int cells) {
  Mesh m;
  const int n = std::max(cells, 1);
  constexpr float kQuarterPi = 0.25f * kPi;
  for (const FaceFrame& f : kAxisFrames) {
    auto base = static_cast<std::uint32_t>(m.positions.size());
    for (int j = 0; j <= n; ++j) {
      for (int i = 0; i <= n; ++i) {
        // Equal angles across the face, so cells are nearly equal on the sphere.
        float a = kQuarterPi * (2.f * i / n - 1.f), b = kQuarterPi * (2.f * j / n - 1.f);
        glm::vec3 d = glm::normalize(f.n + std::tan(a) * f.u + std::tan(b) * f.v);
        addVertex(m, d * radius, d, glm::vec2(a, b) * radius);
      }
    }
    auto idx = [&](int i, int j) { return base + static_cast<std::uint32_t>(j * (n + 1) + i); };
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        glm::vec3 centre = m.positions[idx(i, j)] + m.positions[idx(i + 1, j + 1)];
        addQuadFacing(m, idx(i, j), idx(i + 1, j), idx(i + 1, j + 1), idx(i, j + 1), centre);
      }
  }
  computeTangents(m);
  return m;
}

// ------------------------------------------------------------- rounded box

namespace {
// Coordinates across one face, from -half to half: the bevel sampled at equal angles at
// both ends, the flat middle as one span.
std::vector<float> roundedFaceCoordinates(float half, float radius, int steps) {
  std::vector<float> at;
  for (int k = 0; k <= steps; ++k) at.push_back(-half + radius * (1.f - std::cos(0.5f * kPi * k / steps)));
  for (int k = steps; k >= 0; --k) at.push_back(half - radius * (1.f - std::cos(0.5f * kPi * k / steps)));
  return at;
}
}  // namespace

Mesh roundedBox(glm::vec3 min, glm::vec3 max, float radius, int bevelSteps) {
  Mesh m;
  const glm::vec3 centre = 0.5f * (min + max), half = 0.5f * (max - min);
  const float r = std::clamp(radius, 0.f, std::min({half.x, half.y, half.z}));
  const int steps = std::max(bevelSteps, 1);
  for (const FaceFrame& f : kAxisFrames) {
    float halfU = glm::dot(glm::abs(f.u), half), halfV = glm::dot(glm::abs(f.v), half);
    auto us = roundedFaceCoordinates(halfU, r, steps), vs = roundedFaceCoordinates(halfV, r, steps);
    auto base = static_cast<std::uint32_t>(m.positions.size());
    for (float v : vs) {
      for (float u : us) {
        // A point on the sharp box's face, pulled onto the rounded surface round the
        // inner box (the box shrunk by r), whose nearest point it is.
        glm::vec3 q = f.n * glm::dot(glm::abs(f.n), half) + f.u * u + f.v * v;
        glm::vec3 inner = glm::clamp(q, -(half - r), half - r);
        glm::vec3 n = glm::length(q - inner) > 0.f ? glm::normalize(q - inner) : f.n;
        addVertex(m, centre + inner + n * r, n, {u, v});
      }
    }
    const auto columns = static_cast<std::uint32_t>(us.size());
    for (std::uint32_t j = 0; j + 1 < vs.size(); ++j)
      for (std::uint32_t i = 0; i + 1 < columns; ++i) {
        std::uint32_t a = base + j * columns + i;
        if (glm::distance(m.positions[a], m.positions[a + 1]) == 0.f ||
            glm::distance(m.positions[a], m.positions[a + columns]) == 0.f)
          continue;  // the zero-width middle span of a face no wider than its bevels
        addQuadFacing(m, a, a + 1, a + 1 + columns, a + columns, f.n);
      }
  }
  computeTangents(m);
  return m;
}

// -------------------------------------------------------------------- ramp

namespace {
// A flat polygon (3 or 4 corners in order) facing `normal`, uv in metres on its plane.
void addFlatFace(Mesh& m, const std::vector<glm::vec3>& corners, glm::vec3 normal) {
  glm::vec3 u = std::abs(normal.y) > 0.9f ? glm::vec3(1.f, 0.f, 0.f) : glm::normalize(glm::cross(kUp, normal));
  glm::vec3 v = glm::cross(normal, u);
  std::vector<std::uint32_t> q;
  for (glm::vec3 p : corners) q.push_back(addVertex(m, p, normal, {glm::dot(p, u), glm::dot(p, v)}));
  if (q.size() == 3) addTriangleFacing(m, q[0], q[1], q[2], normal);
  else addQuadFacing(m, q[0], q[1], q[2], q[3], normal);
}
}  // namespace

namespace {
// A point of a rounded convex outline in a (z, y) profile: the corner of the outline
// shrunk by the radius, and the outward normal there.
struct OutlinePoint {
  glm::vec2 inner, normal;
};

// The outline of a convex polygon (corners in order) with every corner rounded by r:
// each corner's arc, steps + 1 normals from one edge's to the next's.
std::vector<OutlinePoint> roundedOutline(const std::vector<glm::vec2>& corners, float r, int steps) {
  const std::size_t n = corners.size();
  glm::vec2 centroid(0.f);
  for (glm::vec2 c : corners) centroid += c / float(n);
  std::vector<glm::vec2> edgeNormal(n);
  for (std::size_t i = 0; i < n; ++i) {
    glm::vec2 d = corners[(i + 1) % n] - corners[i], normal = glm::normalize(glm::vec2(d.y, -d.x));
    edgeNormal[i] = glm::dot(normal, 0.5f * (corners[i] + corners[(i + 1) % n]) - centroid) < 0.f ? -normal : normal;
  }
  std::vector<OutlinePoint> outline;
  for (std::size_t i = 0; i < n; ++i) {
    glm::vec2 from = edgeNormal[(i + n - 1) % n], to = edgeNormal[i];
    glm::vec2 inner = corners[i] - r * (from + to) / (1.f + glm::dot(from, to));  // r from both edges
    float a0 = std::atan2(from.y, from.x), turn = std::remainder(std::atan2(to.y, to.x) - a0, 2.f * kPi);
    for (int k = 0; k <= steps; ++k) {
      float a = a0 + turn * float(k) / float(steps);
      outline.push_back({inner, {std::cos(a), std::sin(a)}});
    }
  }
  return outline;
}

// Adds triangle a, b, c unless it has no area (where a rounded corner closes to a point).
void addTriangleIfAny(Mesh& m, std::uint32_t a, std::uint32_t b, std::uint32_t c, glm::vec3 outward) {
  glm::vec3 cross = glm::cross(m.positions[b] - m.positions[a], m.positions[c] - m.positions[a]);
  if (glm::length(cross) > 1e-10f) addTriangleFacing(m, a, b, c, outward);
}

// A convex (z, y) profile extruded along x over `width`, every edge and corner rounded
// by r: a band round the outline, a quarter-turn band at each end, and flat end faces.
// Bands run round the outline once more to its first point, so their v (the length
// along the outline) never wraps.
Mesh roundedPrism(const std::vector<glm::vec2>& profile, float width, float r, int steps) {
  Mesh m;
  auto outline = roundedOutline(profile, r, steps);
  outline.push_back(outline.front());
  const float a = 0.5f * width - r;
  std::vector<float> along(1, 0.f);  // length of the outline so far
  for (std::size_t j = 1; j < outline.size(); ++j)
    along.push_back(along.back() + glm::distance(outline[j].inner + r * outline[j].normal,
                                                 outline[j - 1].inner + r * outline[j - 1].normal));
  // A row round the outline at x, turned by (cos, sin) from the profile plane towards x.
  auto row = [&](float x, float c, float s, float side, bool planarUv) {
    std::vector<std::uint32_t> ids;
    for (std::size_t j = 0; j < outline.size(); ++j) {
      const OutlinePoint& p = outline[j];
      glm::vec3 normal(side * s, c * p.normal.y, c * p.normal.x);
      glm::vec3 position = glm::vec3(x, p.inner.y, p.inner.x) + r * normal;
      glm::vec2 uv = planarUv ? glm::vec2(position.z, position.y) : glm::vec2(position.x, along[j]);
      ids.push_back(addVertex(m, position, normal, uv));
    }
    return ids;
  };
  auto band = [&](const std::vector<std::uint32_t>& lo, const std::vector<std::uint32_t>& hi) {
    for (std::size_t j = 0; j + 1 < lo.size(); ++j) {
      glm::vec3 outward = m.normals[lo[j]] + m.normals[lo[j + 1]] + m.normals[hi[j]] + m.normals[hi[j + 1]];
      addTriangleIfAny(m, lo[j], lo[j + 1], hi[j + 1], outward);
      addTriangleIfAny(m, lo[j], hi[j + 1], hi[j], outward);
    }
  };
  band(row(-a, 1.f, 0.f, 1.f, false), row(a, 1.f, 0.f, 1.f, false));
  for (float side : {-1.f, 1.f}) {
    std::vector<std::uint32_t> previous = row(side * a, 1.f, 0.f, side, true);
    for (int k = 1; k <= steps; ++k) {
      float turn = 0.5f * kPi * float(k) / float(steps);
      auto next = k == steps ? row(side * a, 0.f, 1.f, side, true) : row(side * a, std::cos(turn), std::sin(turn), side, true);
      band(previous, next);
      previous = std::move(next);
    }
    // The end face: the outline's corners on the last row, one per corner arc.
    for (std::size_t i = 1; i + 1 < profile.size(); ++i)
      addTriangleIfAny(m, previous[0], previous[i * (steps + 1)], previous[(i + 1) * (steps + 1)], {side, 0.f, 0.f});
  }
  computeTangents(m);
  return m;
}
}  // namespace

Mesh ramp(glm::vec3 size, float edgeRadius, int bevelSteps) {
  const float x = 0.5f * size.x, z = 0.5f * size.z, h = size.y;
  if (edgeRadius > 0.f) {
    float r = std::min({edgeRadius, 0.25f * size.x, 0.25f * size.y, 0.25f * size.z});
    return roundedPrism({{z, 0.f}, {-z, 0.f}, {-z, h}}, size.x, r, std::max(bevelSteps, 1));
  }
  Mesh m;
  addFlatFace(m, {{-x, 0.f, -z}, {x, 0.f, -z}, {x, 0.f, z}, {-x, 0.f, z}}, -kUp);
  addFlatFace(m, {{-x, 0.f, -z}, {x, 0.f, -z}, {x, h, -z}, {-x, h, -z}}, {0.f, 0.f, -1.f});
  addFlatFace(m, {{-x, 0.f, z}, {x, 0.f, z}, {x, h, -z}, {-x, h, -z}}, glm::normalize(glm::vec3(0.f, size.z, h)));
  for (float side : {-1.f, 1.f})
    addFlatFace(m, {{side * x, 0.f, z}, {side * x, 0.f, -z}, {side * x, h, -z}}, {side, 0.f, 0.f});
  computeTangents(m);
  return m;
}

// ---------------------------------------------------------------- height field

Mesh heightFieldTerrain(float size, int resolution, const HeightFn& heightFn, float uvTiling) {
  Mesh m;
  const int n = std::max(resolution, 1) + 1;  // vertices per side
  const float cell = size / static_cast<float>(n - 1);
  const float origin = -0.5f * size;
  std::vector<float> h(static_cast<std::size_t>(n) * n);
  auto at = [&](int i, int j) -> float& { return h[static_cast<std::size_t>(j) * n + i]; };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) at(i, j) = heightFn(origin + i * cell, origin + j * cell);
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      // Central differences of the samples (one-sided at the border): the slope of the
      // mesh itself, not of a finer heightFn the grid cannot show.
      int i0 = std::max(i - 1, 0), i1 = std::min(i + 1, n - 1);
      int j0 = std::max(j - 1, 0), j1 = std::min(j + 1, n - 1);
      float dx = (at(i1, j) - at(i0, j)) / ((i1 - i0) * cell);
      float dz = (at(i, j1) - at(i, j0)) / ((j1 - j0) * cell);
      glm::vec3 p(origin + i * cell, at(i, j), origin + j * cell);
      addVertex(m, p, glm::vec3(-dx, 1.f, -dz), glm::vec2(p.x, p.z) / uvTiling);
    }
  }
  for (int j = 0; j + 1 < n; ++j) {
    for (int i = 0; i + 1 < n; ++i) {
      auto idx = [&](int a, int b) { return static_cast<std::uint32_t>(b * n + a); };
      // Counter-clockwise from above: +z then +x is a left turn seen from +y.
      m.indices.insert(m.indices.end(), {idx(i, j), idx(i, j + 1), idx(i + 1, j)});
      m.indices.insert(m.indices.end(), {idx(i + 1, j), idx(i, j + 1), idx(i + 1, j + 1)});
    }
  }
  computeTangents(m);
  return m;
}

// ------------------------------------------------------------------------ rock

namespace {
// Boulder shape: ellipsoid axes drawn per seed (flatter than tall, like weathered stone).
constexpr glm::vec3 kRockAxesMin{0.95f, 0.62f, 0.85f};
constexpr glm::vec3 kRockAxesMax{1.25f, 0.82f, 1.15f};
// Broad lumps: fraction of the radius, frequency on the unit sphere, octaves.
constexpr float kRockLumpiness = 0.45f;
constexpr float kRockLumpFrequency = 1.7f;
constexpr int kRockLumpOctaves = 2;
// Fine grain on top of the facets (so they are not perfectly flat).
constexpr float kRockGrain = 0.05f;
constexpr float kRockGrainFrequency = 7.f;
constexpr int kRockGrainOctaves = 2;
// Fractured faces: planes cutting the lumpy ellipsoid at a fraction of its extent in
// their direction, plus a flatter base so the rock beds into the ground.
constexpr int kRockFacets = 6;
constexpr float kRockFacetDepthMin = 0.55f, kRockFacetDepthMax = 0.8f;
constexpr float kRockBaseDepth = 0.6f;
// Seeds move the noise domain by up to this many lattice cells.
constexpr float kRockSeedOffset = 97.f;
// Texture tiling of the cube-projected uv (metres per uv unit).
constexpr float kRockUvTiling = 2.f;

// 3D noise from three orthogonal 2D lookups, continuous on the sphere.
float noise3(glm::vec3 p) {
  return (gradientNoise(p.x, p.y) + gradientNoise(p.y + 31.7f, p.z) + gradientNoise(p.z + 71.3f, p.x + 11.9f)) /
         3.f;
}

float rockFbm(glm::vec3 p, int octaves) {
  float sum = 0.f, amplitude = 1.f, norm = 0.f;
  for (int o = 0; o < octaves; ++o) {
    sum += amplitude * (noise3(p) - 0.5f);
    norm += amplitude;
    p = p * 2.03f + glm::vec3(5.1f, 1.3f, 7.7f);  // non-integer factor: octaves do not align
    amplitude *= 0.5f;
  }
  return sum / norm;  // centred on 0
}

struct Icosphere {
  std::vector<glm::vec3> dirs;
  std::vector<std::uint32_t> indices;
};

Icosphere icosphere(int detail) {
  const float t = (1.f + std::sqrt(5.f)) * 0.5f;
  Icosphere s;
  s.dirs = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t},
            {0, -1, -t}, {0, 1, -t}, {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
  for (auto& d : s.dirs) d = glm::normalize(d);
  s.indices = {0, 11, 5, 0, 5, 1, 0, 1, 7, 0, 7, 10, 0, 10, 11, 1, 5, 9, 5, 11, 4, 11, 10, 2, 10, 7, 6, 7, 1, 8,
               3, 9, 4, 3, 4, 2, 3, 2, 6, 3, 6, 8, 3, 8, 9, 4, 9, 5, 2, 4, 11, 6, 2, 10, 8, 6, 7, 9, 8, 1};
  for (int level = 0; level < detail; ++level) {
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> midpoints;
    auto midpoint = [&](std::uint32_t a, std::uint32_t b) {
      auto key = std::minmax(a, b);
      auto [it, inserted] = midpoints.try_emplace(key, static_cast<std::uint32_t>(s.dirs.size()));
      if (inserted) s.dirs.push_back(glm::normalize(s.dirs[a] + s.dirs[b]));
      return it->second;
    };
    std::vector<std::uint32_t> next;
    next.reserve(s.indices.size() * 4);
    for (std::size_t f = 0; f < s.indices.size(); f += 3) {
      std::uint32_t a = s.indices[f], b = s.indices[f + 1], c = s.indices[f + 2];
      std::uint32_t ab = midpoint(a, b), bc = midpoint(b, c), ca = midpoint(c, a);
      next.insert(next.end(), {a, ab, ca, b, bc, ab, c, ca, bc, ab, bc, ca});
    }
    s.indices = std::move(next);
  }
  return s;
}
}  // namespace

Mesh rock(std::uint32_t seed, float radius, int detail) {
  Icosphere sphere = icosphere(std::clamp(detail, 0, 6));
  const glm::vec3 axes = glm::mix(kRockAxesMin, kRockAxesMax,
                                  glm::vec3(hashUnit(seed, 1), hashUnit(seed, 2), hashUnit(seed, 3)));
  const glm::vec3 offset = glm::vec3(hashUnit(seed, 4), hashUnit(seed, 5), hashUnit(seed, 6)) * kRockSeedOffset;

  // Cutting planes: seeded directions (uniform on the sphere) and the flat base.
  struct Facet {
    glm::vec3 normal;
    float depth;
  };
  std::vector<Facet> facets;
  auto extent = [&](glm::vec3 n) { return radius * glm::length(axes * n); };  // ellipsoid support
  for (int k = 0; k < kRockFacets; ++k) {
    float z = hashUnit(seed, 20 + 3 * k) * 2.f - 1.f, phi = hashUnit(seed, 21 + 3 * k) * 2.f * kPi;
    glm::vec3 n(std::sqrt(1.f - z * z) * std::cos(phi), z, std::sqrt(1.f - z * z) * std::sin(phi));
    facets.push_back({n, extent(n) * glm::mix(kRockFacetDepthMin, kRockFacetDepthMax, hashUnit(seed, 22 + 3 * k))});
  }
  facets.push_back({-kUp, extent(-kUp) * kRockBaseDepth});

  // Displace the shared (welded) sphere and take smooth normals there, so the chart
  // split below does not crease the shading. Every step moves points along their own
  // ray from the centre, so the surface stays star-shaped and never folds over.
  Mesh shared;
  for (glm::vec3 d : sphere.dirs) {
    glm::vec3 p = d * axes * (radius * (1.f + kRockLumpiness * rockFbm(d * kRockLumpFrequency + offset, kRockLumpOctaves)));
    for (const Facet& f : facets) {
      float reach = glm::dot(p, f.normal);
      if (reach > f.depth) p *= f.depth / reach;
    }
    p *= 1.f + kRockGrain * rockFbm(d * kRockGrainFrequency + glm::vec3(offset.z, offset.x, offset.y), kRockGrainOctaves);
    shared.positions.push_back(p);
  }
  shared.indices = sphere.indices;
  computeNormals(shared);

  // Each triangle goes to the cube chart its displaced face faces (a facet cut turns a
  // side of the sphere upwards, and projecting it along its old axis streaks the
  // texture); vertices used by several charts are duplicated, one per chart.
  Mesh m;
  std::map<std::pair<std::uint32_t, int>, std::uint32_t> chartVertex;
  for (std::size_t f = 0; f < sphere.indices.size(); f += 3) {
    int chart = dominantAxis(faceNormal(shared, f / 3));
    const FaceFrame& frame = kAxisFrames[chart];
    for (int k = 0; k < 3; ++k) {
      std::uint32_t v = sphere.indices[f + k];
      auto [it, inserted] = chartVertex.try_emplace({v, chart}, static_cast<std::uint32_t>(m.positions.size()));
      if (inserted) {
        glm::vec3 p = shared.positions[v];
        addVertex(m, p, shared.normals[v], glm::vec2(glm::dot(p, frame.u), glm::dot(p, frame.v)) / kRockUvTiling);
      }
      m.indices.push_back(it->second);
    }
  }
  computeTangents(m);
  return m;
}

// ----------------------------------------------------------------------- river

namespace {
// Quads across the river: v is interpolated exactly by one, but a few keep the
// per-vertex lighting of a wide strip smooth.
constexpr int kRiverAcrossQuads = 4;

struct Polyline {
  std::vector<glm::vec3> points;
  std::vector<float> lengths;  // cumulative

  explicit Polyline(const std::vector<glm::vec3>& p) : points(p) {
    lengths.push_back(0.f);
    for (std::size_t i = 1; i < points.size(); ++i) lengths.push_back(lengths.back() + glm::distance(points[i - 1], points[i]));
  }
  float length() const { return lengths.back(); }
  glm::vec3 at(float s) const {
    s = std::clamp(s, 0.f, length());
    auto it = std::upper_bound(lengths.begin(), lengths.end(), s);
    std::size_t i = std::min<std::size_t>(static_cast<std::size_t>(it - lengths.begin()), points.size() - 1);
    if (i == 0) return points.front();
    float span = lengths[i] - lengths[i - 1];
    float t = span > 0.f ? (s - lengths[i - 1]) / span : 0.f;
    return glm::mix(points[i - 1], points[i], t);
  }
};
}  // namespace

Mesh riverStrip(const std::vector<glm::vec3>& centreline, float width, int segments) {
  Mesh m;
  if (centreline.size() < 2) return m;
  Polyline line(centreline);
  segments = std::max(segments, 1);
  const float step = line.length() / static_cast<float>(segments);
  std::vector<std::uint32_t> previous;
  for (int i = 0; i <= segments; ++i) {
    float s = step * static_cast<float>(i);
    glm::vec3 c = line.at(s);
    // Central difference along the line (one-sided at the ends) for the flow direction.
    glm::vec3 ahead = line.at(s + 0.5f * step), behind = line.at(s - 0.5f * step);
    glm::vec3 flow = glm::normalize(ahead - behind);
    glm::vec3 right = glm::normalize(glm::cross(flow, kUp));
    glm::vec3 normal = glm::normalize(glm::cross(right, flow));
    std::vector<std::uint32_t> row;
    for (int j = 0; j <= kRiverAcrossQuads; ++j) {
      float v = static_cast<float>(j) / kRiverAcrossQuads;
      glm::vec3 p = c + right * ((v - 0.5f) * width);
      row.push_back(addVertex(m, p, normal, {s / width, v}));
    }
    if (!previous.empty()) {
      for (int j = 0; j < kRiverAcrossQuads; ++j)
        addQuadFacing(m, previous[j], previous[j + 1], row[j + 1], row[j], normal);
    }
    previous = std::move(row);
  }
  computeTangents(m);
  return m;
}

// ------------------------------------------------------------------------ road

namespace {
// Road surface pieces are at most this long, so coverage can be measured per triangle.
constexpr float kRoadStep = 1.f;
// Quads from the crown to each edge.
constexpr int kRoadHalfQuads = 2;
}  // namespace

float RoadLayout::length() const {
  float total = 0.f;
  for (const auto& s : sections) total += s.length;
  return total;
}

glm::vec3 RoadLayout::forward() const { return glm::normalize(glm::vec3(direction.x, 0.f, direction.y)); }

glm::vec3 RoadLayout::right() const { return glm::normalize(glm::cross(forward(), kUp)); }

glm::vec2 RoadLayout::toRoad(glm::vec2 xz) const {
  glm::vec3 d(xz.x - start.x, 0.f, xz.y - start.z);
  return {glm::dot(d, forward()), glm::dot(d, right())};
}

int RoadLayout::sectionAt(float along) const {
  float s0 = 0.f;
  for (std::size_t k = 0; k < sections.size(); ++k) {
    if (along < s0 + sections[k].length) return static_cast<int>(k);
    s0 += sections[k].length;
  }
  return static_cast<int>(sections.size()) - 1;
}

float RoadLayout::centreHeight(float along) const {
  along = std::clamp(along, 0.f, length());
  float y = start.y, s0 = 0.f;
  for (const auto& s : sections) {
    float rise = std::tan(glm::radians(s.gradeDegrees));
    if (along <= s0 + s.length) return y + rise * (along - s0);
    y += rise * s.length;
    s0 += s.length;
  }
  return y;
}

float RoadLayout::camberDegreesAt(float along) const {
  along = std::clamp(along, 0.f, length());
  float s0 = 0.f;
  for (std::size_t k = 0; k < sections.size(); ++k) {
    const auto& s = sections[k];
    float before = k == 0 ? s.camberDegrees : sections[k - 1].camberDegrees;
    if (along <= s0 + s.length) {
      float t = s.length > 0.f ? (along - s0) / s.length : 1.f;
      return before + (s.camberDegrees - before) * t;
    }
    s0 += s.length;
  }
  return sections.empty() ? 0.f : sections.back().camberDegrees;
}

float RoadLayout::surfaceHeight(float along, float across) const {
  across = std::clamp(across, -0.5f * width, 0.5f * width);
  return centreHeight(along) - std::tan(glm::radians(camberDegreesAt(along))) * std::abs(across);
}

glm::vec3 RoadLayout::surfacePoint(float along, float across) const {
  glm::vec3 p = start + forward() * along + right() * across;
  p.y = surfaceHeight(along, across);
  return p;
}

Mesh roadStrip(const RoadLayout& road, float skirtDepth) {
  Mesh m;
  const glm::vec3 fwd = road.forward(), right = road.right();
  const float halfWidth = 0.5f * road.width;
  auto uvAt = [&](float along, float across) { return glm::vec2(across / road.width + 0.5f, along / road.width); };

  // Top surface, section by section and half by half: own vertices, so section borders
  // (grade changes) and the crown are hard edges and a flat section is exactly flat.
  std::vector<float> stations;  // every section border and step, for the skirts
  float s0 = 0.f;
  for (std::size_t k = 0; k < road.sections.size(); ++k) {
    const RoadSection& sec = road.sections[k];
    const float before = k == 0 ? sec.camberDegrees : road.sections[k - 1].camberDegrees;
    const float camberRate = glm::radians(sec.camberDegrees - before) / std::max(sec.length, 1e-6f);
    const float grade = std::tan(glm::radians(sec.gradeDegrees));
    const int steps = std::max(1, static_cast<int>(std::ceil(sec.length / kRoadStep)));
    for (int i = 0; i <= steps; ++i) {
      float s = s0 + sec.length * static_cast<float>(i) / steps;
      if (stations.empty() || s > stations.back()) stations.push_back(s);
    }
    for (float side : {-1.f, 1.f}) {
      std::vector<std::uint32_t> previous;
      for (int i = 0; i <= steps; ++i) {
        float s = s0 + sec.length * static_cast<float>(i) / steps;
        float camber = glm::radians(before) + camberRate * (s - s0);
        std::vector<std::uint32_t> row;
        for (int j = 0; j <= kRoadHalfQuads; ++j) {
          float across = side * halfWidth * static_cast<float>(j) / kRoadHalfQuads;
          glm::vec3 p = road.start + fwd * s + right * across;
          p.y = road.centreHeight(s) - std::tan(camber) * std::abs(across);
          // Analytic normal of y(s, t) = centre(s) - tan(camber(s)) |t| in this section.
          float dyds = grade - camberRate / (std::cos(camber) * std::cos(camber)) * std::abs(across);
          float dydt = -std::tan(camber) * side;
          glm::vec3 n = glm::normalize(glm::cross(right + kUp * dydt, fwd + kUp * dyds));
          row.push_back(addVertex(m, p, n, uvAt(s, across)));
        }
        if (!previous.empty()) {
          for (int j = 0; j < kRoadHalfQuads; ++j)
            addQuadFacing(m, previous[j], previous[j + 1], row[j + 1], row[j], kUp);
        }
        previous = std::move(row);
      }
    }
    s0 += sec.length;
  }

  // Side skirts: vertical strips hanging from both edges, facing outwards.
  for (float side : {-1.f, 1.f}) {
    glm::vec3 outward = right * side;
    std::vector<std::uint32_t> previous;
    for (float s : stations) {
      glm::vec3 top = road.surfacePoint(s, side * halfWidth);
      glm::vec3 bottom = top - kUp * skirtDepth;
      std::uint32_t a = addVertex(m, top, outward, {s / road.width, 0.f});
      std::uint32_t b = addVertex(m, bottom, outward, {s / road.width, skirtDepth / road.width});
      if (!previous.empty()) addQuadFacing(m, previous[0], previous[1], b, a, outward);
      previous = {a, b};
    }
  }
  // End caps: the cross-section (crowned top, flat bottom) at both ends.
  for (float end : {0.f, road.length()}) {
    glm::vec3 outward = end == 0.f ? -fwd : fwd;
    glm::vec3 lt = road.surfacePoint(end, -halfWidth), ct = road.surfacePoint(end, 0.f),
              rt = road.surfacePoint(end, halfWidth);
    glm::vec3 lb = lt - kUp * skirtDepth, rb = rt - kUp * skirtDepth;
    auto capUv = [&](glm::vec3 p) {
      return glm::vec2(glm::dot(p - ct, right) / road.width + 0.5f, (ct.y - p.y) / road.width);
    };
    std::uint32_t iLt = addVertex(m, lt, outward, capUv(lt)), iCt = addVertex(m, ct, outward, capUv(ct)),
                  iRt = addVertex(m, rt, outward, capUv(rt)), iRb = addVertex(m, rb, outward, capUv(rb)),
                  iLb = addVertex(m, lb, outward, capUv(lb));
    addTriangleFacing(m, iLb, iLt, iCt, outward);
    addTriangleFacing(m, iLb, iCt, iRt, outward);
    addTriangleFacing(m, iLb, iRt, iRb, outward);
  }
  computeTangents(m);
  return m;
}

// ----------------------------------------------------------------------- cards

namespace {
// Cards turn by up to this fraction of their even spacing, so clumps do not repeat.
constexpr float kCardAngleJitter = 0.3f;
}  // namespace

Mesh crossedCards(glm::vec3 center, glm::vec2 size, int count, std::uint32_t seed) {
  Mesh m;
  count = std::max(count, 1);
  const float spacing = kPi / static_cast<float>(count);
  const float base = hashUnit(seed, 0) * kPi;
  for (int k = 0; k < count; ++k) {
    float angle = base + spacing * (static_cast<float>(k) + kCardAngleJitter * (hashUnit(seed, k + 1) - 0.5f));
    glm::vec3 along(std::cos(angle), 0.f, std::sin(angle));
    glm::vec3 facing = glm::cross(along, kUp);
    glm::vec3 half = along * (0.5f * size.x), up = kUp * size.y;
    const std::array<glm::vec3, 4> corners = {center - half, center + half, center + half + up, center - half + up};
    const std::array<glm::vec2, 4> uvs = {{{0.f, 0.f}, {1.f, 0.f}, {1.f, 1.f}, {0.f, 1.f}}};
    std::array<std::uint32_t, 4> q{};
    for (int c = 0; c < 4; ++c) q[c] = addVertex(m, corners[c], facing, uvs[c]);
    addQuadFacing(m, q[0], q[1], q[2], q[3], facing);
  }
  computeTangents(m);
  return m;
}

// --------------------------------------------------------------------- shelter

std::vector<glm::vec2> shelterPostPositions(glm::vec3 center, glm::vec2 size) {
  glm::vec2 offset = size * 0.5f - glm::vec2(kShelterPostInset + 0.5f * kShelterPostWidth);
  std::vector<glm::vec2> posts;
  for (float sz : {-1.f, 1.f})
    for (float sx : {-1.f, 1.f}) posts.push_back(glm::vec2(center.x, center.z) + offset * glm::vec2(sx, sz));
  return posts;
}

Mesh shelter(glm::vec3 center, glm::vec2 size, float height) {
  Mesh m;
  const float underside = center.y + height;
  append(m, box(glm::vec3(center.x - 0.5f * size.x, underside, center.z - 0.5f * size.y),
                glm::vec3(center.x + 0.5f * size.x, underside + kShelterRoofThickness, center.z + 0.5f * size.y)));
  const glm::vec2 halfPost(0.5f * kShelterPostWidth);
  for (glm::vec2 p : shelterPostPositions(center, size)) {
    append(m, box(glm::vec3(p.x - halfPost.x, center.y - kShelterFooting, p.y - halfPost.y),
                  glm::vec3(p.x + halfPost.x, underside, p.y + halfPost.y)));
  }
  return m;
}

}  // namespace wg::scene
