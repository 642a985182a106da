// The bundled validation scenes: deterministic, well-formed meshes (unit normals,
// orthogonal tangents, front faces outward), and the geometry each weather test needs
// (river v from bank to bank, flat and tilted road, a shelter over road and ground,
// probes on surfaces and in view, rocks at both ends of the height range).
#include "host/scene/scene.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "host/scene/mesh.hpp"
#include "host/scene/shapes.hpp"

namespace wg::scene {
namespace {

constexpr std::size_t kTriangleBudget = 150000;
constexpr float kUnitTolerance = 1e-3f;
constexpr float kMinTriangleArea = 1e-6f;  // m^2
constexpr double kMinConsistentWinding = 0.99;
constexpr float kProbeTolerance = 0.01f;  // m
constexpr glm::vec3 kUp{0.f, 1.f, 0.f};

const Scene& cached(const std::string& name) {
  static std::map<std::string, Scene> scenes;
  auto it = scenes.find(name);
  if (it == scenes.end()) {
    auto s = makeScene(name);
    EXPECT_TRUE(s.has_value()) << name;
    it = scenes.emplace(name, s ? std::move(*s) : Scene{}).first;
  }
  return it->second;
}

Mesh worldMesh(const SceneObject& o) { return transformed(o.mesh, o.model); }

template <typename T>
void put(std::string& out, const std::vector<T>& v) {
  std::size_t n = v.size();
  out.append(reinterpret_cast<const char*>(&n), sizeof n);
  if (n) out.append(reinterpret_cast<const char*>(v.data()), n * sizeof(T));
}
template <typename T>
void putValue(std::string& out, const T& v) {
  out.append(reinterpret_cast<const char*>(&v), sizeof v);
}

std::string serialise(const Scene& s) {
  std::string out = s.name;
  for (const auto& o : s.objects) {
    out += o.name + "|" + o.graph + "|";
    put(out, o.mesh.positions);
    put(out, o.mesh.normals);
    put(out, o.mesh.tangents);
    put(out, o.mesh.texcoords);
    put(out, o.mesh.colors);
    put(out, o.mesh.indices);
    putValue(out, o.model);
    putValue(out, o.castsShadow);
    putValue(out, o.occludesSky);
  }
  for (const auto& c : s.cameras) {
    out += c.name;
    putValue(out, c.eye);
    putValue(out, c.target);
    putValue(out, c.fovYDegrees);
  }
  for (const auto& p : s.probes) {
    out += p.name + p.expect + p.object;
    putValue(out, p.position);
    putValue(out, p.normal);
    for (const auto& c : p.visibleFrom) out += c;
  }
  putValue(out, s.towardsSun);
  putValue(out, s.boundsMin);
  putValue(out, s.boundsMax);
  putValue(out, s.terrainRegion);
  putValue(out, s.terrainHeightResolution);
  put(out, s.terrainHeights);
  putValue(out, s.terrainHeightScale);
  putValue(out, s.terrainHeightOffset);
  return out;
}

// Ericson, Real-Time Collision Detection, 5.1.5.
glm::vec3 closestOnTriangle(glm::vec3 p, glm::vec3 a, glm::vec3 b, glm::vec3 c) {
  glm::vec3 ab = b - a, ac = c - a, ap = p - a;
  float d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
  if (d1 <= 0.f && d2 <= 0.f) return a;
  glm::vec3 bp = p - b;
  float d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
  if (d3 >= 0.f && d4 <= d3) return b;
  float vc = d1 * d4 - d3 * d2;
  if (vc <= 0.f && d1 >= 0.f && d3 <= 0.f) return a + ab * (d1 / (d1 - d3));
  glm::vec3 cp = p - c;
  float d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
  if (d6 >= 0.f && d5 <= d6) return c;
  float vb = d5 * d2 - d1 * d6;
  if (vb <= 0.f && d2 >= 0.f && d6 <= 0.f) return a + ac * (d2 / (d2 - d6));
  float va = d3 * d6 - d5 * d4;
  if (va <= 0.f && (d4 - d3) >= 0.f && (d5 - d6) >= 0.f) return b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)));
  float denom = 1.f / (va + vb + vc);
  return a + ab * (vb * denom) + ac * (vc * denom);
}

float distanceToMesh(const Mesh& m, glm::vec3 p) {
  float best = std::numeric_limits<float>::max();
  for (std::size_t t = 0; t < triangleCount(m); ++t) {
    glm::vec3 q = closestOnTriangle(p, m.positions[m.indices[t * 3]], m.positions[m.indices[t * 3 + 1]],
                                    m.positions[m.indices[t * 3 + 2]]);
    best = std::min(best, glm::distance(p, q));
  }
  return best;
}

float triangleArea(const Mesh& m, std::size_t t) { return 0.5f * glm::length(faceNormal(m, t)); }
glm::vec3 centroid(const Mesh& m, std::size_t t) {
  return (m.positions[m.indices[t * 3]] + m.positions[m.indices[t * 3 + 1]] + m.positions[m.indices[t * 3 + 2]]) / 3.f;
}
float tiltDegrees(glm::vec3 n) { return glm::degrees(std::acos(std::clamp(glm::normalize(n).y, -1.f, 1.f))); }

