#include "host/snowfield/snow_puff_shaders.hpp"

#include <string>

namespace wg::snow {

namespace {
constexpr std::string_view kParticle = R"(#version 440
struct Particle { vec4 positionAge; vec4 velocityLife; vec4 sizeShade; };
)";

// Air drag towards the wind, solved exactly over the step, then gravity; a particle
// that falls back below the surface it was emitted from has landed.
constexpr std::string_view kSimulate = R"(
layout(local_size_x = 64, local_size_y = 1, local_size_z = 1) in;
layout(std430, set = 0, binding = 0) buffer Particles { Particle particles[]; };
layout(push_constant) uniform Step { vec2 wind; float dt; float gravity; float drag; uint count; } step;
void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= step.count) return;
  Particle p = particles[i];
  if (p.velocityLife.w <= 0.0) return;
  p.positionAge.w += step.dt;
  if (p.positionAge.w >= p.velocityLife.w) {
    p.velocityLife.w = 0.0;
    particles[i] = p;
    return;
  }
  vec3 air = vec3(step.wind.x, 0.0, step.wind.y);
  vec3 v = air + (p.velocityLife.xyz - air) * exp(-step.drag * step.dt);
  v.y -= step.gravity * step.dt;
  p.positionAge.xyz += v * step.dt;
  p.velocityLife.xyz = v;
  // Settled back onto the snow it was kicked out of: gone.
  if (v.y < 0.0 && p.positionAge.y < p.sizeShade.z) p.velocityLife.w = 0.0;
  particles[i] = p;
}
)";

constexpr std::string_view kView = R"(
// right.w and up.w carry the sky's and the sun's light; sun holds the direction towards
// the sun in the billboard's frame (right, up, towards the camera): 128 bytes in all.
layout(push_constant) uniform View { mat4 viewProjection; vec4 right; vec4 up; vec4 sun; vec4 fade; } view;
)";

// Six vertices per particle; a free slot collapses outside the clip volume. The cloud
// grows and thins as it ages.
constexpr std::string_view kVertex = R"(
layout(std430, set = 0, binding = 0) readonly buffer Particles { Particle particles[]; };
layout(location = 0) out vec2 v_corner;
layout(location = 1) out float v_alpha;
layout(location = 2) out float v_shade;
const vec2 kCorners[6] = vec2[](vec2(-1.0, -1.0), vec2(1.0, -1.0), vec2(1.0, 1.0), vec2(-1.0, -1.0), vec2(1.0, 1.0), vec2(-1.0, 1.0));
const float kSpread = 1.5;
void main() {
  Particle p = particles[gl_VertexIndex / 6];
  vec2 corner = kCorners[gl_VertexIndex % 6];
  v_corner = corner;
  v_shade = p.sizeShade.y;
  if (p.velocityLife.w <= 0.0) {
    gl_Position = vec4(2.0, 2.0, 2.0, 1.0);
    v_alpha = 0.0;
    return;
  }
  float t = clamp(p.positionAge.w / p.velocityLife.w, 0.0, 1.0);
  float radius = p.sizeShade.x * (1.0 + kSpread * t);
  vec3 world = p.positionAge.xyz + (view.right.xyz * corner.x + view.up.xyz * corner.y) * radius;
  gl_Position = view.viewProjection * vec4(world, 1.0);
  v_alpha = (1.0 - t) * (1.0 - t);
}
)";

// Seed 3.3.2: fade where the billboard's depth reaches the scene's. Both are made
// linear (metres) from the [0, 1] depth of the projection; the scene depth is the D32
// float itself, not the seed's two 8-bit channels (eq. 3.1-3.4). Lit as a ball of snow:
// the sky everywhere, the sun by a half-Lambert term on the billboard's sphere normal
// (a cloud scatters light round to its shaded side).
constexpr std::string_view kFragment = R"(
layout(set = 0, binding = 1) uniform texture2D SceneDepth;
layout(set = 0, binding = 2) uniform sampler DepthSampler;
layout(location = 0) in vec2 v_corner;
layout(location = 1) in float v_alpha;
layout(location = 2) in float v_shade;
layout(location = 0) out vec4 out_color;
float metres(float depth) { return view.fade.x * view.fade.y / (view.fade.y - depth * (view.fade.y - view.fade.x)); }
void main() {
  float r2 = dot(v_corner, v_corner);
  if (r2 >= 1.0) discard;
  float scene = metres(texelFetch(sampler2D(SceneDepth, DepthSampler), ivec2(gl_FragCoord.xy), 0).r);
  float soft = clamp((scene - metres(gl_FragCoord.z)) / view.fade.z, 0.0, 1.0);
  float a = (1.0 - r2) * v_alpha * soft * view.fade.w;
  vec3 n = vec3(v_corner, sqrt(1.0 - r2));
  float sun = 0.5 + 0.5 * dot(n, view.sun.xyz);
  const vec3 kSkyTint = vec3(0.85, 0.97, 1.12), kSunTint = vec3(1.0, 0.97, 0.92);
  vec3 lit = v_shade * (view.right.w * kSkyTint + view.up.w * sun * sun * kSunTint);
  out_color = vec4(lit * a, a);  // premultiplied
}
)";
}  // namespace

std::string_view puffSimulateSource() {
  static const std::string s = std::string(kParticle) + std::string(kSimulate);
  return s;
}
std::string_view puffVertexSource() {
  static const std::string s = std::string(kParticle) + std::string(kView) + std::string(kVertex);
  return s;
}
std::string_view puffFragmentSource() {
  static const std::string s = std::string("#version 440\n") + std::string(kView) + std::string(kFragment);
  return s;
}

}  // namespace wg::snow
