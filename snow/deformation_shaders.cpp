#include "snow/deformation_shaders.hpp"

namespace wg::snow {

namespace {

// Shared by the compute passes: the window (push constants) and the texel encoding of
// deformation_texel.hpp. `originSlot` is the origin's storage position (origin mod N,
// taken on the CPU, so no shader ever takes the modulo of a negative number).
constexpr std::string_view kComputeHeader = R"(#version 440
layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;
layout(push_constant) uniform Window {
  ivec2 origin;
  ivec2 originSlot;
  int resolution;
  float texelSize;
  uint refillQuanta;
} window;
)";

// The mesh interactors' window: the same fields after the model matrix, and where the
// undisturbed snow surface and the ground under it are (world y).
constexpr std::string_view kMeshHeader = R"(#version 440
layout(push_constant) uniform Window {
  mat4 model;
  ivec2 origin;
  ivec2 originSlot;
  int resolution;
  float texelSize;
  float surfaceHeight;
  float snowDepth;
} window;
)";

constexpr std::string_view kTexelEncoding = R"(
layout(std430, set = 0, binding = 0) buffer Heights { uint heights[]; };
const float kDepthQuantum = 1e-4;
const uint kMaxQuanta = 0xFFFFu;
ivec2 storageSlot(ivec2 texel) { return (window.originSlot + (texel - window.origin)) % window.resolution; }
uint storageIndex(ivec2 texel) {
  ivec2 slot = storageSlot(texel);
  return uint(slot.y * window.resolution + slot.x);
}
uint toQuanta(float metres) {
  if (!(metres > 0.0)) return 0u;
  float q = metres / kDepthQuantum + 0.5;
  return q >= float(kMaxQuanta) ? kMaxQuanta : uint(q);
}
float texelHeight(uint texel) {
  uint depth = texel >> 16;
  return depth != 0u ? -float(depth) * kDepthQuantum : float(texel & kMaxQuanta) * kDepthQuantum;
}
)";

// One workgroup layer per stamp (gl_WorkGroupID.z), covering its bounding box: the cost
// follows the stamped area, not the map size. Overlaps merge with atomicMax.
constexpr std::string_view kStamp = R"(
struct Stamp { vec2 a; vec2 b; float radiusA; float radiusB; float depthA; float depthB; float rimWidth; float rimHeight; float waist; float archDepth; };
layout(std430, set = 0, binding = 2) readonly buffer Stamps { Stamp stamps[]; };
layout(std430, set = 0, binding = 3) readonly buffer StampBoxes { ivec4 stampBoxes[]; };
const float kDegenerateAxis = 1e-5;
const float kWallFraction = 0.35;
const float kArchFlat = 0.05, kArchReach = 0.3;
float unevenCapsuleDistance(vec2 p, float r1, float r2, float h) {
  p.x = abs(p.x);
  if (h <= abs(r1 - r2)) return min(length(p) - r1, length(p - vec2(0.0, h)) - r2);
  float b = (r1 - r2) / h, a = sqrt(1.0 - b * b);
  float k = dot(p, vec2(-b, a));
  if (k < 0.0) return length(p) - r1;
  if (k > a * h) return length(p - vec2(0.0, h)) - r2;
  return dot(p, vec2(a, b)) - r1;
}
float archWeight(float t) { return 1.0 - smoothstep(kArchFlat, kArchReach, abs(t - 0.5)); }
void main() {
  ivec4 box = stampBoxes[gl_WorkGroupID.z];
  ivec2 local = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(local, box.zw))) return;
  ivec2 texel = box.xy + local;
  Stamp s = stamps[gl_WorkGroupID.z];
  vec2 point = (vec2(texel) + 0.5) * window.texelSize;
  vec2 axis = s.b - s.a;
  float h = length(axis);
  vec2 along = h > kDegenerateAxis ? axis / h : vec2(0.0, 1.0);
  vec2 across = vec2(along.y, -along.x);
  vec2 d = point - s.a;
  vec2 q = vec2(dot(d, across), dot(d, along));
  float distance = unevenCapsuleDistance(q, s.radiusA, s.radiusB, h);
  float t = h > kDegenerateAxis ? clamp(q.y / h, 0.0, 1.0) : 0.0;
  float arch = s.waist > 0.0 ? archWeight(t) : 0.0;
  float sole = distance + arch * max(s.radiusA + (s.radiusB - s.radiusA) * t - s.waist, 0.0);
  float depth = s.depthA + (s.depthB - s.depthA) * t;
  depth += (s.archDepth - depth) * arch;
  depth *= smoothstep(0.0, kWallFraction * min(s.radiusA, s.radiusB), -sole);
  float rim = 0.0;
  if (distance > 0.0 && distance < s.rimWidth) {
    float u = distance / s.rimWidth;
    rim = s.rimHeight * 4.0 * u * (1.0 - u);
  }
  uint packed = (toQuanta(depth) << 16) | toQuanta(rim);
  if (packed != 0u) atomicMax(heights[storageIndex(texel)], packed);
}
)";