double signedVolume(const Mesh& m) {
  double v = 0.0;
  for (std::size_t t = 0; t < triangleCount(m); ++t) {
    glm::dvec3 a = m.positions[m.indices[t * 3]], b = m.positions[m.indices[t * 3 + 1]], c = m.positions[m.indices[t * 3 + 2]];
    v += glm::dot(a, glm::cross(b, c)) / 6.0;
  }
  return v;
}

// Closed and consistently wound once vertices at the same position are welded: every
// directed edge has exactly one partner running the other way.
bool closedAndConsistent(const Mesh& m) {
  std::map<std::tuple<float, float, float>, int> weld;
  std::vector<int> id(m.positions.size());
  for (std::size_t i = 0; i < m.positions.size(); ++i) {
    auto key = std::make_tuple(m.positions[i].x, m.positions[i].y, m.positions[i].z);
    id[i] = weld.try_emplace(key, static_cast<int>(weld.size())).first->second;
  }
  std::map<std::pair<int, int>, int> edges;
  for (std::size_t t = 0; t < triangleCount(m); ++t)
    for (int k = 0; k < 3; ++k) ++edges[{id[m.indices[t * 3 + k]], id[m.indices[t * 3 + (k + 1) % 3]]}];
  for (const auto& [e, count] : edges) {
    if (count != 1) return false;
    auto back = edges.find({e.second, e.first});
    if (back == edges.end() || back->second != 1) return false;
  }
  return true;
}

// Any surface of the scene straight above p (starting 1 cm up, so p's own surface is not it)?
std::optional<std::string> coveredBy(const Scene& s, glm::vec3 p) {
  for (const auto& o : s.objects)
    if (raycast(worldMesh(o), p + kUp * kProbeTolerance, kUp)) return o.name;
  return std::nullopt;
}

void expectWellFormed(const Mesh& m, const std::string& what) {
  const std::size_t n = m.positions.size();
  ASSERT_GT(n, 0u) << what;
  ASSERT_EQ(m.normals.size(), n) << what;
  ASSERT_EQ(m.tangents.size(), n) << what;
  ASSERT_EQ(m.texcoords.size(), n) << what;
  ASSERT_EQ(m.colors.size(), n) << what;
  ASSERT_EQ(m.indices.size() % 3, 0u) << what;
  for (std::uint32_t i : m.indices) ASSERT_LT(i, n) << what;
  for (std::size_t i = 0; i < n; ++i) {
    glm::vec3 nn = m.normals[i];
    glm::vec4 t = m.tangents[i];
    ASSERT_NEAR(glm::length(nn), 1.f, kUnitTolerance) << what << " vertex " << i;
    ASSERT_NEAR(glm::length(glm::vec3(t)), 1.f, kUnitTolerance) << what << " vertex " << i;
    ASSERT_LT(std::abs(glm::dot(nn, glm::vec3(t))), kUnitTolerance) << what << " vertex " << i;
    ASSERT_TRUE(t.w == 1.f || t.w == -1.f) << what << " vertex " << i;
    ASSERT_TRUE(std::isfinite(m.positions[i].x) && std::isfinite(m.positions[i].y) && std::isfinite(m.positions[i].z));
  }
  std::size_t consistent = 0;
  for (std::size_t t = 0; t < triangleCount(m); ++t) {
    ASSERT_GT(triangleArea(m, t), kMinTriangleArea) << what << " triangle " << t;
    glm::vec3 avg = m.normals[m.indices[t * 3]] + m.normals[m.indices[t * 3 + 1]] + m.normals[m.indices[t * 3 + 2]];
    if (glm::dot(faceNormal(m, t), avg) > 0.f) ++consistent;
  }
  EXPECT_GE(static_cast<double>(consistent), kMinConsistentWinding * static_cast<double>(triangleCount(m))) << what;
}

// ------------------------------------------------------------------ mesh helpers

// One table names the scenes: each name builds the scene of that name and has a summary
// (list-scenes prints it), and no other name builds anything.
TEST(SceneTable, EveryNameBuildsItsSceneAndHasASummary) {
  ASSERT_EQ(sceneNames().size(), 4u);
  for (auto name : sceneNames()) {
    EXPECT_EQ(cached(std::string(name)).name, name);
    EXPECT_FALSE(sceneSummary(name).empty()) << name;
  }
  EXPECT_FALSE(makeScene("snowfield").has_value());  // the interactive snowfield is the CLI's own
  EXPECT_TRUE(sceneSummary("nope").empty());
}

TEST(SceneMesh, TangentsFollowUvWithHandedness) {
  Mesh quad;
  // A floor quad with u along +x and v along +z: bitangent +z = -cross(up, +x), so w = -1.
  for (glm::vec2 c : {glm::vec2(0, 0), glm::vec2(1, 0), glm::vec2(1, 1), glm::vec2(0, 1)})
    addVertex(quad, {c.x, 0.f, c.y}, kUp, c);
  addQuadFacing(quad, 0, 1, 2, 3, kUp);
  computeTangents(quad);
  for (const glm::vec4& t : quad.tangents) {
    EXPECT_NEAR(t.x, 1.f, 1e-6f);
    EXPECT_EQ(t.w, -1.f);
  }
  EXPECT_GT(faceNormal(quad, 0).y, 0.f);
  EXPECT_GT(faceNormal(quad, 1).y, 0.f);
}

