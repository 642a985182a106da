// A deferred renderer that is not weathergen's: its own vertex format, camera block,
// descriptor sets, G-buffer and lights. It hosts a weathergen surface through the
// surface contract (docs/engine-api.md, "The surface contract") and the reflection alone:
//  1. compiles a graph with weathergen::compile (Options::surface) and reads the
//     reflection's "surface" object;
//  2. writes its G-buffer glue in GLSL and in HLSL from that object, moving every
//     surface resource to a set and binding of its own with the WG_ macros, and compiles
//     it with its own glslang;
//  3. renders a sphere into an RGBA16F G-buffer, then lights it in a full-screen pass
//     with two point lights, a directional light and a hemispheric ambient, on lavapipe
//     with VK_LAYER_KHRONOS_validation, for a dry and a snowy weather state that
//     weathergen::weather simulates and writes into the weather block, with its noise;
//  4. writes OUT_DIR/deferred-dry.png and deferred-snow.png and checks that snow
//     whitened the sphere's top and left its underside alone, and that the HLSL
//     surface's G-buffer matches the GLSL surface's.
// Any compile error, Vulkan error, validation message or failed check exits 1.
//
// usage: engine_plugin GRAPH.json OUT_DIR
#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>
#include <glslang/SPIRV/GlslangToSpv.h>
#include <stb/stb_image_write.h>  // the implementation lives in Debian's libstb.so
#include <vulkan/vulkan.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <deque>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>
#include <weathergen/weather.hpp>
#include <weathergen/weathergen.hpp>

