#include "host/scene/mesh.hpp"

#include <algorithm>
#include <cmath>

namespace wg::scene {

namespace {
// Triangles whose uv parallelogram is smaller than this carry no usable uv direction.
constexpr float kMinUvArea = 1e-12f;
// Vectors shorter than this are treated as zero when normalising.
constexpr float kMinLength = 1e-12f;
// Ray-triangle tests: determinants below this mean the ray runs along the triangle.
constexpr float kParallelEpsilon = 1e-12f;
// Barycentric slack so that rays through shared edges hit one of the two triangles.
constexpr float kEdgeSlack = 1e-6f;
// Vertical rays for topSurfaceAt start this far above the mesh.
constexpr float kRayStartMargin = 1.f;

// Any unit vector orthogonal to n (n unit).
glm::vec3 anyOrthogonal(glm::vec3 n) {
  glm::vec3 axis = std::abs(n.x) < 0.9f ? glm::vec3(1.f, 0.f, 0.f) : glm::vec3(0.f, 1.f, 0.f);
  return glm::normalize(axis - n * glm::dot(n, axis));
}

// Gram-Schmidt: t made unit and orthogonal to the unit normal n; twice, so the float
// residue of the first pass does not survive.
glm::vec3 orthogonalise(glm::vec3 t, glm::vec3 n) {
  for (int pass = 0; pass < 2; ++pass) {
    t -= n * glm::dot(n, t);
    float len = glm::length(t);
    if (!(len > kMinLength)) return anyOrthogonal(n);
    t /= len;
  }
  return t;
}

}  // namespace

glm::vec3 faceNormal(const Mesh& m, std::size_t tri) {
  glm::vec3 a = m.positions[m.indices[tri * 3]];
  glm::vec3 b = m.positions[m.indices[tri * 3 + 1]];
  glm::vec3 c = m.positions[m.indices[tri * 3 + 2]];
  return glm::cross(b - a, c - a);
}

std::size_t triangleCount(const Mesh& mesh) { return mesh.indices.size() / 3; }

std::uint32_t addVertex(Mesh& mesh, glm::vec3 position, glm::vec3 normal, glm::vec2 texcoord, glm::vec4 color) {
  auto index = static_cast<std::uint32_t>(mesh.positions.size());
  mesh.positions.push_back(position);
  mesh.normals.push_back(glm::normalize(normal));
  mesh.tangents.push_back(glm::vec4(anyOrthogonal(glm::normalize(normal)), 1.f));
  mesh.texcoords.push_back(texcoord);
  mesh.colors.push_back(color);
  return index;
}

void addTriangleFacing(Mesh& mesh, std::uint32_t a, std::uint32_t b, std::uint32_t c, glm::vec3 outward) {
  glm::vec3 n = glm::cross(mesh.positions[b] - mesh.positions[a], mesh.positions[c] - mesh.positions[a]);
  if (glm::dot(n, outward) < 0.f) std::swap(b, c);
  mesh.indices.insert(mesh.indices.end(), {a, b, c});
}

void addQuadFacing(Mesh& mesh, std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d, glm::vec3 outward) {
  addTriangleFacing(mesh, a, b, c, outward);
  addTriangleFacing(mesh, a, c, d, outward);
}

void computeNormals(Mesh& mesh) {
  std::vector<glm::vec3> sum(mesh.positions.size(), glm::vec3(0.f));
  for (std::size_t t = 0; t < triangleCount(mesh); ++t) {
    glm::vec3 n = faceNormal(mesh, t);  // area weighted
    for (int k = 0; k < 3; ++k) sum[mesh.indices[t * 3 + k]] += n;
  }
  mesh.normals.resize(mesh.positions.size());
  for (std::size_t i = 0; i < sum.size(); ++i) {
    float len = glm::length(sum[i]);
    mesh.normals[i] = len > kMinLength ? sum[i] / len : glm::vec3(0.f, 1.f, 0.f);
  }
}

void computeTangents(Mesh& mesh) {
  const std::size_t n = mesh.positions.size();
  std::vector<glm::vec3> tan(n, glm::vec3(0.f)), bitan(n, glm::vec3(0.f));
  for (std::size_t t = 0; t < triangleCount(mesh); ++t) {
    std::uint32_t i0 = mesh.indices[t * 3], i1 = mesh.indices[t * 3 + 1], i2 = mesh.indices[t * 3 + 2];
    glm::vec3 e1 = mesh.positions[i1] - mesh.positions[i0];
    glm::vec3 e2 = mesh.positions[i2] - mesh.positions[i0];
    glm::vec2 d1 = mesh.texcoords[i1] - mesh.texcoords[i0];
    glm::vec2 d2 = mesh.texcoords[i2] - mesh.texcoords[i0];
    float det = d1.x * d2.y - d2.x * d1.y;
    if (std::abs(det) < kMinUvArea) continue;
    // dP/du and dP/dv of the triangle's affine uv map.
    glm::vec3 sdir = (e1 * d2.y - e2 * d1.y) / det;
    glm::vec3 tdir = (e2 * d1.x - e1 * d2.x) / det;
    // Weight by area so that slivers do not dominate; the directions are unit first
    // because uv density differs between triangles.
    float area = 0.5f * glm::length(glm::cross(e1, e2));
    float sl = glm::length(sdir), tl = glm::length(tdir);
    if (!(sl > kMinLength) || !(tl > kMinLength)) continue;
    for (std::uint32_t i : {i0, i1, i2}) {
      tan[i] += sdir / sl * area;
      bitan[i] += tdir / tl * area;
    }
  }
  mesh.tangents.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    glm::vec3 normal = mesh.normals[i];
    glm::vec3 t = orthogonalise(tan[i], normal);
    float w = glm::dot(glm::cross(normal, t), bitan[i]) < 0.f ? -1.f : 1.f;
    mesh.tangents[i] = glm::vec4(t, w);
  }
}