TEST(SceneMesh, AppendKeepsFacesFrontFacingUnderMirroring) {
  Mesh b = box({0, 0, 0}, {1, 2, 3});
  Mesh mirrored = transformed(b, glm::scale(glm::mat4(1.f), glm::vec3(-1.f, 1.f, 1.f)));
  EXPECT_NEAR(signedVolume(mirrored), 6.0, 1e-4);
  EXPECT_TRUE(closedAndConsistent(mirrored));
  expectWellFormed(mirrored, "mirrored box");
  for (std::size_t i = 0; i < b.tangents.size(); ++i) EXPECT_EQ(mirrored.tangents[i].w, -b.tangents[i].w);
  Bounds bb = bounds(mirrored);
  EXPECT_EQ(bb.min, glm::vec3(-1.f, 0.f, 0.f));
  EXPECT_EQ(bb.max, glm::vec3(0.f, 2.f, 3.f));
}

TEST(SceneMesh, RaycastFindsNearestHitAndInterpolates) {
  Mesh b = box({-1, 0, -1}, {1, 1, 1});
  auto hit = raycast(b, {0.f, 5.f, 0.f}, {0.f, -1.f, 0.f});
  ASSERT_TRUE(hit);
  EXPECT_NEAR(hit->position.y, 1.f, 1e-5f);
  EXPECT_NEAR(hit->distance, 4.f, 1e-5f);
  EXPECT_NEAR(hit->normal.y, 1.f, 1e-6f);
  EXPECT_FALSE(raycast(b, {3.f, 5.f, 0.f}, {0.f, -1.f, 0.f}));
  auto top = topSurfaceAt(b, 0.5f, 0.5f);
  ASSERT_TRUE(top);
  EXPECT_NEAR(top->position.y, 1.f, 1e-5f);
}

// ------------------------------------------------------------------------ shapes

TEST(SceneShapes, BoxesAndShelterAreClosedWithOutwardNormals) {
  Mesh b = box({1, 2, 3}, {2, 4, 6});
  expectWellFormed(b, "box");
  EXPECT_TRUE(closedAndConsistent(b));
  EXPECT_NEAR(signedVolume(b), 6.0, 1e-4);
  EXPECT_EQ(triangleCount(b), 12u);

  Mesh s = shelter({0.f, 1.f, 0.f}, {8.f, 6.f}, 3.f);
  expectWellFormed(s, "shelter");
  EXPECT_EQ(triangleCount(s), 5u * 12u);  // roof + 4 posts
  Bounds sb = bounds(s);
  EXPECT_NEAR(sb.max.y, 1.f + 3.f + kShelterRoofThickness, 1e-5f);
  EXPECT_NEAR(sb.min.y, 1.f - kShelterFooting, 1e-5f);
  // Each of the five boxes is closed: the welded shelter is closed as a whole too,
  // since posts only touch the roof.
  for (std::size_t k = 0; k < 5; ++k) {
    Mesh part;
    part.positions.assign(s.positions.begin() + k * 24, s.positions.begin() + (k + 1) * 24);
    part.normals.assign(s.normals.begin() + k * 24, s.normals.begin() + (k + 1) * 24);
    for (std::size_t i = k * 36; i < (k + 1) * 36; ++i) part.indices.push_back(s.indices[i] - k * 24);
    EXPECT_TRUE(closedAndConsistent(part)) << "box " << k;
    EXPECT_GT(signedVolume(part), 0.0) << "box " << k;
  }
}

TEST(SceneShapes, SphereLiesOnItsRadiusWithRadialNormals) {
  constexpr float kRadius = 1.5f;
  Mesh m = sphere(kRadius, 8);
  expectWellFormed(m, "sphere");
  for (std::size_t i = 0; i < m.positions.size(); ++i) {
    ASSERT_NEAR(glm::length(m.positions[i]), kRadius, 1e-4f);
    ASSERT_LT(glm::distance(m.normals[i], m.positions[i] / kRadius), 1e-4f);
  }
  // Flat facets cut a little off the true sphere.
  double volume = 4.0 / 3.0 * 3.14159265 * kRadius * kRadius * kRadius;
  EXPECT_GT(signedVolume(m), 0.97 * volume);
  EXPECT_LT(signedVolume(m), volume);
}

TEST(SceneShapes, RoundedBoxIsClosedWithinItsCornersAndSmoothAcrossEdges) {
  glm::vec3 lo{-1.f, 0.f, -0.5f}, hi{1.f, 0.2f, 0.5f};
  constexpr float kBevel = 0.08f;
  Mesh m = roundedBox(lo, hi, kBevel);
  expectWellFormed(m, "rounded box");
  EXPECT_TRUE(closedAndConsistent(m));
  Bounds b = bounds(m);
  EXPECT_LT(glm::distance(b.min, lo), 1e-5f);
  EXPECT_LT(glm::distance(b.max, hi), 1e-5f);
  double full = 2.0 * 0.2 * 1.0;
  EXPECT_LT(signedVolume(m), full);
  EXPECT_GT(signedVolume(m), 0.9 * full);
  // Vertices at one position share one normal: a displacement along it cannot tear.
  std::map<std::tuple<float, float, float>, glm::vec3> normalAt;
  for (std::size_t i = 0; i < m.positions.size(); ++i) {
    auto [it, inserted] = normalAt.try_emplace({m.positions[i].x, m.positions[i].y, m.positions[i].z}, m.normals[i]);
    ASSERT_LT(glm::distance(it->second, m.normals[i]), 1e-5f) << "vertex " << i;
  }
}

