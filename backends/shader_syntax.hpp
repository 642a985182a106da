// What a target language looks like: type names, literals, splats, sampling calls and
// the declarations and entry point around a stage. Backends know syntax, not materials or weather.
#pragma once
#include <string>
#include <string_view>
#include <vector>

#include "compiler/material_interface.hpp"
#include "compiler/pbr_output.hpp"
#include "nodes/op_definition.hpp"
#include "nodes/shader_stage.hpp"

namespace wg {

// The GLSL version of every stage we write and of the host's own shaders. glslang sets
// up its built-in functions once per version in a process; from 4.50 on they add the
// ray-tracing and mesh stages, which double that setup (half of a one-material
// `weathergen compile`), and nothing we write needs 4.50.
inline constexpr int kGlslVersion = 440;
inline constexpr std::string_view kGlslVersionLine = "#version 440\n";

// One stage's code before a language's frame wraps it: the material's node statements
// and the libraries they call.
struct StageSource {
  ShaderStage stage = ShaderStage::Fragment;
  const MaterialInterface* interface = nullptr;
  std::vector<const ShaderLibrary*> libraries;  // dependency order
  // Node statements, in the surface functions' names (frame members as
  // backends/surface_names.hpp spells them, interpolants as wg_out./wg_in. fields),
  // then the locals the frame reads: wg_baseColor, wg_metallic,
  // wg_roughness, wg_specular, wg_normal, wg_occlusion, wg_emissive, wg_opacity and the
  // wg_coverage_* terms (fragment), or wg_offset (vertex). The frame provides
  // wg_texcoord1 when the interface has the "texcoord1" input.
  std::string body;
  std::vector<std::string_view> bodyCalls;  // the library functions the body calls
};

// A full stage as the reference host (backends/reference_host.hpp) hands it to a
// language: the language declares the resources and stage IO and wraps the entry point.
struct HostedStage {
  ShaderStage stage = ShaderStage::Fragment;
  const MaterialInterface* interface = nullptr;
  std::string banner;   // first comment line: generator and content hash
  std::string surface;  // the embedded surface: library code, structs, function
  // The entry point's statements in this language; the fragment's leave wg_color and
  // wg_alpha for the language to write out.
  std::string main;
};

class ShaderSyntax {
 public:
  virtual ~ShaderSyntax() = default;
  virtual ShaderLanguage language() const = 0;
  virtual std::string_view typeName(ValueType type) const = 0;
  virtual std::string splat(ValueType to, std::string_view scalar) const = 0;
  virtual std::string_view sampleFunction(ShaderStage stage) const = 0;
  virtual std::string_view lodArgument(ShaderStage stage) const = 0;
  virtual std::string assemble(const HostedStage& stage) const = 0;
  // Shader code is written once, in GLSL: a library, an op's template (its "{...}"
  // placeholders untouched) and the stage frame's statements, in this language.
  virtual std::string_view libraryCode(const ShaderLibrary& library) const = 0;
  virtual std::string_view opCode(const OpDef& op) const = 0;
  virtual std::string frameCode(std::string_view glsl, ShaderStage stage) const = 0;
  // A varying as the stage's code reads or writes it: the vertex stage's output, the
  // fragment stage's input.
  virtual std::string stageVariable(std::string_view identifier, ShaderStage stage) const = 0;

  void appendConstant(std::string& out, const Value& value) const;
  // A parameter's value from its block member (bools are stored as uint).
  void appendParameterRead(std::string& out, const BlockMember& member, ValueType type) const;
};

const ShaderSyntax& glslSyntax();
const ShaderSyntax& hlslSyntax();
const ShaderSyntax& syntaxFor(ShaderLanguage language);

}  // namespace wg
