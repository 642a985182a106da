// The host contract of a weathered surface (--target surface, docs/engine-api.md,
// "The surface contract"): the two functions a host calls, their input and output
// structs, and every resource they read with the macros that move it. Computed once
// per material from its interface; the surface writer prints it and the reflection
// publishes it, so a host can generate its glue from either.
#pragma once
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "compiler/material_interface.hpp"

namespace wg {

enum class SurfaceLanguage : std::uint8_t {
  Glsl,    // Vulkan GLSL 450: separate textures and samplers, set and binding
  GlslEs,  // GLSL ES 3.10: combined samplers, binding only (textureGather needs 3.10)
  Hlsl,    // HLSL for Shader Model 5: register and space, [[vk::binding]] for Vulkan
};

struct SurfaceLanguageInfo {
  SurfaceLanguage language;
  std::string_view name;    // the reflection's surface.files key: "glsl", "glsles", "hlsl"
  std::string_view suffix;  // of the file name: NAME.surface.glsl...
};
std::span<const SurfaceLanguageInfo> surfaceLanguages();

struct SurfaceField {
  std::string name;
  std::string_view type;  // GLSL spelling: float, vec2..vec4, bool
};

struct SurfaceStruct {
  std::string name;  // prefixed with the material's identifier prefix
  std::vector<SurfaceField> fields;
};

enum class SurfaceResourceKind : std::uint8_t { UniformBlock, Texture, Sampler };
std::string_view surfaceResourceKindName(SurfaceResourceKind kind);  // "uniformBlock"...

struct SurfaceResource {
  std::string name;        // logical: "Weather", a map's or a texture's name, "Material"
  std::string identifier;  // as declared in the surface
  SurfaceResourceKind kind;
  bool shared;  // the weather's, declared once however many surfaces a shader includes
  std::uint32_t set, binding;          // the defaults
  std::string setMacro, bindingMacro;  // defined before the include, they move it
  std::string_view absentMacro;        // a shared map's: defined, the host binds none
};

struct SurfaceInterface {
  std::string prefix;  // the material's identifiers begin with it ("rock_")
  std::string vertexFunction, fragmentFunction;
  SurfaceStruct vertexInput, vertexOutput, fragmentInput, fragmentOutput;
  std::vector<SurfaceResource> resources;
  // The material's interface with every per-material identifier prefixed, so two
  // surfaces' globals never meet in one shader.
  MaterialInterface prefixed;
};

// Macros a host defines to include only one stage's function (and the library code it
// reaches) in a shader of that stage.
inline constexpr std::string_view kSurfaceVertexOnlyMacro = "WG_SURFACE_VERTEX";
inline constexpr std::string_view kSurfaceFragmentOnlyMacro = "WG_SURFACE_FRAGMENT";
// Defined by a host whose resources are its own (a Filament material's parameters): the
// surface then declares none, and the host declares, or #defines, every identifier of
// its resources, the uniform blocks' members included.
inline constexpr std::string_view kSurfaceHostResourcesMacro = "WG_HOST_DECLARES_RESOURCES";

// The weather's uniform block: every frame field the weather owns or places, named
// weather_<field>, std140. The same for every material.
const UniformBlock& surfaceWeatherBlock();

// The fragment output field an output slot (IrGraph::outputs) leaves in.
std::string_view surfaceOutputField(std::size_t slot);

// fileStem: the material's file stem (fileStemFor), from which its prefix is made.
SurfaceInterface buildSurfaceInterface(const MaterialInterface& mi, std::string_view fileStem);
// The same contract without a prefix, for a host whose shader holds one material (the
// reference host's full shaders): functions surfaceVertex and surfaceFragment, structs
// VertexInput..FragmentOutput, and the material's own identifiers.
SurfaceInterface buildEmbeddedSurfaceInterface(const MaterialInterface& mi);

}  // namespace wg