TEST(SceneShapes, RampRisesAtItsAngleFromTheFrontEdge) {
  Mesh m = ramp({2.f, 1.f, 1.f});
  expectWellFormed(m, "ramp");
  EXPECT_TRUE(closedAndConsistent(m));
  EXPECT_NEAR(signedVolume(m), 2.0 * 1.0 * 1.0 / 2.0, 1e-4);
  auto top = topSurfaceAt(m, 0.f, 0.f);  // halfway up the slope
  ASSERT_TRUE(top);
  EXPECT_NEAR(top->position.y, 0.5f, 1e-5f);
  EXPECT_NEAR(tiltDegrees(top->normal), 45.f, 1e-3f);
  EXPECT_GT(top->normal.z, 0.f);  // the slope faces +z
}

TEST(SceneShapes, RoundedRampKeepsItsBoundsAndSlopeAndNeverTears) {
  Mesh m = ramp({2.f, 1.f, 1.f}, 0.1f);
  expectWellFormed(m, "rounded ramp");
  EXPECT_TRUE(closedAndConsistent(m));
  Bounds b = bounds(m);
  EXPECT_LT(glm::distance(b.min, glm::vec3(-1.f, 0.f, -0.5f)), 1e-5f);
  // The 45 degree corners (the slope's ends) recede more than the radius.
  EXPECT_NEAR(b.max.x, 1.f, 1e-5f);
  EXPECT_GT(b.max.y, 0.8f);
  EXPECT_LT(b.max.y, 1.f);
  EXPECT_GT(b.max.z, 0.3f);
  EXPECT_LT(b.max.z, 0.5f);
  auto slope = topSurfaceAt(m, 0.f, 0.f);  // the flat middle of the slope keeps its plane
  ASSERT_TRUE(slope);
  EXPECT_NEAR(slope->position.y, 0.5f, 1e-5f);
  EXPECT_LT(signedVolume(m), 1.0);
  EXPECT_GT(signedVolume(m), 0.85);
  EXPECT_NEAR(tiltDegrees(slope->normal), 45.f, 1e-3f);
  std::map<std::tuple<float, float, float>, glm::vec3> normalAt;
  for (std::size_t i = 0; i < m.positions.size(); ++i) {
    auto [it, inserted] = normalAt.try_emplace({m.positions[i].x, m.positions[i].y, m.positions[i].z}, m.normals[i]);
    ASSERT_LT(glm::distance(it->second, m.normals[i]), 1e-4f) << "vertex " << i;
  }
}

TEST(SceneShapes, RocksAreClosedSeededAndDeterministic) {
  Mesh a = rock(7, 2.f, 3), again = rock(7, 2.f, 3), other = rock(8, 2.f, 3);
  expectWellFormed(a, "rock");
  EXPECT_EQ(triangleCount(a), 20u * 64u);
  EXPECT_TRUE(closedAndConsistent(a));
  EXPECT_GT(signedVolume(a), 0.0);
  EXPECT_EQ(std::memcmp(a.positions.data(), again.positions.data(), a.positions.size() * sizeof(glm::vec3)), 0);
  EXPECT_NE(a.positions, other.positions);
  Bounds b = bounds(a);
  EXPECT_GT(b.max.x - b.min.x, 2.f);  // roughly radius-sized, not collapsed
  EXPECT_LT(b.max.x - b.min.x, 8.f);
}

// A rock's texture is cube-projected per triangle, so a triangle projected along an axis
// its face does not face stretches the texture into streaks: uv area per world area falls
// towards 0. On the chart its face normal picks, it stays within a factor sqrt(3).
TEST(SceneShapes, RockTextureChartsFollowTheDisplacedFaces) {
  for (std::uint32_t seed : {1u, 7u, 8u, 23u}) {
    Mesh m = rock(seed, 2.f, 3);
    double least = 1e30, most = 0.0;
    for (std::size_t t = 0; t < triangleCount(m); ++t) {
      std::uint32_t i = m.indices[t * 3], j = m.indices[t * 3 + 1], k = m.indices[t * 3 + 2];
      double world = glm::length(faceNormal(m, t));
      glm::vec2 du = m.texcoords[j] - m.texcoords[i], dv = m.texcoords[k] - m.texcoords[i];
      double uv = std::abs(du.x * dv.y - du.y * dv.x);
      if (world < 1e-8) continue;
      least = std::min(least, uv / world);
      most = std::max(most, uv / world);
    }
    EXPECT_LE(most / least, std::sqrt(3.0) * 1.001) << "seed " << seed;
  }
}

TEST(SceneShapes, RoadMeshFollowsItsLayout) {
  RoadLayout road;
  road.start = {-10.f, 2.f, 5.f};
  road.sections = {{6.f, 0.f, 0.f}, {4.f, 14.f, 0.f}, {4.f, 0.f, 10.f}, {6.f, 0.f, 10.f}, {4.f, 0.f, 0.f}};
  Mesh m = roadStrip(road);
  expectWellFormed(m, "road");
  for (float along : {1.f, 3.f, 8.f, 12.f, 17.f, 21.f}) {
    for (float across : {-2.5f, -1.f, 0.5f, 2.f}) {
      glm::vec3 p = road.surfacePoint(along, across);
      auto hit = topSurfaceAt(m, p.x, p.z);
      ASSERT_TRUE(hit) << along << ", " << across;
      EXPECT_NEAR(hit->position.y, p.y, 0.02f) << along << ", " << across;
      // u runs across from the left edge.
      EXPECT_NEAR(hit->texcoord.x, across / road.width + 0.5f, 1e-3f);
    }
  }
  EXPECT_NEAR(road.centreHeight(8.f) - road.centreHeight(6.f), 2.f * std::tan(glm::radians(14.f)), 1e-5f);
  EXPECT_NEAR(road.camberDegreesAt(12.f), 5.f, 1e-4f);  // ramping in
  EXPECT_NEAR(road.camberDegreesAt(17.f), 10.f, 1e-4f);
  EXPECT_NEAR(road.camberDegreesAt(22.f), 5.f, 1e-4f);  // and out
}