namespace {

using nlohmann::json;

constexpr std::uint32_t kWidth = 256, kHeight = 256;
constexpr std::size_t kPixels = std::size_t(kWidth) * kHeight;
constexpr VkFormat kGBufferFormat = VK_FORMAT_R16G16B16A16_SFLOAT;
constexpr VkFormat kDepthFormat = VK_FORMAT_D32_SFLOAT;
constexpr VkFormat kLitFormat = VK_FORMAT_R8G8B8A8_UNORM;
constexpr std::uint32_t kGBufferTargets = 4;  // albedo, normal, material, emissive
// The host's descriptor sets: its camera in set 0, where weathergen puts the weather
// by default, so the surface's resources must move: the weather's to set 1, the
// material's to set 2.
constexpr std::uint32_t kCameraSet = 0, kWeatherSet = 1, kMaterialSet = 2;
constexpr VkShaderStageFlags kStages = VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT;

int validationMessages = 0;

VKAPI_ATTR VkBool32 VKAPI_CALL onValidationMessage(VkDebugUtilsMessageSeverityFlagBitsEXT,
                                                   VkDebugUtilsMessageTypeFlagsEXT,
                                                   const VkDebugUtilsMessengerCallbackDataEXT* data, void*) {
  std::fprintf(stderr, "validation: %s\n", data->pMessage);
  ++validationMessages;
  return VK_FALSE;
}

void check(VkResult result, const char* what) {
  if (result != VK_SUCCESS) throw std::runtime_error(std::string(what) + " failed: VkResult " + std::to_string(result));
}

// ---- Math: column-major 4x4 matrices, as GLSL's mat4 and HLSL's default column_major.

struct Vec3 {
  float x, y, z;
};
Vec3 operator-(Vec3 a, Vec3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
float dot(Vec3 a, Vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
Vec3 cross(Vec3 a, Vec3 b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
Vec3 normalize(Vec3 v) {
  float s = 1.f / std::sqrt(dot(v, v));
  return {v.x * s, v.y * s, v.z * s};
}

using Mat4 = std::array<float, 16>;  // m[column * 4 + row]

Mat4 operator*(const Mat4& a, const Mat4& b) {
  Mat4 r{};
  for (int c = 0; c < 4; ++c)
    for (int row = 0; row < 4; ++row)
      for (int k = 0; k < 4; ++k) r[c * 4 + row] += a[k * 4 + row] * b[c * 4 + k];
  return r;
}

// Right-handed, looking down -z, Vulkan's depth range [0, 1] and y flipped so that +y
// is up on screen.
Mat4 perspective(float fovY, float aspect, float nearZ, float farZ) {
  float f = 1.f / std::tan(fovY / 2.f);
  Mat4 m{};
  m[0] = f / aspect;
  m[5] = -f;
  m[10] = farZ / (nearZ - farZ);
  m[11] = -1.f;
  m[14] = nearZ * farZ / (nearZ - farZ);
  return m;
}

Mat4 lookAt(Vec3 eye, Vec3 target, Vec3 up) {
  Vec3 f = normalize(target - eye), s = normalize(cross(f, up)), u = cross(s, f);
  return {s.x, u.x, -f.x, 0, s.y, u.y, -f.y, 0, s.z, u.z, -f.z, 0, -dot(s, eye), -dot(u, eye), dot(f, eye), 1};
}

Mat4 scaledRotationY(float scale, float angle) {
  float c = scale * std::cos(angle), s = scale * std::sin(angle);
  return {c, 0, -s, 0, 0, scale, 0, 0, s, 0, c, 0, 0, 0, 0, 1};
}

// Gauss-Jordan elimination with partial pivoting, in double.
Mat4 inverse(const Mat4& m) {
  double a[4][8];
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) {
      a[r][c] = m[c * 4 + r];
      a[r][c + 4] = r == c;
    }
  for (int c = 0; c < 4; ++c) {
    int pivot = c;
    for (int r = c + 1; r < 4; ++r)
      if (std::abs(a[r][c]) > std::abs(a[pivot][c])) pivot = r;
    std::swap(a[c], a[pivot]);
    double p = a[c][c];
    for (double& v : a[c]) v /= p;
    for (int r = 0; r < 4; ++r)
      if (r != c) {
        double factor = a[r][c];
        for (int k = 0; k < 8; ++k) a[r][k] -= factor * a[c][k];
      }
  }
  Mat4 r;
  for (int row = 0; row < 4; ++row)
    for (int c = 0; c < 4; ++c) r[c * 4 + row] = float(a[row][c + 4]);
  return r;
}

Vec3 transformPoint(const Mat4& m, float x, float y, float z) {
  float v[4];
  for (int row = 0; row < 4; ++row) v[row] = m[row] * x + m[4 + row] * y + m[8 + row] * z + m[12 + row];
  return {v[0] / v[3], v[1] / v[3], v[2] / v[3]};
}

// ---- The host's scene: its own vertex format, a unit sphere, its camera.

struct HostVertex {
  float position[3], normal[3], tangent[4], uv[2];  // object space; tangent.w: bitangent sign
};

struct Mesh {
  std::vector<HostVertex> vertices;
  std::vector<std::uint32_t> indices;
};

// A UV sphere of radius 1: u runs with longitude, v from the north pole down, so the
// tangent is d/du and the bitangent cross(normal, tangent) is d/dv (sign +1).
Mesh sphere(std::uint32_t rings, std::uint32_t segments) {
  const float pi = 3.14159265f;
  Mesh mesh;
  for (std::uint32_t i = 0; i <= rings; ++i)
    for (std::uint32_t j = 0; j <= segments; ++j) {  // a seam column: u runs 0..1
      float u = float(j) / segments, v = float(i) / rings;
      float theta = v * pi, phi = u * 2.f * pi;
      float x = std::sin(theta) * std::cos(phi), y = std::cos(theta), z = std::sin(theta) * std::sin(phi);
      mesh.vertices.push_back({{x, y, z}, {x, y, z}, {-std::sin(phi), 0.f, std::cos(phi), 1.f}, {u, v}});
    }
  // Counter-clockwise seen from outside.
  for (std::uint32_t i = 0; i < rings; ++i)
    for (std::uint32_t j = 0; j < segments; ++j) {
      std::uint32_t a = i * (segments + 1) + j, b = a + segments + 1;
      mesh.indices.insert(mesh.indices.end(), {a, a + 1, b + 1, a, b + 1, b});
    }
  return mesh;
}

// A boulder 4 m across, so that the rock preset's 25 cm of snow looks its size.
constexpr float kRadius = 2.f;
const Vec3 kEye{0.f, 0.7f, 6.6f};
const Mat4 kModel = scaledRotationY(kRadius, 0.6f);  // the host owns the object transform
const Mat4 kViewProjection =
    perspective(0.785f, float(kWidth) / kHeight, 0.1f, 40.f) * lookAt(kEye, {0, 0, 0}, {0, 1, 0});
const Vec3 kSun = normalize({-0.5f, 0.8f, 0.35f});  // towards the sun: the weather's, and the host's light

// The host's camera block, at set 0, binding 0, in both glue languages.
struct CameraBlock {
  Mat4 viewProjection;
  Mat4 model;  // a rotation and a uniform scale: mat3(model) turns normals too
  float eye[4];
};

// ---- The surface's resources, placed where this host wants them.

// One resource the surface lists, at the host's set and binding.
struct Slot {
  json resource;
  std::uint32_t set, binding;
  VkDescriptorType type;
};

struct ResourcePlan {
  std::vector<Slot> slots;
  std::vector<std::string> defines;  // "NAME VALUE" for the glue's #defines
};

// The weather maps this host has; every other map it drops with its absentMacro, and
// the surface reads the map's documented fallback.
const std::set<std::string> kHostMaps = {"weatherNoise"};

// Every resource the surface lists goes to the host's weather or material set, numbered
// by the host's own convention (samplers first, then textures, then uniform blocks),
// and the surface's set and binding macros say so.
ResourcePlan planResources(const json& surface) {
  ResourcePlan plan;
  std::set<std::string> defined;
  auto define = [&](const std::string& macro, const std::string& value) {
    if (defined.insert(macro).second) plan.defines.push_back(value.empty() ? macro : macro + " " + value);
  };
  std::map<std::uint32_t, std::uint32_t> nextBinding;
  const std::pair<const char*, VkDescriptorType> kinds[] = {{"sampler", VK_DESCRIPTOR_TYPE_SAMPLER},
                                                            {"texture", VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE},
                                                            {"uniformBlock", VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER}};
  for (const auto& [kind, type] : kinds)
    for (const json& r : surface.at("resources")) {
      if (r.at("kind") != kind) continue;
      if (r.contains("absentMacro") && !kHostMaps.count(r.at("name").get<std::string>())) {
        define(r.at("absentMacro").get<std::string>(), "");
        continue;
      }
      std::uint32_t set = r.at("shared").get<bool>() ? kWeatherSet : kMaterialSet;
      std::uint32_t binding = nextBinding[set]++;
      define(r.at("setMacro").get<std::string>(), std::to_string(set));
      define(r.at("bindingMacro").get<std::string>(), std::to_string(binding));
      plan.slots.push_back({r, set, binding, type});
    }
  return plan;
}

const json& findResource(const json& surface, const std::string& identifier) {
  for (const json& r : surface.at("resources"))
    if (r.at("identifier") == identifier) return r;
  throw std::runtime_error("the surface lists no resource " + identifier);
}

// Writes values at a block member's reflected offset; the member's type must have as
// many floats.
void put(std::vector<std::byte>& block, const json& resource, const std::string& member, std::vector<float> values) {
  static const std::map<std::string, std::size_t> kFloats = {{"float", 1}, {"vec2", 2}, {"vec3", 3}, {"vec4", 4}};
  for (const json& m : resource.at("members"))
    if (m.at("name") == member) {
      auto floats = kFloats.find(m.at("type"));
      if (floats == kFloats.end() || floats->second != values.size())
        throw std::runtime_error(member + " is a " + m.at("type").get<std::string>());
      std::memcpy(block.data() + m.at("offset").get<std::size_t>(), values.data(), values.size() * sizeof(float));
      return;
    }
  throw std::runtime_error(resource.at("identifier").get<std::string>() + " has no member " + member);
}

// A named weather state from weathergen::weather's simulation: `hours` of the given
// conditions from a dry start.
struct WeatherState {
  const char* name;
  weathergen::weather::State state;
};

WeatherState simulate(const char* name, float temperature, float precipitation, double hours) {
  WeatherState w{name, {}};
  w.state.conditions.temperature = temperature;
  w.state.conditions.precipitation = precipitation;
  w.state.conditions.sunDirection = {kSun.x, kSun.y, kSun.z};
  const double kTimeScale = 3600.0;  // one real second is an hour of weather
  for (double second = 0.0; second < hours; second += 0.25)
    if (std::string reason = weathergen::weather::step(w.state, 0.25, kTimeScale); !reason.empty())
      throw std::runtime_error("weathergen::weather::step: " + reason);
  return w;
}

// The weather block: every field weathergen::weather fills, at the reflected offsets, and
// the terrain's height scale, which is the host's.
std::vector<std::byte> weatherBlock(const json& resource, const WeatherState& weather) {
  std::vector<std::byte> block(resource.at("size").get<std::size_t>());  // the maps' regions: none bound
  for (const weathergen::weather::BlockField& field : weathergen::weather::weatherBlock(weather.state))
    put(block, resource, field.name, {field.value.begin(), field.value.begin() + field.components});
  put(block, resource, "terrainHeightScale", {1.f});
  return block;
}

// The material's parameters at their defaults: the surface's block members carry the
// layout, the reflection's "blocks" the defaults, matched by name.
std::vector<std::byte> materialBlock(const json& reflection, const json& resource) {
  std::vector<std::byte> block(resource.at("size").get<std::size_t>());
  for (const json& b : reflection.at("blocks"))
    if (b.at("name") == resource.at("name"))
      for (const json& m : b.at("members")) {
        const json& value = m.at("default");
        put(block, resource, m.at("name"),
            value.is_array() ? value.get<std::vector<float>>() : std::vector<float>{value.get<float>()});
      }
  return block;
}

// rock.json's textures are procedural and the engine API does not generate texels, so
// the host binds one neutral texel for each of the material's textures.
std::array<std::uint8_t, 4> neutralTexel(const std::string& name) {
  if (name == "normalMap") return {128, 128, 255, 255};  // flat: the geometric normal
  if (name == "cracks") return {153, 153, 153, 0};       // alpha 0: no crevices
  return {136, 131, 124, 255};                           // between the albedo fBm's two colours
}

// ---- The glue, written from the reflection's "surface" object alone.

const std::map<std::string, std::string> kHlslTypes = {
    {"float", "float"}, {"vec2", "float2"}, {"vec3", "float3"}, {"vec4", "float4"}};

std::string hlslType(const std::string& glslType) {
  auto t = kHlslTypes.find(glslType);
  if (t == kHlslTypes.end()) throw std::runtime_error("the glue cannot pass a " + glslType + " between stages");
  return t->second;
}

// How this host fills each field of the surface's vertex input from its own vertex
// format and camera: {GLSL, HLSL}. The HLSL side reads the same column-major bytes as
// row_major matrices and multiplies mul(v, M): glslang then emits GLSL's very
// OpMatrixTimesVector, so both glues place every vertex bit for bit alike. (mul(M, v)
// on column_major matrices becomes OpVectorTimesMatrix, which rounds differently.)
const std::map<std::string, std::pair<std::string, std::string>> kVertexInput = {
    {"worldPosition", {"(host_model * vec4(in_position, 1.0)).xyz", "mul(float4(v.position, 1.0), host_model).xyz"}},
    {"worldNormal", {"normalize(mat3(host_model) * in_normal)", "normalize(mul(v.normal, (float3x3)host_model))"}},
    {"worldTangent",
     {"vec4(normalize(mat3(host_model) * in_tangent.xyz), in_tangent.w)",
      "float4(normalize(mul(v.tangent.xyz, (float3x3)host_model)), v.tangent.w)"}},
    {"texcoord", {"in_uv", "v.uv"}},
    {"texcoord1", {"in_uv", "v.uv"}},
    {"color", {"vec4(1.0)", "(float4)1.0"}},
    {"cameraPosition", {"host_eye.xyz", "host_eye.xyz"}},
};

// The G-buffer: what this host keeps of the surface's output, one RGBA16F target each.
const std::pair<const char*, const char*> kGBuffer[kGBufferTargets] = {
    {"gbuffer_albedo", "(o.baseColor, o.opacity)"},
    {"gbuffer_normal", "(o.normal, o.roughness)"},  // world space, signed: the targets are float
    {"gbuffer_material", "(o.metallic, o.specular, o.occlusion, o.snow)"},
    {"gbuffer_emissive", "(o.emissive, o.wet)"},
};

struct Glue {
  const json& surface;
  const ResourcePlan& plan;
  bool hlsl;
  std::string source;  // the surface text of this language

  const json& fields(const char* stage, const char* which) const {
    return surface.at("structs").at(surface.at(stage).at(which).get<std::string>());
  }

  // The stage macro and the host's placement macros, then the surface pasted in (as a
  // host without #include support would), then the host's camera block.
  std::string preamble(const char* stage) const {
    std::ostringstream s;
    if (!hlsl) s << "#version 450\n";
    s << "#define " << surface.at("stageMacros").at(stage).get<std::string>() << "\n";
    for (const std::string& d : plan.defines) s << "#define " << d << "\n";
    s << source << "\n";
    if (hlsl)
      s << "[[vk::binding(0, " << kCameraSet << ")]] cbuffer HostCamera : register(b0, space" << kCameraSet << ") {\n"
        << "  row_major float4x4 host_viewProjection;\n  row_major float4x4 host_model;\n  float4 host_eye;\n};\n";
    else
      s << "layout(set = " << kCameraSet << ", binding = 0, std140) uniform HostCamera {\n"
        << "  mat4 host_viewProjection;\n  mat4 host_model;\n  vec4 host_eye;\n};\n";
    return s.str();
  }

  // The vertex output's fields, each one varying, declared at consecutive locations.
  std::string varyings(const char* glslDirection) const {
    std::ostringstream s;
    int location = 0;
    for (const json& f : fields("vertex", "output")) {
      const std::string type = f.at("type"), name = f.at("name"), hlslName = hlslType(type);
      if (hlsl)
        s << "  [[vk::location(" << location << ")]] " << hlslName << " " << name << " : TEXCOORD" << location << ";\n";
      else
        s << "layout(location = " << location << ") " << glslDirection << " " << type << " v_" << name << ";\n";
      ++location;
    }
    return s.str();
  }

  std::string vertex() const {
    std::ostringstream s;
    const std::string in = surface.at("vertex").at("input"), out = surface.at("vertex").at("output");
    s << preamble("vertex");
    if (hlsl) {
      s << "struct HostVertex {\n  [[vk::location(0)]] float3 position : POSITION;\n"
        << "  [[vk::location(1)]] float3 normal : NORMAL;\n  [[vk::location(2)]] float4 tangent : TANGENT;\n"
        << "  [[vk::location(3)]] float2 uv : TEXCOORD0;\n};\n"
        << "struct HostVaryings {\n  float4 clip : SV_Position;\n"
        << varyings("") << "};\n"
        << "HostVaryings main(HostVertex v) {\n  " << in << " s = (" << in << ")0;\n";
    } else {
      s << "layout(location = 0) in vec3 in_position;\nlayout(location = 1) in vec3 in_normal;\n"
        << "layout(location = 2) in vec4 in_tangent;\nlayout(location = 3) in vec2 in_uv;\n"
        << varyings("out") << "void main() {\n  " << in << " s;\n";
    }
    for (const json& f : fields("vertex", "input")) {
      auto value = kVertexInput.find(f.at("name"));
      if (value == kVertexInput.end()) throw std::runtime_error("this host has no vertex input " + f.at("name").dump());
      s << "  s." << value->first << " = " << (hlsl ? value->second.second : value->second.first) << ";\n";
    }
    s << "  " << out << " o = " << surface.at("vertex").at("function").get<std::string>() << "(s);\n";
    if (hlsl) s << "  HostVaryings r;\n";
    for (const json& f : fields("vertex", "output")) {
      const std::string name = f.at("name");
      s << (hlsl ? "  r." : "  v_") << name << " = o." << name << ";\n";
    }
    // The host projects the displaced position.
    s << (hlsl ? "  r.clip = mul(float4(o.worldPosition, 1.0), host_viewProjection);\n  return r;\n}\n"
               : "  gl_Position = host_viewProjection * vec4(o.worldPosition, 1.0);\n}\n");
    return s.str();
  }

  std::string fragment() const {
    std::ostringstream s;
    const std::string in = surface.at("fragment").at("input"), out = surface.at("fragment").at("output");
    std::set<std::string> interpolated;
    for (const json& f : fields("vertex", "output")) interpolated.insert(f.at("name"));
    s << preamble("fragment");
    if (hlsl) {
      s << "struct HostVaryings {\n  float4 clip : SV_Position;\n" << varyings("") << "};\nstruct GBuffer {\n";
      for (std::uint32_t i = 0; i < kGBufferTargets; ++i)
        s << "  float4 " << kGBuffer[i].first << " : SV_Target" << i << ";\n";
      s << "};\nGBuffer main(HostVaryings v, bool frontFacing : SV_IsFrontFace) {\n  " << in << " s = (" << in
        << ")0;\n";
    } else {
      s << varyings("in");
      for (std::uint32_t i = 0; i < kGBufferTargets; ++i)
        s << "layout(location = " << i << ") out vec4 " << kGBuffer[i].first << ";\n";
      s << "void main() {\n  " << in << " s;\n";
    }
    for (const json& f : fields("fragment", "input")) {
      const std::string name = f.at("name");
      s << "  s." << name << " = ";
      if (interpolated.count(name))
        s << (hlsl ? "v." : "v_") << name << ";\n";
      else if (name == "frontFacing")
        s << (hlsl ? "frontFacing" : "gl_FrontFacing") << ";\n";
      else if (name == "cameraPosition")
        s << "host_eye.xyz;\n";
      else
        throw std::runtime_error("this host has no fragment input " + name);
    }
    s << "  " << out << " o = " << surface.at("fragment").at("function").get<std::string>() << "(s);\n";
    if (hlsl) {
      s << "  GBuffer g;\n";
      for (const auto& [target, value] : kGBuffer) s << "  g." << target << " = float4" << value << ";\n";
      s << "  return g;\n}\n";
    } else {
      for (const auto& [target, value] : kGBuffer) s << "  " << target << " = vec4" << value << ";\n";
      s << "}\n";
    }
    return s.str();
  }
};

// ---- The host's lighting: a full-screen pass over the G-buffer.

constexpr const char* kFullScreenVertex = R"(#version 450
void main() {  // one triangle over the whole target
  vec2 p = vec2((gl_VertexIndex << 1) & 2, gl_VertexIndex & 2);
  gl_Position = vec4(p * 2.0 - 1.0, 0.0, 1.0);
}
)";

// Two point lights, the sun and a sky/ground hemisphere; GGX specular, Lambert diffuse,
// world positions from depth. A filmic curve (Narkowicz's ACES fit), gamma 2.2.
constexpr const char* kLightingFragment = R"(#version 450
layout(set = 0, binding = 0, std140) uniform Lights {
  mat4 invViewProjection;
  vec4 eye;
  vec4 sunDirection;      // towards the sun
  vec4 sunColor;
  vec4 pointPosition[2];  // w: radius of influence
  vec4 pointColor[2];
  vec4 skyColor;
  vec4 groundColor;
};
layout(set = 0, binding = 1) uniform sampler2D gbufferAlbedo;
layout(set = 0, binding = 2) uniform sampler2D gbufferNormal;
layout(set = 0, binding = 3) uniform sampler2D gbufferMaterial;
layout(set = 0, binding = 4) uniform sampler2D gbufferEmissive;
layout(set = 0, binding = 5) uniform sampler2D gbufferDepth;
layout(location = 0) out vec4 outColor;

const float PI = 3.14159265;

vec3 shade(vec3 n, vec3 v, vec3 l, vec3 radiance, vec3 diffuse, vec3 f0, float roughness) {
  float nl = dot(n, l);
  if (nl <= 0.0) return vec3(0.0);
  vec3 h = normalize(l + v);
  float nv = max(dot(n, v), 1e-4), nh = max(dot(n, h), 0.0), vh = max(dot(v, h), 0.0);
  float a2 = pow(roughness, 4.0);  // alpha = roughness squared
  float d = a2 / (PI * pow(nh * nh * (a2 - 1.0) + 1.0, 2.0));
  float k = roughness * roughness * 0.5;
  float visibility = 0.25 / ((nl * (1.0 - k) + k) * (nv * (1.0 - k) + k));  // Smith-Schlick G / (4 nl nv)
  vec3 f = f0 + (1.0 - f0) * pow(1.0 - vh, 5.0);
  return (diffuse / PI + d * visibility * f) * radiance * nl;
}

vec3 hemisphere(float up) { return mix(groundColor.rgb, skyColor.rgb, up * 0.5 + 0.5); }

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  vec2 ndc = gl_FragCoord.xy / vec2(textureSize(gbufferDepth, 0)) * 2.0 - 1.0;
  float depth = texelFetch(gbufferDepth, pixel, 0).r;
  vec3 color = hemisphere(-ndc.y) * 0.5;  // the background; ndc.y is -1 at the top
  if (depth < 1.0) {
    vec4 albedo = texelFetch(gbufferAlbedo, pixel, 0);
    vec4 normalRoughness = texelFetch(gbufferNormal, pixel, 0);
    vec4 material = texelFetch(gbufferMaterial, pixel, 0);  // metallic, specular, occlusion, snow
    vec4 world = invViewProjection * vec4(ndc, depth, 1.0);
    vec3 p = world.xyz / world.w, n = normalize(normalRoughness.xyz), v = normalize(eye.xyz - p);
    float roughness = clamp(normalRoughness.w, 0.045, 1.0);
    vec3 diffuse = albedo.rgb * (1.0 - material.r);
    vec3 f0 = mix(vec3(0.08 * material.g), albedo.rgb, material.r);
    color = shade(n, v, sunDirection.xyz, sunColor.rgb, diffuse, f0, roughness);
    for (int i = 0; i < 2; ++i) {
      vec3 toLight = pointPosition[i].xyz - p;
      float d2 = dot(toLight, toLight);
      float window = clamp(1.0 - d2 / (pointPosition[i].w * pointPosition[i].w), 0.0, 1.0);
      color += shade(n, v, toLight * inversesqrt(d2), pointColor[i].rgb * window * window / d2, diffuse, f0, roughness);
    }
    color += hemisphere(n.y) * diffuse * material.b + texelFetch(gbufferEmissive, pixel, 0).rgb;
  }
  color = clamp(color * (2.51 * color + 0.03) / (color * (2.43 * color + 0.59) + 0.14), 0.0, 1.0);
  outColor = vec4(pow(color, vec3(1.0 / 2.2)), 1.0);
}
)";

