#include "host/precipitation_shaders.hpp"

#include <string>

namespace wg {

namespace {
// Mirrors PrecipitationBlock in precipitation_pass.cpp (std140).
constexpr std::string_view kBlock = R"(#version 440
layout(std140, set = 0, binding = 0) uniform Precipitation {
  mat4 viewProjection;
  vec4 eyeTime;     // xyz eye (world), w time (s)
  vec4 motion;      // xy wind (m/s, world xz), z snow and w rain fall speed (m/s)
  vec4 volume;      // x half-size of the box around the eye, y near fade (m), z flake and w drop radius (m)
  vec4 screen;      // width, height (px), focal length (px at 1 m), unused
  vec4 depthRange;  // near, far plane (m), snow and rain softness (m)
  vec4 snowColour;  // rgb tone-mapped, a opacity
  vec4 rainColour;  // rgb tone-mapped, a opacity
  vec4 shutter;     // x snow, y rain exposure (s): streak length = speed * exposure; zw least half-width (px)
  uvec4 counts;     // x snowflakes (the first instances), y all particles
} fall;
)";

// Each instance is one particle. Its place in a 2R tile of the world, its speed and its
// drift come from a hash of its index; the tile is wrapped around the eye, so the box
// follows the camera while every flake stays put in the world. A particle is a capsule
// in screen space from where it is to where it was one exposure earlier (the motion
// blur), at least a pixel or so wide; what a thin one lacks in width it loses in opacity,
// so distant flakes fade instead of flickering.
constexpr std::string_view kVertex = R"(
layout(location = 0) noperspective out vec2 v_local;  // px: along the streak from its middle, across it
layout(location = 1) flat out vec4 v_shape;           // half-length, half-width (px), opacity, 1 for rain
layout(location = 2) noperspective out float v_depth; // m along the view
layout(location = 3) flat out vec3 v_colour;

uint hash(uint x) {  // lowbias32 (Chris Wellons): a bijection with full avalanche
  x ^= x >> 16; x *= 0x7feb352du; x ^= x >> 15; x *= 0x846ca68bu; x ^= x >> 16;
  return x;
}
float unit(uint particle, uint draw) { return float(hash(particle * 8u + draw) >> 8) * (1.0 / 16777216.0); }

const vec2 kCorners[6] = vec2[](vec2(-1.0, -1.0), vec2(1.0, -1.0), vec2(1.0, 1.0), vec2(-1.0, -1.0), vec2(1.0, 1.0), vec2(-1.0, 1.0));

void hide() {
  gl_Position = vec4(2.0, 2.0, 2.0, 1.0);
  v_local = vec2(0.0);
  v_shape = vec4(0.0);
  v_depth = 0.0;
  v_colour = vec3(0.0);
}

void main() {
  uint i = uint(gl_InstanceIndex);
  bool rain = i >= fall.counts.x;
  float R = fall.volume.x, t = fall.eyeTime.w;
  vec3 eye = fall.eyeTime.xyz;
  float fallSpeed = (rain ? fall.motion.w : fall.motion.z) * (0.75 + 0.5 * unit(i, 3u));
  vec3 velocity = vec3(fall.motion.x, -fallSpeed, fall.motion.y);
  vec3 world = vec3(unit(i, 0u), unit(i, 1u), unit(i, 2u)) * (2.0 * R) + velocity * t;
  if (!rain) {
    // Tumbling flakes wander on small loops of their own around their drift.
    float phase = 6.2831853 * unit(i, 4u), rate = 0.8 + 1.6 * unit(i, 5u), loop = 0.1 + 0.2 * unit(i, 6u);
    float a = rate * t + phase;
    world += loop * vec3(cos(a), 0.0, sin(a));
    velocity += loop * rate * vec3(-sin(a), 0.0, cos(a));
  }
  vec3 p = eye + mod(world - eye + R, 2.0 * R) - R;
  float d = length(p - eye);
  // A sphere, not the box's corners; nothing right at the lens.
  float fade = (1.0 - smoothstep(0.7 * R, R, d)) * smoothstep(fall.volume.y, 2.0 * fall.volume.y, d);
  vec4 head = fall.viewProjection * vec4(p, 1.0);
  vec4 tail = fall.viewProjection * vec4(p - velocity * (rain ? fall.shutter.y : fall.shutter.x), 1.0);
  if (fade <= 0.0 || min(head.w, tail.w) <= fall.depthRange.x) { hide(); return; }
  vec2 a = (head.xy / head.w * 0.5 + 0.5) * fall.screen.xy;
  vec2 b = (tail.xy / tail.w * 0.5 + 0.5) * fall.screen.xy;
  float radius = (rain ? fall.volume.w : fall.volume.z) * (0.7 + 0.6 * unit(i, 7u));
  float trueWidth = radius * fall.screen.z * 2.0 / (head.w + tail.w);
  float width = max(trueWidth, rain ? fall.shutter.w : fall.shutter.z);
  float len = length(b - a);
  float coverage = (3.14159265 * trueWidth * trueWidth + 2.0 * trueWidth * len) / (3.14159265 * width * width + 2.0 * width * len);
  vec2 along = len > 1e-3 ? (b - a) / len : vec2(1.0, 0.0);
  vec2 across = vec2(-along.y, along.x);
  vec2 corner = kCorners[gl_VertexIndex];
  float reach = 0.5 * len + width + 1.0, side = width + 1.0;  // a pixel to spare for the soft edge
  vec2 pixel = 0.5 * (a + b) + along * corner.x * reach + across * corner.y * side;
  gl_Position = vec4(pixel / fall.screen.xy * 2.0 - 1.0, 0.5, 1.0);
  v_local = vec2(corner.x * reach, corner.y * side);
  v_depth = mix(head.w, tail.w, 0.5 + 0.5 * corner.x);
  vec4 colour = rain ? fall.rainColour : fall.snowColour;
  v_shape = vec4(0.5 * len, width, colour.a * fade * coverage, rain ? 1.0 : 0.0);
  v_colour = colour.rgb * (rain ? 1.0 : 0.88 + 0.12 * unit(i, 4u));
}
)";