TEST(SceneShapes, RiverStripRunsVAcrossFromLeftToRightBank) {
  std::vector<glm::vec3> line = {{0, 0, 0}, {10, -0.1f, 0}, {20, -0.2f, 3}};
  Mesh m = riverStrip(line, 8.f, 20);
  expectWellFormed(m, "river");
  for (std::size_t i = 0; i < m.positions.size(); ++i) {
    EXPECT_GE(m.texcoords[i].y, 0.f);
    EXPECT_LE(m.texcoords[i].y, 1.f);
  }
  // Looking downstream (+x) the left bank is at -z: v = 0 there.
  auto left = topSurfaceAt(m, 2.f, -3.9f), right = topSurfaceAt(m, 2.f, 3.9f);
  ASSERT_TRUE(left && right);
  EXPECT_NEAR(left->texcoord.y, 0.5f - 3.9f / 8.f, 1e-3f);
  EXPECT_NEAR(right->texcoord.y, 0.5f + 3.9f / 8.f, 1e-3f);
}

TEST(SceneShapes, CrossedCardsStandOnTheirCentre) {
  Mesh m = crossedCards({1.f, 2.f, 3.f}, {2.f, 1.5f}, 3, 42);
  expectWellFormed(m, "cards");
  EXPECT_EQ(triangleCount(m), 6u);
  Bounds b = bounds(m);
  EXPECT_NEAR(b.min.y, 2.f, 1e-6f);
  EXPECT_NEAR(b.max.y, 3.5f, 1e-6f);
  for (glm::vec2 uv : m.texcoords) {
    EXPECT_TRUE(uv.x == 0.f || uv.x == 1.f);
    EXPECT_TRUE(uv.y == 0.f || uv.y == 1.f);
  }
  for (glm::vec3 n : m.normals) EXPECT_NEAR(n.y, 0.f, 1e-6f);
}

// ------------------------------------------------------------------------ scenes

TEST(Scenes, NamesAndUnknownScene) {
  std::vector<std::string_view> names = sceneNames();
  EXPECT_EQ(names, (std::vector<std::string_view>{"valley", "rocks", "river", "road"}));
  EXPECT_FALSE(makeScene("nope").has_value());
  EXPECT_FALSE(makeScene("").has_value());
}

class EachScene : public ::testing::TestWithParam<std::string> {
 protected:
  const Scene& scene() const { return cached(GetParam()); }
  std::vector<const SceneObject*> withGraph(const std::string& graph) const {
    std::vector<const SceneObject*> out;
    for (const auto& o : scene().objects)
      if (o.graph == graph) out.push_back(&o);
    return out;
  }
  const Probe* probe(const std::string& name) const {
    for (const auto& p : scene().probes)
      if (p.name == name) return &p;
    return nullptr;
  }
};

TEST_P(EachScene, IsDeterministic) {
  auto again = makeScene(GetParam());
  ASSERT_TRUE(again);
  std::string a = serialise(scene()), b = serialise(*again);
  EXPECT_EQ(a.size(), b.size());
  EXPECT_TRUE(a == b);
}

TEST_P(EachScene, MeshesAreWellFormed) {
  for (const auto& o : scene().objects) {
    SCOPED_TRACE(o.name);
    expectWellFormed(o.mesh, o.name);
    expectWellFormed(worldMesh(o), o.name + " (world)");
  }
}

TEST_P(EachScene, StaysWithinTheTriangleBudget) {
  std::size_t total = 0;
  for (const auto& o : scene().objects) total += triangleCount(o.mesh);
  EXPECT_LE(total, kTriangleBudget);
  EXPECT_GT(total, 1000u);
}

TEST_P(EachScene, UsesBundledGraphs) {
  const std::set<std::string> kGraphs = {"rock", "terrain", "grass", "foliage", "river", "road", "snowfield"};
  std::set<std::string> names;
  for (const auto& o : scene().objects) {
    EXPECT_TRUE(kGraphs.count(o.graph)) << o.name << ": " << o.graph;
    EXPECT_TRUE(std::filesystem::exists(std::filesystem::path(WG_SOURCE_DIR) / "graphs" / (o.graph + ".json")))
        << o.graph;
    EXPECT_TRUE(names.insert(o.name).second) << "duplicate object " << o.name;
    if (o.graph == "foliage") {
      EXPECT_FALSE(o.occludesSky) << o.name;
    }
  }
  ASSERT_FALSE(withGraph("terrain").empty());
}