struct LightsBlock {  // std140: only mat4 and vec4
  Mat4 invViewProjection;
  float eye[4];
  float sunDirection[4], sunColor[4];
  float pointPosition[2][4], pointColor[2][4];
  float skyColor[4], groundColor[4];
};

// ---- glslang, in-process: GLSL, or HLSL as glslangValidator -D -e main reads it.

std::vector<std::uint32_t> compileShader(const std::string& source, EShLanguage stage, bool hlsl,
                                         const std::string& what) {
  glslang::TShader shader(stage);
  const char* text = source.c_str();
  shader.setStrings(&text, 1);
  shader.setEnvInput(hlsl ? glslang::EShSourceHlsl : glslang::EShSourceGlsl, stage, glslang::EShClientVulkan, 100);
  shader.setEnvClient(glslang::EShClientVulkan, glslang::EShTargetVulkan_1_1);
  shader.setEnvTarget(glslang::EShTargetSpv, glslang::EShTargetSpv_1_3);
  shader.setEntryPoint("main");
  auto messages = EShMessages(EShMsgSpvRules | EShMsgVulkanRules | (hlsl ? EShMsgReadHlsl : EShMsgDefault));
  if (!shader.parse(GetDefaultResources(), 450, false, messages))
    throw std::runtime_error(what + " does not compile:\n" + shader.getInfoLog());
  glslang::TProgram program;
  program.addShader(&shader);
  if (!program.link(messages)) throw std::runtime_error(what + " does not link:\n" + program.getInfoLog());
  std::vector<std::uint32_t> spirv;
  glslang::GlslangToSpv(*program.getIntermediate(stage), spirv);
  return spirv;
}

// ---- Vulkan.

struct Gpu {
  VkInstance instance = VK_NULL_HANDLE;
  VkDebugUtilsMessengerEXT messenger = VK_NULL_HANDLE;
  VkPhysicalDevice physical = VK_NULL_HANDLE;
  VkPhysicalDeviceMemoryProperties memory{};
  VkDevice device = VK_NULL_HANDLE;
  VkQueue queue = VK_NULL_HANDLE;
  VkCommandPool pool = VK_NULL_HANDLE;
  VkCommandBuffer commands = VK_NULL_HANDLE;
  std::vector<std::function<void()>> destroy;  // run in reverse before the device goes
};