void append(Mesh& dst, const Mesh& src, const glm::mat4& transform) {
  const auto base = static_cast<std::uint32_t>(dst.positions.size());
  const glm::mat3 linear(transform);
  const glm::mat3 normalMatrix = glm::transpose(glm::inverse(linear));
  const bool mirrored = glm::determinant(linear) < 0.f;
  // A second texture coordinate set stays parallel to the positions once either mesh
  // has one; where a mesh has none, its set 0 stands in (as packVertices does).
  const bool secondSet = !src.texcoords1.empty() || !dst.texcoords1.empty();
  if (secondSet && dst.texcoords1.empty()) dst.texcoords1 = dst.texcoords;
  for (std::size_t i = 0; i < src.positions.size(); ++i) {
    dst.positions.push_back(glm::vec3(transform * glm::vec4(src.positions[i], 1.f)));
    glm::vec3 n = glm::normalize(normalMatrix * src.normals[i]);
    dst.normals.push_back(n);
    glm::vec4 t = i < src.tangents.size() ? src.tangents[i] : glm::vec4(1.f, 0.f, 0.f, 1.f);
    dst.tangents.push_back(glm::vec4(orthogonalise(linear * glm::vec3(t), n), mirrored ? -t.w : t.w));
    dst.texcoords.push_back(i < src.texcoords.size() ? src.texcoords[i] : glm::vec2(0.f));
    if (secondSet) dst.texcoords1.push_back(i < src.texcoords1.size() ? src.texcoords1[i] : dst.texcoords.back());
    dst.colors.push_back(i < src.colors.size() ? src.colors[i] : glm::vec4(1.f));
  }
  for (std::size_t t = 0; t + 2 < src.indices.size(); t += 3) {
    std::uint32_t a = src.indices[t], b = src.indices[t + 1], c = src.indices[t + 2];
    if (mirrored) std::swap(b, c);
    dst.indices.insert(dst.indices.end(), {base + a, base + b, base + c});
  }
}

Mesh transformed(const Mesh& mesh, const glm::mat4& transform) {
  Mesh out;
  append(out, mesh, transform);
  return out;
}

Bounds bounds(const Mesh& mesh) {
  Bounds b;
  for (glm::vec3 p : mesh.positions) b.include(p);
  return b;
}

Bounds bounds(const Mesh& mesh, const glm::mat4& transform) {
  Bounds b;
  for (glm::vec3 p : mesh.positions) b.include(glm::vec3(transform * glm::vec4(p, 1.f)));
  return b;
}

std::optional<SurfaceHit> raycast(const Mesh& mesh, glm::vec3 origin, glm::vec3 direction) {
  std::optional<SurfaceHit> best;
  for (std::size_t t = 0; t < triangleCount(mesh); ++t) {
    std::uint32_t i0 = mesh.indices[t * 3], i1 = mesh.indices[t * 3 + 1], i2 = mesh.indices[t * 3 + 2];
    glm::vec3 p0 = mesh.positions[i0];
    glm::vec3 e1 = mesh.positions[i1] - p0, e2 = mesh.positions[i2] - p0;
    // Moller-Trumbore, two-sided.
    glm::vec3 pv = glm::cross(direction, e2);
    float det = glm::dot(e1, pv);
    if (std::abs(det) < kParallelEpsilon) continue;
    float inv = 1.f / det;
    glm::vec3 tv = origin - p0;
    float u = glm::dot(tv, pv) * inv;
    if (u < -kEdgeSlack || u > 1.f + kEdgeSlack) continue;
    glm::vec3 qv = glm::cross(tv, e1);
    float v = glm::dot(direction, qv) * inv;
    if (v < -kEdgeSlack || u + v > 1.f + kEdgeSlack) continue;
    float dist = glm::dot(e2, qv) * inv;
    if (dist <= 0.f || (best && dist >= best->distance)) continue;
    float w = 1.f - u - v;
    SurfaceHit hit;
    hit.position = origin + direction * dist;
    hit.normal = glm::normalize(mesh.normals[i0] * w + mesh.normals[i1] * u + mesh.normals[i2] * v);
    hit.texcoord = mesh.texcoords[i0] * w + mesh.texcoords[i1] * u + mesh.texcoords[i2] * v;
    hit.distance = dist;
    hit.triangle = static_cast<std::uint32_t>(t);
    best = hit;
  }
  return best;
}

std::optional<SurfaceHit> topSurfaceAt(const Mesh& mesh, float x, float z) {
  Bounds b = bounds(mesh);
  if (b.empty()) return std::nullopt;
  return raycast(mesh, glm::vec3(x, b.max.y + kRayStartMargin, z), glm::vec3(0.f, -1.f, 0.f));
}

}  // namespace wg::scene