// Eq. 3.8's MinHeight and MaxHeight come from the terrain, not a fixed -50..50 m: its
// ground level lies mid-range and its peak at three quarters, on every object.
TEST_P(EachScene, TheHeightRangeComesFromTheTerrain) {
  const Scene& s = scene();
  Bounds terrain = bounds(worldMesh(*s.find("terrain")));
  if (const SceneObject* meadow = s.find("meadow")) terrain.include(bounds(worldMesh(*meadow)));
  for (const auto& o : s.objects) {
    SCOPED_TRACE(o.name);
    ASSERT_TRUE(o.parameters.count("weather.minHeight") && o.parameters.count("weather.maxHeight"));
    const float lo = o.parameters.at("weather.minHeight"), hi = o.parameters.at("weather.maxHeight");
    EXPECT_NEAR((terrain.min.y - lo) / (hi - lo), 0.5f, 0.001f);
    EXPECT_NEAR((terrain.max.y - lo) / (hi - lo), 0.75f, 0.001f);
  }
}

TEST_P(EachScene, SunBoundsAndCameras) {
  const Scene& s = scene();
  EXPECT_NEAR(glm::length(s.towardsSun), 1.f, 1e-5f);
  EXPECT_GT(s.towardsSun.y, 0.2f);
  for (const auto& o : s.objects) {
    if (o.horizon) continue;  // the apron reaches past the bounds on purpose
    Bounds b = bounds(o.mesh, o.model);
    EXPECT_TRUE(glm::all(glm::greaterThanEqual(b.min, s.boundsMin)) && glm::all(glm::lessThanEqual(b.max, s.boundsMax)))
        << o.name;
  }
  static const std::map<std::string, std::vector<std::string>> kCameras = {
      {"valley", {"overview", "aerial", "shelter", "river", "rocks", "puddle"}},
      {"rocks", {"front", "sun-side", "shade-side"}},
      {"river", {"overhead", "bank"}},
      {"road", {"overview", "under-shelter"}}};
  std::vector<std::string> names;
  for (const auto& c : s.cameras) {
    names.push_back(c.name);
    EXPECT_GT(c.fovYDegrees, 10.f);
    EXPECT_LT(c.fovYDegrees, 120.f);
    EXPECT_GT(glm::distance(c.eye, c.target), 1.f);
    // Not looking straight down (lookAt with +Y up would degenerate).
    EXPECT_LT(std::abs(glm::normalize(c.target - c.eye).y), 0.999f) << c.name;
    // Above the ground it stands over.
    if (auto ground = topSurfaceAt(worldMesh(*s.find("terrain")), c.eye.x, c.eye.z)) {
      EXPECT_GT(c.eye.y, ground->position.y + 1.f) << c.name;
    }
  }
  EXPECT_EQ(names, kCameras.at(s.name));
}

// The ground runs on to the horizon: an apron of terrain round the height field that
// shares its border vertices (no crack), reaches past the far plane of any view the CLI
// allows (an orbit up to 500 m from the centre sees up to about 920 m: pass_cameras.cpp),
// stays out of the shadow and sky-exposure maps, and the scene fades it into the sky
// with distance haze.
TEST_P(EachScene, GroundRunsOnToTheHorizon) {
  const Scene& s = scene();
  EXPECT_GT(s.hazeDistance, 0.f);
  const SceneObject* apron = s.find("horizon");
  ASSERT_NE(apron, nullptr);
  EXPECT_TRUE(apron->horizon);
  EXPECT_EQ(apron->graph, "terrain");
  EXPECT_FALSE(apron->castsShadow);
  EXPECT_FALSE(apron->occludesSky);
  Bounds reach = bounds(worldMesh(*apron));
  EXPECT_GE(std::min(-reach.min.x, reach.max.x), 1450.f);
  EXPECT_GE(std::min(-reach.min.z, reach.max.z), 1450.f);
  std::set<std::tuple<float, float, float>> apronVertices;
  for (glm::vec3 p : worldMesh(*apron).positions) apronVertices.insert({p.x, p.y, p.z});
  Mesh ground = worldMesh(*s.find("terrain"));
  Bounds field = bounds(ground);
  std::size_t border = 0;
  for (glm::vec3 p : ground.positions) {
    bool onBorder = p.x == field.min.x || p.x == field.max.x || p.z == field.min.z || p.z == field.max.z;
    if (!onBorder) continue;
    ++border;
    EXPECT_TRUE(apronVertices.count({p.x, p.y, p.z})) << "terrain border vertex " << p.x << ", " << p.y << ", " << p.z;
  }
  EXPECT_GE(border, 4u * 128u);
}

TEST_P(EachScene, TerrainHeightMapMatchesTheTerrainMesh) {
  const Scene& s = scene();
  const int n = s.terrainHeightResolution;
  ASSERT_GE(n, 64);
  ASSERT_EQ(s.terrainHeights.size(), static_cast<std::size_t>(n) * n);
  auto [lo, hi] = std::minmax_element(s.terrainHeights.begin(), s.terrainHeights.end());
  EXPECT_EQ(*lo, 0.f);
  EXPECT_NEAR(*hi, 1.f, 1e-6f);
  EXPECT_GT(s.terrainHeightScale, 0.f);
  // Every terrain (and meadow) vertex is a texel centre holding its height.
  for (const auto* o : {s.find("terrain"), s.find("meadow")}) {
    if (!o) continue;
    Mesh m = worldMesh(*o);
    for (glm::vec3 p : m.positions) {
      glm::vec2 uv = (glm::vec2(p.x, p.z) - glm::vec2(s.terrainRegion)) * glm::vec2(s.terrainRegion.z, s.terrainRegion.w);
      glm::vec2 texel = uv * static_cast<float>(n) - 0.5f;
      glm::ivec2 i(std::lround(texel.x), std::lround(texel.y));
      ASSERT_NEAR(texel.x, i.x, 1e-2f);
      ASSERT_NEAR(texel.y, i.y, 1e-2f);
      ASSERT_TRUE(i.x >= 0 && i.y >= 0 && i.x < n && i.y < n);
      float h = s.terrainHeightOffset + s.terrainHeightScale * s.terrainHeights[static_cast<std::size_t>(i.y) * n + i.x];
      ASSERT_NEAR(h, p.y, 1e-3f);
    }
  }
}