// Central differences of the decoded height, neighbours clamped to the window; one
// workgroup layer per rectangle (each stamp's box grown by one texel). The same texels
// of the surface image the snow layer samples (height, world normal; same toroidal
// order) are rewritten too, so nothing is resolved or uploaded from the CPU.
constexpr std::string_view kNormals = R"(
layout(std430, set = 0, binding = 1) writeonly buffer Normals { uint normals[]; };
layout(set = 0, binding = 5, rgba16f) uniform writeonly image2D Surface;
layout(std430, set = 0, binding = 4) readonly buffer NormalRects { ivec4 normalRects[]; };
float heightAt(ivec2 texel) {
  texel = clamp(texel, window.origin, window.origin + window.resolution - 1);
  return texelHeight(heights[storageIndex(texel)]);
}
void main() {
  ivec4 rect = normalRects[gl_WorkGroupID.z];
  ivec2 local = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(local, rect.zw))) return;
  ivec2 t = rect.xy + local;
  float span = 2.0 * window.texelSize;
  float dx = (heightAt(t + ivec2(1, 0)) - heightAt(t - ivec2(1, 0))) / span;
  float dz = (heightAt(t + ivec2(0, 1)) - heightAt(t - ivec2(0, 1))) / span;
  vec3 n = normalize(vec3(-dx, 1.0, -dz));
  normals[storageIndex(t)] = packSnorm2x16(vec2(n.x, n.z));
  imageStore(Surface, storageSlot(t), vec4(heightAt(t), n));
}
)";

// Fresh snow and drift: both halves of every texel of a tile lowered by the quanta
// that tile is owed, never below 0. One workgroup layer per tile (x, z, size, quanta):
// only tiles that hold prints, a few per frame (refill_schedule.hpp).
constexpr std::string_view kRefill = R"(
layout(std430, set = 0, binding = 6) readonly buffer RefillTiles { ivec4 refillTiles[]; };
void main() {
  ivec4 tile = refillTiles[gl_WorkGroupID.z];
  ivec2 local = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(local, ivec2(tile.z)))) return;
  uint i = storageIndex(tile.xy + local);
  uint texel = heights[i];
  uint depth = texel >> 16, rim = texel & kMaxQuanta, q = uint(tile.w);
  heights[i] = ((depth > q ? depth - q : 0u) << 16) | (rim > q ? rim - q : 0u);
}
)";

// Recentring moves whole tiles between the map and its host copy (the same storage
// order): one workgroup layer per tile of TransferTiles (x, z, size, 0). One dispatch
// instead of a copy region per tile row, which cost lavapipe ~0.3 ms a move.
constexpr std::string_view kTransferTiles = R"(
layout(std430, set = 0, binding = 7) buffer HostHeights { uint hostHeights[]; };
layout(std430, set = 0, binding = 8) readonly buffer TransferTiles { ivec4 transferTiles[]; };
// Four texels of a tile row a invocation (a tile row is contiguous in storage: tiles
// never straddle the toroidal seam); calls `move` on each storage index.
#define FOR_EACH_TILE_TEXEL(move) { \
  ivec4 tile = transferTiles[gl_WorkGroupID.z]; \
  ivec2 local = ivec2(gl_GlobalInvocationID.x * 4u, gl_GlobalInvocationID.y); \
  if (local.y < tile.z) { \
    uint first = storageIndex(tile.xy + local); \
    for (int k = 0; k < 4 && local.x + k < tile.z; ++k) move(first + uint(k)); \
  } }
)";
constexpr std::string_view kTilesOut = R"(
void copyOut(uint i) { hostHeights[i] = heights[i]; }
void main() FOR_EACH_TILE_TEXEL(copyOut)
)";
constexpr std::string_view kTilesIn = R"(
void copyIn(uint i) { heights[i] = hostHeights[i]; }
void main() FOR_EACH_TILE_TEXEL(copyIn)
)";

// Any mesh deforms the snow by its depth seen from below (the shipped technique:
// render the interactors' depth from under the ground): an orthographic projection
// straight down maps world texels to framebuffer pixels, and every fragment merges
// its print depth (how far below the snow surface the mesh reaches there, at most
// the snow's depth) into the map with the stamps' atomicMax. The largest depth is
// the lowest surface, so no depth buffer is needed and triangle order does not matter.
constexpr std::string_view kMeshVertex = R"(
layout(location = 0) in vec3 position;
layout(location = 0) out float worldHeight;
void main() {
  vec4 world = window.model * vec4(position, 1.0);
  worldHeight = world.y;
  vec2 pixel = world.xz / window.texelSize - vec2(window.origin);
  gl_Position = vec4(pixel / float(window.resolution) * 2.0 - 1.0, 0.5, 1.0);
}
)";

constexpr std::string_view kMeshFragment = R"(
layout(location = 0) in float worldHeight;
void main() {
  ivec2 texel = window.origin + ivec2(gl_FragCoord.xy);
  float depth = min(window.surfaceHeight - worldHeight, window.snowDepth);
  uint packed = toQuanta(depth) << 16;
  if (packed != 0u) atomicMax(heights[storageIndex(texel)], packed);
}
)";

std::string join(std::string_view body) {
  return std::string(kComputeHeader) + std::string(kTexelEncoding) + std::string(body);
}
std::string joinMesh(std::string_view body) {
  return std::string(kMeshHeader) + std::string(kTexelEncoding) + std::string(body);
}

}  // namespace

std::string_view stampShaderSource() {
  static const std::string source = join(kStamp);
  return source;
}
std::string_view normalShaderSource() {
  static const std::string source = join(kNormals);
  return source;
}
std::string_view refillShaderSource() {
  static const std::string source = join(kRefill);
  return source;
}
std::string_view tilesOutShaderSource() {
  static const std::string source = join(std::string(kTransferTiles) + std::string(kTilesOut));
  return source;
}
std::string_view tilesInShaderSource() {
  static const std::string source = join(std::string(kTransferTiles) + std::string(kTilesIn));
  return source;
}
std::string_view meshVertexShaderSource() {
  // No Heights here: a vertex stage that declares a writable buffer would need
  // vertexPipelineStoresAndAtomics.
  static const std::string source = std::string(kMeshHeader) + std::string(kMeshVertex);
  return source;
}
std::string_view meshFragmentShaderSource() {
  static const std::string source = joinMesh(kMeshFragment);
  return source;
}

}  // namespace wg::snow