// Seed 000 ch. 5's particles with seed 001's soft particles (3.3.2): the opacity fades
// out over `softness` metres as the particle nears the scene's depth (the D32 float of
// the colour pass, made linear), so streaks and flakes never cut into the ground.
constexpr std::string_view kFragment = R"(
layout(set = 0, binding = 1) uniform texture2D SceneDepth;
layout(set = 0, binding = 2) uniform sampler DepthSampler;
layout(location = 0) noperspective in vec2 v_local;
layout(location = 1) flat in vec4 v_shape;
layout(location = 2) noperspective in float v_depth;
layout(location = 3) flat in vec3 v_colour;
layout(location = 0) out vec4 out_color;
float metres(float depth) {
  float n = fall.depthRange.x, f = fall.depthRange.y;
  return n * f / (f - depth * (f - n));
}
void main() {
  // Distance from the streak's axis segment, in its half-widths.
  vec2 q = vec2(max(abs(v_local.x) - v_shape.x, 0.0), v_local.y);
  float r = length(q) / v_shape.y;
  float shape = clamp(1.0 - r * r, 0.0, 1.0);
  if (v_shape.w > 0.5) {
    // Raindrop streaks taper towards both ends.
    float s = abs(v_local.x) / (v_shape.x + v_shape.y);
    shape *= 1.0 - s * s;
  }
  float scene = metres(texelFetch(sampler2D(SceneDepth, DepthSampler), ivec2(gl_FragCoord.xy), 0).r);
  float softness = v_shape.w > 0.5 ? fall.depthRange.w : fall.depthRange.z;
  float soft = clamp((scene - v_depth) / softness, 0.0, 1.0);
  float a = shape * soft * v_shape.z;
  if (a <= 0.0) discard;
  out_color = vec4(v_colour * a, a);  // premultiplied
}
)";
}  // namespace

std::string_view precipitationVertexSource() {
  static const std::string s = std::string(kBlock) + std::string(kVertex);
  return s;
}
std::string_view precipitationFragmentSource() {
  static const std::string s = std::string(kBlock) + std::string(kFragment);
  return s;
}

}  // namespace wg