TEST_P(EachScene, ProbesLieOnSurfacesAndAreSeen) {
  const Scene& s = scene();
  ASSERT_GE(s.probes.size(), 4u);
  std::vector<Mesh> world;
  for (const auto& o : s.objects) world.push_back(worldMesh(o));
  std::set<std::string> names;
  for (const auto& p : s.probes) {
    SCOPED_TRACE(p.name);
    EXPECT_TRUE(names.insert(p.name).second);
    EXPECT_NEAR(glm::length(p.normal), 1.f, kUnitTolerance);
    const SceneObject* o = s.find(p.object);
    ASSERT_NE(o, nullptr) << p.object;
    EXPECT_LT(distanceToMesh(worldMesh(*o), p.position), kProbeTolerance);
    float nearest = std::numeric_limits<float>::max();
    for (const Mesh& m : world) nearest = std::min(nearest, distanceToMesh(m, p.position));
    EXPECT_LT(nearest, kProbeTolerance);
    EXPECT_FALSE(p.visibleFrom.empty()) << "no camera sees probe " << p.name;
    for (const auto& c : p.visibleFrom) EXPECT_NE(s.camera(c), nullptr) << c;
    // Sheltered points have the roof above them; open ones nothing at all.
    if (p.expect == "sheltered") {
      EXPECT_EQ(coveredBy(s, p.position).value_or(""), "shelter");
    } else if (p.expect != "rock-sun-side" && p.expect != "rock-shade-side") {
      EXPECT_FALSE(coveredBy(s, p.position).has_value()) << "covered by " << coveredBy(s, p.position).value_or("");
    }
    if (p.expect == "flat-road") {
      EXPECT_LT(tiltDegrees(p.normal), 2.f);
    }
    if (p.expect == "sloped-road") {
      EXPECT_GE(tiltDegrees(p.normal), 12.f);
    }
    if (p.expect == "rock-top") {
      EXPECT_LT(tiltDegrees(p.normal), 45.f);
    }
    glm::vec3 sun = glm::normalize(glm::vec3(s.towardsSun.x, 0.f, s.towardsSun.z));
    if (p.expect == "rock-sun-side") {
      EXPECT_GT(glm::dot(p.normal, sun), 0.6f);
    }
    if (p.expect == "rock-shade-side") {
      EXPECT_LT(glm::dot(p.normal, sun), -0.6f);
    }
  }
  static const std::map<std::string, std::set<std::string>> kExpected = {
      {"valley",
       {"sheltered", "open", "flat-road", "sloped-road", "river-bank", "river-centre", "rock-top", "rock-sun-side",
        "rock-shade-side"}},
      {"rocks", {"open", "rock-top", "rock-sun-side", "rock-shade-side"}},
      {"river", {"open", "river-bank", "river-centre"}},
      {"road", {"sheltered", "open", "flat-road", "sloped-road"}}};
  std::set<std::string> expects;
  for (const auto& p : s.probes) expects.insert(p.expect);
  EXPECT_EQ(expects, kExpected.at(s.name));
}

TEST_P(EachScene, RiverVSpansBankToBank) {
  const Scene& s = scene();
  auto rivers = withGraph("river");
  if (s.name == "valley" || s.name == "river") {
    ASSERT_EQ(rivers.size(), 1u);
  }
  if (rivers.empty()) return;
  Mesh water = worldMesh(*rivers[0]);
  Mesh ground = worldMesh(*s.find("terrain"));
  float vMin = 1.f, vMax = 0.f;
  for (std::size_t i = 0; i < water.positions.size(); ++i) {
    float v = water.texcoords[i].y;
    vMin = std::min(vMin, v);
    vMax = std::max(vMax, v);
    glm::vec3 p = water.positions[i];
    auto g = topSurfaceAt(ground, p.x, p.z);
    if (!g) continue;  // past the terrain's edge
    // The strip's edges are buried in the banks; its middle floats over the bed.
    if (v == 0.f || v == 1.f) {
      EXPECT_GT(g->position.y, p.y + 0.1f) << "edge vertex " << i;
    }
    if (v == 0.5f) {
      EXPECT_LT(g->position.y, p.y - 0.5f) << "centre vertex " << i;
    }
  }
  EXPECT_EQ(vMin, 0.f);
  EXPECT_EQ(vMax, 1.f);
  // Bank probes sit where the frost map F = 1 - |2v - 1| is low; the centre where it is 1.
  for (const auto& p : s.probes) {
    if (p.object != rivers[0]->name) continue;
    auto hit = topSurfaceAt(water, p.position.x, p.position.z);
    ASSERT_TRUE(hit);
    float frostMap = 1.f - std::abs(2.f * hit->texcoord.y - 1.f);
    if (p.expect == "river-bank") {
      EXPECT_LT(frostMap, 0.3f) << p.name;
      EXPECT_GT(frostMap, 0.1f) << p.name << " (inside the water's visible edge)";
    }
    if (p.expect == "river-centre") {
      EXPECT_GT(frostMap, 0.95f) << p.name;
    }
  }
}

