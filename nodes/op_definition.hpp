// One node op, defined once: typed signature with defaults, CPU semantics (constant
// folding and the CPU evaluator) and code templates for each backend.
#pragma once
#include <array>
#include <limits>
#include <optional>
#include <string_view>
#include <vector>

#include "nodes/value.hpp"
#include "nodes/frame_state.hpp"

namespace wg {

// A port's declared type. Generic is "T": float, vec2, vec3 or vec4, the same T for
// every generic port of the node (a float may feed any of them by splat). Text is a
// static string setting (e.g. swizzle channels); TextureName names a declared texture.
enum class PortType : std::uint8_t { Float, Vec2, Vec3, Vec4, Bool, Generic, TextureName, Text };

struct PortSpec {
  std::string_view name;
  PortType type;
  std::optional<Value> defaultValue;  // nullopt: the input is required
  float min = -std::numeric_limits<float>::infinity();  // literal range, checked at load
  float max = std::numeric_limits<float>::infinity();
};

// An output reads the op's value through an accessor: "" for the whole value or a
// swizzle such as ".rgb" or ".x". Accessors are spelled alike in GLSL and HLSL and the
// CPU evaluator applies the same swizzle, so multi-output ops share one temporary.
struct OutputSpec {
  std::string_view name;
  std::string_view accessor;
};

// Geometry and time the CPU evaluator feeds to ops that read the surface.
struct SurfacePoint {
  std::array<float, 3> worldPosition{0.f, 0.f, 0.f};
  std::array<float, 3> worldNormal{0.f, 1.f, 0.f};
  std::array<float, 4> tangent{1.f, 0.f, 0.f, 1.f};
  std::array<float, 2> texcoord{0.f, 0.f};
  std::array<float, 2> texcoord1{0.f, 0.f};  // the second set (glTF TEXCOORD_1)
  std::array<float, 4> vertexColor{1.f, 1.f, 1.f, 1.f};
  // What the GPU reads from the shared weather maps at this point.
  float skyExposure = 1.f;  // 1: open sky; 0: fully sheltered
  // The snow deformation map's texel: height offset (m), then the world normal.
  std::array<float, 4> snowDeformation{0.f, 0.f, 1.f, 0.f};
  float sunVisibility = 1.f;  // the sun shadow map's answer: 1 lit, 0 in shadow
};

struct TextureSampler;  // nodes/texture_sampling.hpp
struct HeightField;     // nodes/height_field.hpp

struct EvalContext {
  const SurfacePoint* surface = nullptr;
  const TextureSampler* textures = nullptr;  // null while constant folding
  const std::vector<Value>* parameters = nullptr;
  const FrameState* frame = nullptr;
  const HeightField* terrainHeight = nullptr;  // null: flat terrain
  // Node-level settings (resolved by the compiler).
  std::string_view text;  // swizzle channels
  int parameterIndex = -1;
};

using CpuEval = Value (*)(const Value* inputs, const EvalContext& context);

// Shader library code shared by ops (noise, normal blending...). Emitted once, in
// dependency order, only when an op that needs it is used. Written once, in GLSL; the
// HLSL backend derives its own text from it (backends/glsl_to_hlsl.hpp).
struct ShaderLibrary {
  std::string_view name;
  std::string_view glsl;
  std::vector<const ShaderLibrary*> dependencies;
};

enum class OpPurity : std::uint8_t {
  Pure,     // depends only on its inputs: folded when they are all constant
  Varying,  // reads geometry, time, textures or parameters: never folded
};

// Which stage may compute an op's value (compiler/passes/vertex_rate.cpp).
enum class OpRate : std::uint8_t {
  Pixel,   // the fragment stage only: derivatives, mip-mapped samples, the facing-corrected frame
  Any,     // the vertex stage computes the same expression (geometry before the vertex offset)
  Vertex,  // as Any, and smooth across a triangle: the fragment stage may read it interpolated
};

// How the op's value type is found.
enum class ValueRule : std::uint8_t {
  Fixed,        // OpDef::valueType
  Generic,      // T, the widest generic input
  SwizzleText,  // as many components as the "channels" text
  Parameter,    // the referenced parameter's type
};

struct OpDef {
  std::string_view name;
  std::string_view category;
  std::string_view summary;
  std::vector<PortSpec> inputs;
  ValueRule valueRule = ValueRule::Generic;
  ValueType valueType = ValueType::Float;  // for ValueRule::Fixed
  // The value's expression: "{port}" is an input expression, "{T}" the value type,
  // "{@symbol}" a symbol the shader writer provides (geometry, time, bindings); checked
  // when the registry is built (nodes/op_template_check.hpp).
  std::string_view glsl;
  // Empty: the HLSL backend derives the template from glsl. Set it only for code no
  // token map can derive, with a comment saying why (no op needs one today).
  std::string_view hlsl;
  std::vector<OutputSpec> outputs;
  CpuEval eval = nullptr;
  OpPurity purity = OpPurity::Pure;
  std::vector<const ShaderLibrary*> libraries;
  // Shared weather maps the op samples (set 0): "terrainHeight", "skyExposure",
  // "snowDeformation".
  std::vector<std::string_view> weatherMaps;
  OpRate rate = OpRate::Pixel;  // Pixel unless vetted for the vertex stage

  const PortSpec* findInput(std::string_view port) const;
  int findOutput(std::string_view output) const;
};

// The single "out" output most ops have.
inline std::vector<OutputSpec> singleOutput() { return {{"out", ""}}; }

// Applies an accessor (".xyz", ".r", "") to a CPU value.
Value applyAccessor(const Value& value, std::string_view accessor);
// Component count an accessor yields from a value of `width` components, or 0 when
// it reads a component the value lacks.
int accessorWidth(std::string_view accessor, int width);

}  // namespace wg