// Instance with VK_LAYER_KHRONOS_validation, the CPU device (lavapipe), a device with a
// graphics queue and one resettable command buffer.
void createGpu(Gpu& gpu) {
  std::uint32_t count = 0;
  vkEnumerateInstanceLayerProperties(&count, nullptr);
  std::vector<VkLayerProperties> layers(count);
  vkEnumerateInstanceLayerProperties(&count, layers.data());
  const char* validation = "VK_LAYER_KHRONOS_validation";
  if (std::none_of(layers.begin(), layers.end(), [&](const auto& l) { return std::string(l.layerName) == validation; }))
    throw std::runtime_error("VK_LAYER_KHRONOS_validation is not installed (vulkan-validationlayers)");

  VkDebugUtilsMessengerCreateInfoEXT messengerInfo{VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
  messengerInfo.messageSeverity =
      VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
  messengerInfo.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT |
                              VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                              VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
  messengerInfo.pfnUserCallback = onValidationMessage;
  VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
  app.pApplicationName = "weathergen engine-plugin example";
  app.apiVersion = VK_API_VERSION_1_1;
  const char* extension = VK_EXT_DEBUG_UTILS_EXTENSION_NAME;
  VkInstanceCreateInfo instanceInfo{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
  instanceInfo.pNext = &messengerInfo;  // also reports on vkCreateInstance and vkDestroyInstance
  instanceInfo.pApplicationInfo = &app;
  instanceInfo.enabledLayerCount = 1;
  instanceInfo.ppEnabledLayerNames = &validation;
  instanceInfo.enabledExtensionCount = 1;
  instanceInfo.ppEnabledExtensionNames = &extension;
  check(vkCreateInstance(&instanceInfo, nullptr, &gpu.instance), "vkCreateInstance");
  auto createMessenger = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
      vkGetInstanceProcAddr(gpu.instance, "vkCreateDebugUtilsMessengerEXT"));
  check(createMessenger(gpu.instance, &messengerInfo, nullptr, &gpu.messenger), "vkCreateDebugUtilsMessengerEXT");

  vkEnumeratePhysicalDevices(gpu.instance, &count, nullptr);
  std::vector<VkPhysicalDevice> devices(count);
  vkEnumeratePhysicalDevices(gpu.instance, &count, devices.data());
  for (VkPhysicalDevice d : devices) {
    VkPhysicalDeviceProperties properties;
    vkGetPhysicalDeviceProperties(d, &properties);
    if (properties.deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU && !gpu.physical) {
      gpu.physical = d;
      std::printf("device: %s\n", properties.deviceName);
    }
  }
  if (!gpu.physical) throw std::runtime_error("no CPU Vulkan device (lavapipe: mesa-vulkan-drivers)");
  vkGetPhysicalDeviceMemoryProperties(gpu.physical, &gpu.memory);

  vkGetPhysicalDeviceQueueFamilyProperties(gpu.physical, &count, nullptr);
  std::vector<VkQueueFamilyProperties> families(count);
  vkGetPhysicalDeviceQueueFamilyProperties(gpu.physical, &count, families.data());
  auto graphics = std::find_if(families.begin(), families.end(),
                               [](const auto& f) { return f.queueFlags & VK_QUEUE_GRAPHICS_BIT; });
  if (graphics == families.end()) throw std::runtime_error("the CPU device has no graphics queue");
  auto family = static_cast<std::uint32_t>(graphics - families.begin());
  float priority = 1.f;
  VkDeviceQueueCreateInfo queueInfo{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
  queueInfo.queueFamilyIndex = family;
  queueInfo.queueCount = 1;
  queueInfo.pQueuePriorities = &priority;
  VkDeviceCreateInfo deviceInfo{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
  deviceInfo.queueCreateInfoCount = 1;
  deviceInfo.pQueueCreateInfos = &queueInfo;
  check(vkCreateDevice(gpu.physical, &deviceInfo, nullptr, &gpu.device), "vkCreateDevice");
  vkGetDeviceQueue(gpu.device, family, 0, &gpu.queue);

  VkCommandPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
  poolInfo.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
  poolInfo.queueFamilyIndex = family;
  check(vkCreateCommandPool(gpu.device, &poolInfo, nullptr, &gpu.pool), "vkCreateCommandPool");
  VkCommandBufferAllocateInfo allocInfo{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
  allocInfo.commandPool = gpu.pool;
  allocInfo.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
  allocInfo.commandBufferCount = 1;
  check(vkAllocateCommandBuffers(gpu.device, &allocInfo, &gpu.commands), "vkAllocateCommandBuffers");
}

void destroyGpu(Gpu& gpu) {
  if (gpu.device) {
    vkDeviceWaitIdle(gpu.device);
    for (auto d = gpu.destroy.rbegin(); d != gpu.destroy.rend(); ++d) (*d)();
    vkDestroyCommandPool(gpu.device, gpu.pool, nullptr);
    vkDestroyDevice(gpu.device, nullptr);
  }
  if (gpu.messenger) {
    auto destroyMessenger = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(gpu.instance, "vkDestroyDebugUtilsMessengerEXT"));
    destroyMessenger(gpu.instance, gpu.messenger, nullptr);
  }
  if (gpu.instance) vkDestroyInstance(gpu.instance, nullptr);
}

VkDeviceMemory allocate(Gpu& gpu, const VkMemoryRequirements& requirements, VkMemoryPropertyFlags want) {
  VkMemoryAllocateInfo info{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
  info.allocationSize = requirements.size;
  info.memoryTypeIndex = UINT32_MAX;
  for (std::uint32_t i = 0; i < gpu.memory.memoryTypeCount && info.memoryTypeIndex == UINT32_MAX; ++i)
    if ((requirements.memoryTypeBits & (1u << i)) && (gpu.memory.memoryTypes[i].propertyFlags & want) == want)
      info.memoryTypeIndex = i;
  VkDeviceMemory memory;
  check(vkAllocateMemory(gpu.device, &info, nullptr, &memory), "vkAllocateMemory");
  gpu.destroy.push_back([&gpu, memory] { vkFreeMemory(gpu.device, memory, nullptr); });
  return memory;
}

// A host-visible, mapped buffer (an engine's allocator would do better).
struct Buffer {
  VkBuffer buffer = VK_NULL_HANDLE;
  void* mapped = nullptr;
};

Buffer createBuffer(Gpu& gpu, VkDeviceSize size, VkBufferUsageFlags usage, const void* contents = nullptr) {
  Buffer b;
  VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
  info.size = size;
  info.usage = usage;
  check(vkCreateBuffer(gpu.device, &info, nullptr, &b.buffer), "vkCreateBuffer");
  VkMemoryRequirements requirements;
  vkGetBufferMemoryRequirements(gpu.device, b.buffer, &requirements);
  VkDeviceMemory memory =
      allocate(gpu, requirements, VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
  gpu.destroy.push_back([&gpu, buffer = b.buffer] { vkDestroyBuffer(gpu.device, buffer, nullptr); });
  check(vkBindBufferMemory(gpu.device, b.buffer, memory, 0), "vkBindBufferMemory");
  check(vkMapMemory(gpu.device, memory, 0, size, 0, &b.mapped), "vkMapMemory");
  if (contents) std::memcpy(b.mapped, contents, size);
  return b;
}

struct Image {
  VkImage image = VK_NULL_HANDLE;
  VkImageView view = VK_NULL_HANDLE;
};

Image createImage(Gpu& gpu, VkFormat format, std::uint32_t width, std::uint32_t height, VkImageUsageFlags usage) {
  Image im;
  VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
  info.imageType = VK_IMAGE_TYPE_2D;
  info.format = format;
  info.extent = {width, height, 1};
  info.mipLevels = 1;
  info.arrayLayers = 1;
  info.samples = VK_SAMPLE_COUNT_1_BIT;
  info.tiling = VK_IMAGE_TILING_OPTIMAL;
  info.usage = usage;
  check(vkCreateImage(gpu.device, &info, nullptr, &im.image), "vkCreateImage");
  VkMemoryRequirements requirements;
  vkGetImageMemoryRequirements(gpu.device, im.image, &requirements);
  VkDeviceMemory memory = allocate(gpu, requirements, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
  gpu.destroy.push_back([&gpu, image = im.image] { vkDestroyImage(gpu.device, image, nullptr); });
  check(vkBindImageMemory(gpu.device, im.image, memory, 0), "vkBindImageMemory");
  VkImageViewCreateInfo viewInfo{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
  viewInfo.image = im.image;
  viewInfo.viewType = VK_IMAGE_VIEW_TYPE_2D;
  viewInfo.format = format;
  viewInfo.subresourceRange = {format == kDepthFormat ? VkImageAspectFlags(VK_IMAGE_ASPECT_DEPTH_BIT)
                                                      : VkImageAspectFlags(VK_IMAGE_ASPECT_COLOR_BIT),
                               0, 1, 0, 1};
  check(vkCreateImageView(gpu.device, &viewInfo, nullptr, &im.view), "vkCreateImageView");
  gpu.destroy.push_back([&gpu, view = im.view] { vkDestroyImageView(gpu.device, view, nullptr); });
  return im;
}

void beginCommands(const Gpu& gpu) {
  check(vkResetCommandBuffer(gpu.commands, 0), "vkResetCommandBuffer");
  VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  check(vkBeginCommandBuffer(gpu.commands, &begin), "vkBeginCommandBuffer");
}

// The host waits for each submission: the next one may then reuse every target.
void submitAndWait(const Gpu& gpu) {
  check(vkEndCommandBuffer(gpu.commands), "vkEndCommandBuffer");
  VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
  submit.commandBufferCount = 1;
  submit.pCommandBuffers = &gpu.commands;
  check(vkQueueSubmit(gpu.queue, 1, &submit, VK_NULL_HANDLE), "vkQueueSubmit");
  check(vkQueueWaitIdle(gpu.queue), "vkQueueWaitIdle");
}

void imageBarrier(VkCommandBuffer commands, VkImage image, VkImageLayout from, VkImageLayout to,
                  VkAccessFlags srcAccess, VkAccessFlags dstAccess, VkPipelineStageFlags srcStage,
                  VkPipelineStageFlags dstStage) {
  VkImageMemoryBarrier barrier{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER};
  barrier.srcAccessMask = srcAccess;
  barrier.dstAccessMask = dstAccess;
  barrier.oldLayout = from;
  barrier.newLayout = to;
  barrier.srcQueueFamilyIndex = barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  barrier.image = image;
  barrier.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
  vkCmdPipelineBarrier(commands, srcStage, dstStage, 0, 0, nullptr, 0, nullptr, 1, &barrier);
}

// An RGBA8 texture, uploaded once and left shader-readable.
Image createTexture(Gpu& gpu, std::uint32_t width, std::uint32_t height, const std::uint8_t* rgba8) {
  Image texture = createImage(gpu, VK_FORMAT_R8G8B8A8_UNORM, width, height,
                              VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT);
  Buffer staging = createBuffer(gpu, VkDeviceSize(width) * height * 4, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, rgba8);
  beginCommands(gpu);
  imageBarrier(gpu.commands, texture.image, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 0,
               VK_ACCESS_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT);
  VkBufferImageCopy region{};
  region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  region.imageExtent = {width, height, 1};
  vkCmdCopyBufferToImage(gpu.commands, staging.buffer, texture.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
  imageBarrier(gpu.commands, texture.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
               VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_ACCESS_TRANSFER_WRITE_BIT, VK_ACCESS_SHADER_READ_BIT,
               VK_PIPELINE_STAGE_TRANSFER_BIT,
               VK_PIPELINE_STAGE_VERTEX_SHADER_BIT | VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT);
  submitAndWait(gpu);
  return texture;
}

// A single-subpass render pass that clears its targets and leaves the colour ones in
// finalLayout (and depth readable), for the next pass's shaders or a copy.
VkRenderPass createRenderPass(Gpu& gpu, std::uint32_t colourTargets, VkFormat colourFormat, VkImageLayout finalLayout,
                              bool depth) {
  std::vector<VkAttachmentDescription> attachments;
  std::vector<VkAttachmentReference> colours;
  for (std::uint32_t i = 0; i < colourTargets; ++i) {
    attachments.push_back({0, colourFormat, VK_SAMPLE_COUNT_1_BIT, VK_ATTACHMENT_LOAD_OP_CLEAR,
                           VK_ATTACHMENT_STORE_OP_STORE, VK_ATTACHMENT_LOAD_OP_DONT_CARE,
                           VK_ATTACHMENT_STORE_OP_DONT_CARE, VK_IMAGE_LAYOUT_UNDEFINED, finalLayout});
    colours.push_back({i, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL});
  }
  VkAttachmentReference depthReference{colourTargets, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL};
  if (depth)
    attachments.push_back({0, kDepthFormat, VK_SAMPLE_COUNT_1_BIT, VK_ATTACHMENT_LOAD_OP_CLEAR,
                           VK_ATTACHMENT_STORE_OP_STORE, VK_ATTACHMENT_LOAD_OP_DONT_CARE,
                           VK_ATTACHMENT_STORE_OP_DONT_CARE, VK_IMAGE_LAYOUT_UNDEFINED,
                           VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL});
  VkSubpassDescription subpass{};
  subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
  subpass.colorAttachmentCount = colourTargets;
  subpass.pColorAttachments = colours.data();
  subpass.pDepthStencilAttachment = depth ? &depthReference : nullptr;
  // What the pass wrote is visible to the shaders and copies after it.
  VkSubpassDependency after{0,
                            VK_SUBPASS_EXTERNAL,
                            VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT | VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT,
                            VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT,
                            VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT,
                            VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_TRANSFER_READ_BIT,
                            0};
  VkRenderPassCreateInfo info{VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO};
  info.attachmentCount = static_cast<std::uint32_t>(attachments.size());
  info.pAttachments = attachments.data();
  info.subpassCount = 1;
  info.pSubpasses = &subpass;
  info.dependencyCount = 1;
  info.pDependencies = &after;
  VkRenderPass pass;
  check(vkCreateRenderPass(gpu.device, &info, nullptr, &pass), "vkCreateRenderPass");
  gpu.destroy.push_back([&gpu, pass] { vkDestroyRenderPass(gpu.device, pass, nullptr); });
  return pass;
}

VkFramebuffer createFramebuffer(Gpu& gpu, VkRenderPass pass, const std::vector<VkImageView>& views) {
  VkFramebufferCreateInfo info{VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO};
  info.renderPass = pass;
  info.attachmentCount = static_cast<std::uint32_t>(views.size());
  info.pAttachments = views.data();
  info.width = kWidth;
  info.height = kHeight;
  info.layers = 1;
  VkFramebuffer framebuffer;
  check(vkCreateFramebuffer(gpu.device, &info, nullptr, &framebuffer), "vkCreateFramebuffer");
  gpu.destroy.push_back([&gpu, framebuffer] { vkDestroyFramebuffer(gpu.device, framebuffer, nullptr); });
  return framebuffer;
}

VkDescriptorSetLayout createSetLayout(Gpu& gpu, const std::vector<VkDescriptorSetLayoutBinding>& bindings) {
  VkDescriptorSetLayoutCreateInfo info{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
  info.bindingCount = static_cast<std::uint32_t>(bindings.size());
  info.pBindings = bindings.data();
  VkDescriptorSetLayout layout;
  check(vkCreateDescriptorSetLayout(gpu.device, &info, nullptr, &layout), "vkCreateDescriptorSetLayout");
  gpu.destroy.push_back([&gpu, layout] { vkDestroyDescriptorSetLayout(gpu.device, layout, nullptr); });
  return layout;
}

VkPipelineLayout createPipelineLayout(Gpu& gpu, const std::vector<VkDescriptorSetLayout>& sets) {
  VkPipelineLayoutCreateInfo info{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
  info.setLayoutCount = static_cast<std::uint32_t>(sets.size());
  info.pSetLayouts = sets.data();
  VkPipelineLayout layout;
  check(vkCreatePipelineLayout(gpu.device, &info, nullptr, &layout), "vkCreatePipelineLayout");
  gpu.destroy.push_back([&gpu, layout] { vkDestroyPipelineLayout(gpu.device, layout, nullptr); });
  return layout;
}

VkShaderModule shaderModule(VkDevice device, const std::vector<std::uint32_t>& spirv) {
  VkShaderModuleCreateInfo info{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
  info.codeSize = spirv.size() * sizeof(std::uint32_t);
  info.pCode = spirv.data();
  VkShaderModule module;
  check(vkCreateShaderModule(device, &info, nullptr, &module), "vkCreateShaderModule");
  return module;
}

// The G-buffer pipeline (mesh: the host's vertex format, depth, back faces culled) or
// the lighting pipeline (a full-screen triangle).
VkPipeline createPipeline(Gpu& gpu, VkRenderPass pass, VkPipelineLayout layout,
                          const std::vector<std::uint32_t>& vertex, const std::vector<std::uint32_t>& fragment,
                          std::uint32_t colourTargets, bool mesh) {
  VkVertexInputBindingDescription binding{0, sizeof(HostVertex), VK_VERTEX_INPUT_RATE_VERTEX};
  VkVertexInputAttributeDescription attributes[] = {
      {0, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(HostVertex, position)},
      {1, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(HostVertex, normal)},
      {2, 0, VK_FORMAT_R32G32B32A32_SFLOAT, offsetof(HostVertex, tangent)},
      {3, 0, VK_FORMAT_R32G32_SFLOAT, offsetof(HostVertex, uv)},
  };
  VkPipelineVertexInputStateCreateInfo vertexInput{VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO};
  if (mesh) {
    vertexInput.vertexBindingDescriptionCount = 1;
    vertexInput.pVertexBindingDescriptions = &binding;
    vertexInput.vertexAttributeDescriptionCount = 4;
    vertexInput.pVertexAttributeDescriptions = attributes;
  }
  VkShaderModule modules[2] = {shaderModule(gpu.device, vertex), shaderModule(gpu.device, fragment)};
  VkPipelineShaderStageCreateInfo stages[2] = {{VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO},
                                               {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO}};
  stages[0].stage = VK_SHADER_STAGE_VERTEX_BIT;
  stages[1].stage = VK_SHADER_STAGE_FRAGMENT_BIT;
  for (int i = 0; i < 2; ++i) {
    stages[i].module = modules[i];
    stages[i].pName = "main";
  }
  VkPipelineInputAssemblyStateCreateInfo assembly{VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO};
  assembly.topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
  VkViewport viewport{0, 0, float(kWidth), float(kHeight), 0, 1};
  VkRect2D scissor{{0, 0}, {kWidth, kHeight}};
  VkPipelineViewportStateCreateInfo viewportState{VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO};
  viewportState.viewportCount = 1;
  viewportState.pViewports = &viewport;
  viewportState.scissorCount = 1;
  viewportState.pScissors = &scissor;
  VkPipelineRasterizationStateCreateInfo raster{VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO};
  raster.cullMode = mesh ? VK_CULL_MODE_BACK_BIT : VK_CULL_MODE_NONE;  // rock is one-sided and opaque
  raster.frontFace = VK_FRONT_FACE_COUNTER_CLOCKWISE;
  raster.lineWidth = 1.f;
  VkPipelineMultisampleStateCreateInfo multisample{VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO};
  multisample.rasterizationSamples = VK_SAMPLE_COUNT_1_BIT;
  VkPipelineDepthStencilStateCreateInfo depth{VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO};
  depth.depthTestEnable = mesh;
  depth.depthWriteEnable = mesh;
  depth.depthCompareOp = VK_COMPARE_OP_LESS;
  std::vector<VkPipelineColorBlendAttachmentState> blendAttachments(colourTargets);
  for (auto& b : blendAttachments) b.colorWriteMask = 0xF;
  VkPipelineColorBlendStateCreateInfo blend{VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO};
  blend.attachmentCount = colourTargets;
  blend.pAttachments = blendAttachments.data();

  VkGraphicsPipelineCreateInfo info{VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO};
  info.stageCount = 2;
  info.pStages = stages;
  info.pVertexInputState = &vertexInput;
  info.pInputAssemblyState = &assembly;
  info.pViewportState = &viewportState;
  info.pRasterizationState = &raster;
  info.pMultisampleState = &multisample;
  info.pDepthStencilState = &depth;
  info.pColorBlendState = &blend;
  info.layout = layout;
  info.renderPass = pass;
  VkPipeline pipeline;
  VkResult result = vkCreateGraphicsPipelines(gpu.device, VK_NULL_HANDLE, 1, &info, nullptr, &pipeline);
  for (VkShaderModule m : modules) vkDestroyShaderModule(gpu.device, m, nullptr);
  check(result, "vkCreateGraphicsPipelines");
  gpu.destroy.push_back([&gpu, pipeline] { vkDestroyPipeline(gpu.device, pipeline, nullptr); });
  return pipeline;
}

// ---- One frame: G-buffer pass, lighting pass, and the targets read back.

float halfToFloat(std::uint16_t h) {
  int exponent = (h >> 10) & 31, mantissa = h & 1023;
  float magnitude = exponent == 0    ? std::ldexp(float(mantissa), -24)
                    : exponent == 31 ? (mantissa ? NAN : INFINITY)
                                     : std::ldexp(float(mantissa | 1024), exponent - 25);
  return h & 0x8000 ? -magnitude : magnitude;
}

struct Frame {
  std::vector<float> gbuffer[3];  // albedo, normal, material: RGBA per pixel
  std::vector<std::uint8_t> lit;  // RGBA8, gamma-encoded
};

struct Renderer {
  VkRenderPass gbufferPass, lightingPass;
  Image targets[kGBufferTargets], depth, lit;
  VkFramebuffer gbufferFramebuffer, lightingFramebuffer;
  VkPipelineLayout gbufferLayout, lightingLayout;
  VkPipeline gbuffer[2], lighting;           // G-buffer: GLSL, HLSL surface
  std::vector<VkDescriptorSet> gbufferSets;  // camera, weather, material
  VkDescriptorSet lightingSet;
  Buffer vertices, indices;
  std::uint32_t indexCount;
  Buffer readback[3], litReadback;
  Buffer weather;  // the surface's WeatherBlock, refilled for each weather state
};

Frame render(const Gpu& gpu, const Renderer& r, VkPipeline gbuffer) {
  VkCommandBuffer c = gpu.commands;
  beginCommands(gpu);
  VkClearValue clears[kGBufferTargets + 1] = {};
  clears[kGBufferTargets].depthStencil = {1.f, 0};
  VkRenderPassBeginInfo begin{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
  begin.renderPass = r.gbufferPass;
  begin.framebuffer = r.gbufferFramebuffer;
  begin.renderArea = {{0, 0}, {kWidth, kHeight}};
  begin.clearValueCount = kGBufferTargets + 1;
  begin.pClearValues = clears;
  vkCmdBeginRenderPass(c, &begin, VK_SUBPASS_CONTENTS_INLINE);
  vkCmdBindPipeline(c, VK_PIPELINE_BIND_POINT_GRAPHICS, gbuffer);
  vkCmdBindDescriptorSets(c, VK_PIPELINE_BIND_POINT_GRAPHICS, r.gbufferLayout, 0,
                          static_cast<std::uint32_t>(r.gbufferSets.size()), r.gbufferSets.data(), 0, nullptr);
  VkDeviceSize offset = 0;
  vkCmdBindVertexBuffers(c, 0, 1, &r.vertices.buffer, &offset);
  vkCmdBindIndexBuffer(c, r.indices.buffer, 0, VK_INDEX_TYPE_UINT32);
  vkCmdDrawIndexed(c, r.indexCount, 1, 0, 0, 0);
  vkCmdEndRenderPass(c);

  begin.renderPass = r.lightingPass;
  begin.framebuffer = r.lightingFramebuffer;
  begin.clearValueCount = 1;
  vkCmdBeginRenderPass(c, &begin, VK_SUBPASS_CONTENTS_INLINE);
  vkCmdBindPipeline(c, VK_PIPELINE_BIND_POINT_GRAPHICS, r.lighting);
  vkCmdBindDescriptorSets(c, VK_PIPELINE_BIND_POINT_GRAPHICS, r.lightingLayout, 0, 1, &r.lightingSet, 0, nullptr);
  vkCmdDraw(c, 3, 1, 0, 0);
  vkCmdEndRenderPass(c);

  VkBufferImageCopy region{};
  region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  region.imageExtent = {kWidth, kHeight, 1};
  for (int i = 0; i < 3; ++i) {
    imageBarrier(c, r.targets[i].image, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                 VK_ACCESS_SHADER_READ_BIT, VK_ACCESS_TRANSFER_READ_BIT, VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT,
                 VK_PIPELINE_STAGE_TRANSFER_BIT);
    vkCmdCopyImageToBuffer(c, r.targets[i].image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, r.readback[i].buffer, 1,
                           &region);
  }
  vkCmdCopyImageToBuffer(c, r.lit.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, r.litReadback.buffer, 1, &region);
  VkMemoryBarrier toHost{VK_STRUCTURE_TYPE_MEMORY_BARRIER, nullptr, VK_ACCESS_TRANSFER_WRITE_BIT,
                         VK_ACCESS_HOST_READ_BIT};
  vkCmdPipelineBarrier(c, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &toHost, 0, nullptr, 0,
                       nullptr);
  submitAndWait(gpu);

  Frame frame;
  for (int i = 0; i < 3; ++i) {
    const auto* halves = static_cast<const std::uint16_t*>(r.readback[i].mapped);
    frame.gbuffer[i].resize(kPixels * 4);
    std::transform(halves, halves + kPixels * 4, frame.gbuffer[i].begin(), halfToFloat);
  }
  const auto* rgba8 = static_cast<const std::uint8_t*>(r.litReadback.mapped);
  frame.lit.assign(rgba8, rgba8 + kPixels * 4);
  return frame;
}

// ---- Checks.

enum class Region { kNone, kTop, kBottom };

// Which pixels see the undisplaced sphere's upper cap (world y above half the radius)
// or its lower cap (below minus half): a ray from the eye through each pixel's centre.
// Displaced snow grows outward and so still covers every pixel of the upper cap.
std::vector<Region> sphereRegions() {
  std::vector<Region> regions(kPixels, Region::kNone);
  Mat4 inv = inverse(kViewProjection);
  for (std::uint32_t y = 0; y < kHeight; ++y)
    for (std::uint32_t x = 0; x < kWidth; ++x) {
      Vec3 far = transformPoint(inv, (x + 0.5f) / kWidth * 2.f - 1.f, (y + 0.5f) / kHeight * 2.f - 1.f, 1.f);
      Vec3 d = normalize(far - kEye);
      float b = dot(kEye, d), disc = b * b - (dot(kEye, kEye) - kRadius * kRadius);
      if (disc <= 0.f) continue;
      float hitY = kEye.y + d.y * (-b - std::sqrt(disc));
      regions[y * kWidth + x] = hitY > 0.5f * kRadius    ? Region::kTop
                                : hitY < -0.5f * kRadius ? Region::kBottom
                                                         : Region::kNone;
    }
  return regions;
}

// The largest difference of any channel at any pixel.
float maxDifference(const std::vector<float>& a, const std::vector<float>& b) {
  float worst = 0.f;
  for (std::size_t i = 0; i < a.size(); ++i) worst = std::max(worst, std::abs(a[i] - b[i]));
  return worst;
}

struct RegionStats {
  std::size_t pixels = 0;
  double luminance = 0, snow = 0;
};

RegionStats stats(const Frame& f, const std::vector<Region>& regions, Region which) {
  RegionStats s;
  for (std::size_t p = 0; p < kPixels; ++p)
    if (regions[p] == which) {
      const float* albedo = &f.gbuffer[0][p * 4];
      s.luminance += 0.2126 * albedo[0] + 0.7152 * albedo[1] + 0.0722 * albedo[2];
      s.snow += f.gbuffer[2][p * 4 + 3];
      ++s.pixels;
    }
  if (s.pixels) {
    s.luminance /= double(s.pixels);
    s.snow /= double(s.pixels);
  }
  return s;
}

void writeText(const std::filesystem::path& path, const std::string& text) { std::ofstream(path) << text; }

// Compiles the graph's surfaces only: no SPIR-V of weathergen's own full shaders.
weathergen::Result compileSurface(const std::string& graphPath) {
  weathergen::initialize();
  std::ifstream file(graphPath);
  if (!file) throw std::runtime_error("cannot read " + graphPath);
  std::string graph((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
  weathergen::Options options;
  options.surface = true;
  options.spirv = false;
  weathergen::Result compiled = weathergen::compile(graphPath, graph, options);
  for (const weathergen::Diagnostic& d : compiled.diagnostics)
    std::printf("%s:%d:%d: %s %s: %s\n", d.file.c_str(), d.line, d.column, d.severity.c_str(), d.code.c_str(),
                d.message.c_str());
  if (!compiled.ok) throw std::runtime_error("the material does not compile");
  return compiled;
}

using Spirv = std::map<std::string, std::array<std::vector<std::uint32_t>, 2>>;  // language -> vertex, fragment

// Writes the G-buffer glue of the GLSL and the HLSL surface to OUT_DIR/glue and compiles it.
Spirv writeGlue(const weathergen::Result& compiled, const json& surface, const ResourcePlan& plan,
                const std::filesystem::path& outDir) {
  std::filesystem::create_directories(outDir / "glue");
  Spirv spirv;
  for (const weathergen::Surface& s : compiled.surfaces) {
    if (s.language == "glsles") continue;  // the ES text is for GL hosts
    Glue glue{surface, plan, s.language == "hlsl", s.source};
    const char* suffix = glue.hlsl ? "hlsl" : "glsl";
    std::string vertex = glue.vertex(), fragment = glue.fragment();
    writeText(outDir / "glue" / ("gbuffer.vert." + std::string(suffix)), vertex);
    writeText(outDir / "glue" / ("gbuffer.frag." + std::string(suffix)), fragment);
    spirv[s.language][0] =
        compileShader(vertex, EShLangVertex, glue.hlsl, std::string(suffix) + " G-buffer vertex glue");
    spirv[s.language][1] =
        compileShader(fragment, EShLangFragment, glue.hlsl, std::string(suffix) + " G-buffer fragment glue");
  }
  if (spirv.size() != 2) throw std::runtime_error("compile() returned no GLSL or no HLSL surface");
  return spirv;
}

// The mesh, the G-buffer and lit targets, both passes and the readback buffers.
void createTargets(Gpu& gpu, Renderer& r) {
  Mesh mesh = sphere(48, 96);
  r.vertices = createBuffer(gpu, mesh.vertices.size() * sizeof(HostVertex), VK_BUFFER_USAGE_VERTEX_BUFFER_BIT,
                            mesh.vertices.data());
  r.indices = createBuffer(gpu, mesh.indices.size() * sizeof(std::uint32_t), VK_BUFFER_USAGE_INDEX_BUFFER_BIT,
                           mesh.indices.data());
  r.indexCount = static_cast<std::uint32_t>(mesh.indices.size());

  const VkImageUsageFlags targetUsage =
      VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
  std::vector<VkImageView> gbufferViews;
  for (Image& t : r.targets)
    gbufferViews.push_back((t = createImage(gpu, kGBufferFormat, kWidth, kHeight, targetUsage)).view);
  r.depth = createImage(gpu, kDepthFormat, kWidth, kHeight,
                        VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT);
  gbufferViews.push_back(r.depth.view);
  r.lit = createImage(gpu, kLitFormat, kWidth, kHeight,
                      VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT);
  r.gbufferPass =
      createRenderPass(gpu, kGBufferTargets, kGBufferFormat, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, true);
  r.lightingPass = createRenderPass(gpu, 1, kLitFormat, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, false);
  r.gbufferFramebuffer = createFramebuffer(gpu, r.gbufferPass, gbufferViews);
  r.lightingFramebuffer = createFramebuffer(gpu, r.lightingPass, {r.lit.view});
  for (Buffer& b : r.readback) b = createBuffer(gpu, kPixels * 8, VK_BUFFER_USAGE_TRANSFER_DST_BIT);
  r.litReadback = createBuffer(gpu, kPixels * 4, VK_BUFFER_USAGE_TRANSFER_DST_BIT);
}

// The G-buffer pipelines (GLSL, HLSL) and the lighting pipeline; returns the set
// layouts: camera, weather, material, lighting.
std::vector<VkDescriptorSetLayout> createPipelines(Gpu& gpu, Renderer& r, const ResourcePlan& plan,
                                                   const Spirv& spirv) {
  // The G-buffer pass's sets: the host's camera, then the surface's resources where the
  // plan put them. The pipeline layout has only these bindings, so the validation layer
  // would report any resource the macros failed to move.
  std::vector<std::vector<VkDescriptorSetLayoutBinding>> setBindings(3);
  setBindings[kCameraSet].push_back({0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1, kStages, nullptr});
  for (const Slot& s : plan.slots) setBindings[s.set].push_back({s.binding, s.type, 1, kStages, nullptr});
  std::vector<VkDescriptorSetLayout> gbufferSetLayouts;
  for (const auto& bindings : setBindings) gbufferSetLayouts.push_back(createSetLayout(gpu, bindings));
  r.gbufferLayout = createPipelineLayout(gpu, gbufferSetLayouts);
  std::vector<VkDescriptorSetLayoutBinding> lightingBindings = {
      {0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1, VK_SHADER_STAGE_FRAGMENT_BIT, nullptr}};
  for (std::uint32_t b = 1; b <= kGBufferTargets + 1; ++b)
    lightingBindings.push_back(
        {b, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, VK_SHADER_STAGE_FRAGMENT_BIT, nullptr});
  VkDescriptorSetLayout lightingSetLayout = createSetLayout(gpu, lightingBindings);
  r.lightingLayout = createPipelineLayout(gpu, {lightingSetLayout});

  for (int i = 0; i < 2; ++i) {
    const auto& stages = spirv.at(i == 0 ? "glsl" : "hlsl");
    r.gbuffer[i] = createPipeline(gpu, r.gbufferPass, r.gbufferLayout, stages[0], stages[1], kGBufferTargets, true);
  }
  r.lighting = createPipeline(gpu, r.lightingPass, r.lightingLayout,
                              compileShader(kFullScreenVertex, EShLangVertex, false, "the lighting vertex shader"),
                              compileShader(kLightingFragment, EShLangFragment, false, "the lighting fragment shader"),
                              1, false);
  gbufferSetLayouts.push_back(lightingSetLayout);
  return gbufferSetLayouts;
}

// The uniform buffers, textures and samplers, and the descriptor sets that bind them.
void bindResources(Gpu& gpu, Renderer& r, const json& reflection, const ResourcePlan& plan,
                   const std::vector<VkDescriptorSetLayout>& setLayouts) {
  // Textures: the shared weather noise, and a neutral texel for each material texture.
  weathergen::weather::NoiseTexture noise = weathergen::weather::noiseTexture();
  if (noise.width <= 0 || noise.rgba8.size() != std::size_t(noise.width) * std::size_t(noise.height) * 4)
    throw std::runtime_error("weathergen::weather::noiseTexture() returned no texels");
  std::map<std::string, Image> textures;
  for (const Slot& s : plan.slots)
    if (s.resource.at("kind") == "texture") {
      const std::string name = s.resource.at("name");
      if (name == "weatherNoise") {
        textures[name] =
            createTexture(gpu, std::uint32_t(noise.width), std::uint32_t(noise.height), noise.rgba8.data());
      } else {
        std::array<std::uint8_t, 4> texel = neutralTexel(name);
        textures[name] = createTexture(gpu, 1, 1, texel.data());
      }
    }
  // One sampler fits all: the noise wants repeat, linear and maxLod 0, as do the texels.
  VkSamplerCreateInfo samplerInfo{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
  samplerInfo.magFilter = samplerInfo.minFilter = VK_FILTER_LINEAR;
  samplerInfo.addressModeU = samplerInfo.addressModeV = samplerInfo.addressModeW = VK_SAMPLER_ADDRESS_MODE_REPEAT;
  VkSampler sampler, nearest;
  check(vkCreateSampler(gpu.device, &samplerInfo, nullptr, &sampler), "vkCreateSampler");
  gpu.destroy.push_back([&gpu, sampler] { vkDestroySampler(gpu.device, sampler, nullptr); });
  samplerInfo.magFilter = samplerInfo.minFilter = VK_FILTER_NEAREST;  // the lighting pass fetches texels
  samplerInfo.addressModeU = samplerInfo.addressModeV = samplerInfo.addressModeW =
      VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
  check(vkCreateSampler(gpu.device, &samplerInfo, nullptr, &nearest), "vkCreateSampler");
  gpu.destroy.push_back([&gpu, nearest] { vkDestroySampler(gpu.device, nearest, nullptr); });

  // Uniform buffers: the host's camera and lights, the surface's weather and material.
  CameraBlock camera{kViewProjection, kModel, {kEye.x, kEye.y, kEye.z, 1.f}};
  Buffer cameraBuffer = createBuffer(gpu, sizeof camera, VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, &camera);
  const std::size_t weatherSize = findResource(reflection.at("surface"), "WeatherBlock").at("size");
  r.weather = createBuffer(gpu, weatherSize, VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
  std::map<std::string, Buffer> materialBuffers;  // by identifier
  for (const Slot& s : plan.slots)
    if (s.resource.at("kind") == "uniformBlock" && !s.resource.at("shared").get<bool>()) {
      std::vector<std::byte> block = materialBlock(reflection, s.resource);
      materialBuffers[s.resource.at("identifier")] =
          createBuffer(gpu, block.size(), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, block.data());
    }
  LightsBlock lights{inverse(kViewProjection),
                     {kEye.x, kEye.y, kEye.z, 1.f},
                     {kSun.x, kSun.y, kSun.z, 0.f},
                     {3.2f, 3.0f, 2.7f, 0.f},
                     {{3.6f, 0.6f, 3.6f, 9.f}, {-3.4f, -2.8f, 2.6f, 9.f}},
                     {{14.f, 7.f, 2.5f, 0.f}, {3.f, 6.f, 16.f, 0.f}},
                     {0.16f, 0.21f, 0.30f, 0.f},
                     {0.06f, 0.05f, 0.04f, 0.f}};
  Buffer lightsBuffer = createBuffer(gpu, sizeof lights, VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, &lights);

  // Descriptor sets.
  VkDescriptorPoolSize sizes[] = {{VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 8},
                                  {VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE, 16},
                                  {VK_DESCRIPTOR_TYPE_SAMPLER, 16},
                                  {VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, kGBufferTargets + 1}};
  VkDescriptorPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
  poolInfo.maxSets = 4;
  poolInfo.poolSizeCount = 4;
  poolInfo.pPoolSizes = sizes;
  VkDescriptorPool pool;
  check(vkCreateDescriptorPool(gpu.device, &poolInfo, nullptr, &pool), "vkCreateDescriptorPool");
  gpu.destroy.push_back([&gpu, pool] { vkDestroyDescriptorPool(gpu.device, pool, nullptr); });
  std::vector<VkDescriptorSet> sets(setLayouts.size());
  VkDescriptorSetAllocateInfo allocInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
  allocInfo.descriptorPool = pool;
  allocInfo.descriptorSetCount = static_cast<std::uint32_t>(sets.size());
  allocInfo.pSetLayouts = setLayouts.data();
  check(vkAllocateDescriptorSets(gpu.device, &allocInfo, sets.data()), "vkAllocateDescriptorSets");
  r.gbufferSets.assign(sets.begin(), sets.begin() + 3);
  r.lightingSet = sets[3];

  // The writes, all applied at once; the infos live in deques, which keep their addresses.
  std::vector<VkWriteDescriptorSet> writes;
  std::deque<VkDescriptorBufferInfo> bufferInfos;
  std::deque<VkDescriptorImageInfo> imageInfos;
  auto write = [&](VkDescriptorSet set, std::uint32_t binding, VkDescriptorType type) -> VkWriteDescriptorSet& {
    VkWriteDescriptorSet& w = writes.emplace_back(VkWriteDescriptorSet{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET});
    w.dstSet = set;
    w.dstBinding = binding;
    w.descriptorCount = 1;
    w.descriptorType = type;
    return w;
  };
  auto writeBuffer = [&](VkDescriptorSet set, std::uint32_t binding, const Buffer& b) {
    write(set, binding, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER).pBufferInfo =
        &bufferInfos.emplace_back(VkDescriptorBufferInfo{b.buffer, 0, VK_WHOLE_SIZE});
  };
  auto writeImage = [&](VkDescriptorSet set, std::uint32_t binding, VkDescriptorType type, VkSampler s,
                        VkImageView view, VkImageLayout layout) {
    write(set, binding, type).pImageInfo = &imageInfos.emplace_back(VkDescriptorImageInfo{s, view, layout});
  };
  writeBuffer(r.gbufferSets[kCameraSet], 0, cameraBuffer);
  for (const Slot& s : plan.slots) {
    VkDescriptorSet set = r.gbufferSets[s.set];
    const std::string kind = s.resource.at("kind");
    if (kind == "uniformBlock")
      writeBuffer(set, s.binding,
                  s.resource.at("shared").get<bool>() ? r.weather : materialBuffers.at(s.resource.at("identifier")));
    else if (kind == "texture")
      writeImage(set, s.binding, s.type, VK_NULL_HANDLE, textures.at(s.resource.at("name")).view,
                 VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
    else
      writeImage(set, s.binding, s.type, sampler, VK_NULL_HANDLE, VK_IMAGE_LAYOUT_UNDEFINED);
  }
  writeBuffer(r.lightingSet, 0, lightsBuffer);
  for (std::uint32_t i = 0; i < kGBufferTargets; ++i)
    writeImage(r.lightingSet, i + 1, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, nearest, r.targets[i].view,
               VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
  writeImage(r.lightingSet, kGBufferTargets + 1, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, nearest, r.depth.view,
             VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL);
  vkUpdateDescriptorSets(gpu.device, static_cast<std::uint32_t>(writes.size()), writes.data(), 0, nullptr);
}

int run(Gpu& gpu, const std::string& graphPath, const std::filesystem::path& outDir) {
  // 1. The surface and its reflection.
  const weathergen::Result compiled = compileSurface(graphPath);
  const json reflection = json::parse(compiled.reflectionJson);
  const json& surface = reflection.at("surface");
  std::printf("%s: surface %s, %zu resources\n", compiled.name.c_str(), surface.at("prefix").get<std::string>().c_str(),
              surface.at("resources").size());

  // 2. The host's placement of every resource, and its glue in both languages.
  const ResourcePlan plan = planResources(surface);
  for (const Slot& s : plan.slots)
    std::printf("  %-26s set %d binding %2d -> set %u binding %u\n",
                s.resource.at("identifier").get<std::string>().c_str(), s.resource.at("set").get<int>(),
                s.resource.at("binding").get<int>(), s.set, s.binding);
  for (const std::string& d : plan.defines)
    if (d.find(' ') == std::string::npos) std::printf("  %s: the map's fallback\n", d.c_str());
  const Spirv spirv = writeGlue(compiled, surface, plan, outDir);

  // 3. The host's Vulkan objects.
  Renderer r;
  createTargets(gpu, r);
  bindResources(gpu, r, reflection, plan, createPipelines(gpu, r, plan, spirv));

  // 4. Both weather states, each through the GLSL and the HLSL surface.
  // Dry: a mild day. Snow: three hours of heavy snowfall at -6 °C.
  const WeatherState states[] = {simulate("dry", 12.f, 0.f, 3.0), simulate("snow", -6.f, 1.f, 3.0)};
  std::printf("simulated snow level after 3 h of heavy snowfall at -6 C: %.3f\n", states[1].state.levels.snow);
  Frame glsl[2];
  bool ok = true;
  for (int i = 0; i < 2; ++i) {
    std::vector<std::byte> block = weatherBlock(findResource(surface, "WeatherBlock"), states[i]);
    std::memcpy(r.weather.mapped, block.data(), block.size());
    glsl[i] = render(gpu, r, r.gbuffer[0]);
    Frame hlsl = render(gpu, r, r.gbuffer[1]);
    float albedo = maxDifference(glsl[i].gbuffer[0], hlsl.gbuffer[0]);
    float normal = maxDifference(glsl[i].gbuffer[1], hlsl.gbuffer[1]);
    bool agree = albedo <= 1.f / 255.f && normal <= 1.f / 255.f;
    std::printf("%s: HLSL vs GLSL G-buffer, largest difference: albedo %.6f, normal %.6f (limit %.6f)%s\n",
                states[i].name, albedo, normal, 1.f / 255.f, agree ? "" : " FAILED");
    ok &= agree;
    std::filesystem::path png = outDir / ("deferred-" + std::string(states[i].name) + ".png");
    if (!stbi_write_png(png.c_str(), int(kWidth), int(kHeight), 4, glsl[i].lit.data(), int(kWidth) * 4))
      throw std::runtime_error("cannot write " + png.string());
    std::printf("wrote %s\n", png.c_str());
  }

  // 5. Snow whitened the upper cap and not the lower one. Three hours at -6 °C also
  // grow hoarfrost, which whitens every face a little, the underside too.
  std::vector<Region> regions = sphereRegions();
  RegionStats topDry = stats(glsl[0], regions, Region::kTop), topSnow = stats(glsl[1], regions, Region::kTop);
  RegionStats bottomDry = stats(glsl[0], regions, Region::kBottom),
              bottomSnow = stats(glsl[1], regions, Region::kBottom);
  bool whitened = topSnow.pixels > 500 && topSnow.luminance > topDry.luminance + 0.2 && topSnow.snow > 0.5;
  bool untouched = bottomSnow.pixels > 500 && bottomSnow.snow < 0.01 && topSnow.luminance > bottomSnow.luminance + 0.15;
  std::printf("top (%zu px): albedo luminance %.3f dry, %.3f snow; snow coverage %.3f%s\n", topSnow.pixels,
              topDry.luminance, topSnow.luminance, topSnow.snow, whitened ? "" : " FAILED");
  std::printf("bottom (%zu px): albedo luminance %.3f dry, %.3f snowy (frost); snow coverage %.3f%s\n",
              bottomSnow.pixels, bottomDry.luminance, bottomSnow.luminance, bottomSnow.snow, untouched ? "" : " FAILED");
  return ok && whitened && untouched ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  std::setvbuf(stdout, nullptr, _IOLBF, BUFSIZ);  // keeps stdout and stderr in order in logs
  if (argc != 3) {
    std::fprintf(stderr, "usage: engine_plugin GRAPH.json OUT_DIR\n");
    return 2;
  }
  glslang::InitializeProcess();
  Gpu gpu;
  int status = 0;
  try {
    createGpu(gpu);
    status = run(gpu, argv[1], argv[2]);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "engine_plugin: %s\n", e.what());
    status = 1;
  }
  destroyGpu(gpu);
  glslang::FinalizeProcess();
  if (validationMessages > 0) {
    std::fprintf(stderr, "engine_plugin: %d validation message(s)\n", validationMessages);
    status = 1;
  }
  if (status == 0)
    std::printf("engine_plugin: G-buffer from the GLSL and HLSL surfaces, own lights, no validation messages\n");
  return status;
}