TEST_P(EachScene, RoadHasFlatAndTiltedStretches) {
  const Scene& s = scene();
  auto roads = withGraph("road");
  if (s.name == "valley" || s.name == "road") {
    ASSERT_EQ(roads.size(), 1u);
  }
  if (roads.empty()) return;
  Mesh road = worldMesh(*roads[0]);
  Bounds rb = bounds(road);
  glm::vec3 along = (rb.max.x - rb.min.x) > (rb.max.z - rb.min.z) ? glm::vec3(1, 0, 0) : glm::vec3(0, 0, 1);
  float flat = 0.f, ramp = 0.f, camber = 0.f;
  for (std::size_t t = 0; t < triangleCount(road); ++t) {
    glm::vec3 n = glm::normalize(faceNormal(road, t));
    if (n.y < 0.5f) continue;  // skirts and end caps
    float tilt = tiltDegrees(n), area = triangleArea(road, t);
    if (tilt < 2.f) flat += area;
    if (tilt >= 12.f) {
      glm::vec3 h = glm::normalize(glm::vec3(n.x, 0.f, n.z));
      (std::abs(glm::dot(h, along)) > 0.9f ? ramp : camber) += area;
    }
  }
  EXPECT_GT(flat, 100.f);   // m^2
  EXPECT_GT(ramp, 20.f);    // a 14 degree ramp
  EXPECT_GT(camber, 20.f);  // a 12 degree crowned stretch
}

TEST_P(EachScene, ShelterCoversRoadAndGround) {
  const Scene& s = scene();
  const SceneObject* shelterObject = s.find("shelter");
  if (s.name == "valley" || s.name == "road") {
    ASSERT_NE(shelterObject, nullptr);
  }
  if (!shelterObject) return;
  Mesh shelterMesh = worldMesh(*shelterObject);
  EXPECT_TRUE(closedAndConsistent(shelterMesh));
  Bounds roof = bounds(shelterMesh);
  auto under = [&](glm::vec3 c) { return c.x > roof.min.x && c.x < roof.max.x && c.z > roof.min.z && c.z < roof.max.z; };
  Mesh road = worldMesh(*s.find("road"));
  float flat = 0.f, coveredFlat = 0.f;
  for (std::size_t t = 0; t < triangleCount(road); ++t) {
    if (tiltDegrees(faceNormal(road, t)) >= 2.f) continue;
    flat += triangleArea(road, t);
    if (under(centroid(road, t))) coveredFlat += triangleArea(road, t);
  }
  EXPECT_GE(coveredFlat, 0.2f * flat);
  Mesh ground = worldMesh(*s.find("terrain"));
  float coveredGround = 0.f;
  for (std::size_t t = 0; t < triangleCount(ground); ++t)
    if (under(centroid(ground, t))) coveredGround += triangleArea(ground, t);
  EXPECT_GT(coveredGround, 20.f);  // m^2 of terrain under the roof
  // The roof is about 3 m above the sheltered road.
  for (const auto& p : s.probes) {
    if (p.expect != "sheltered") continue;
    float clearance = roof.max.y - kShelterRoofThickness - p.position.y;
    EXPECT_GT(clearance, 2.5f) << p.name;
    EXPECT_LT(clearance, 4.5f) << p.name;
  }
}

INSTANTIATE_TEST_SUITE_P(Bundled, EachScene, ::testing::Values("valley", "rocks", "river", "road"),
                         [](const auto& info) { return info.param; });

TEST(Scenes, ValleyHasEverything) {
  const Scene& s = cached("valley");
  for (const char* name : {"terrain", "meadow", "river", "road", "shelter", "bushes", "grass-tufts"})
    EXPECT_NE(s.find(name), nullptr) << name;
  EXPECT_EQ(s.find("meadow")->graph, "grass");
  // Five or more rocks, each on a slope.
  Mesh ground = worldMesh(*s.find("terrain"));
  int rocks = 0;
  for (const auto& o : s.objects) {
    if (o.graph != "rock" || o.name == "shelter") continue;
    ++rocks;
    glm::vec3 c(o.model[3]);
    auto g = topSurfaceAt(ground, c.x, c.z);
    ASSERT_TRUE(g) << o.name;
    EXPECT_GT(tiltDegrees(g->normal), 10.f) << o.name;
  }
  EXPECT_GE(rocks, 5);
}

TEST(Scenes, RocksSpanTheDefaultHeightRange) {
  const Scene& s = cached("rocks");
  bool low = false, high = false;
  int rocks = 0;
  for (const auto& o : s.objects) {
    if (o.graph != "rock") continue;
    ++rocks;
    float y = o.model[3].y;
    low = low || (y > -35.f && y < -25.f);
    high = high || (y > 25.f && y < 35.f);
  }
  EXPECT_GE(rocks, 5);
  EXPECT_TRUE(low);
  EXPECT_TRUE(high);
  int lowTops = 0, highTops = 0;
  for (const auto& p : s.probes) {
    if (p.expect != "rock-top") continue;
    lowTops += p.position.y < -20.f;
    highTops += p.position.y > 20.f;
  }
  EXPECT_GE(lowTops, 1);
  EXPECT_GE(highTops, 1);
}

}  // namespace
}  // namespace wg::scene
