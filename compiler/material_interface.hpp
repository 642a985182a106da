// The resource interface both languages share, computed once per material: the
// frame/weather block, the material parameter block (std140), texture and sampler
// bindings, vertex inputs and varyings. Backends print it; reflection publishes it.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "compiler/ir.hpp"

namespace wg {

struct FrameField;

enum class InterfaceType : std::uint8_t { Float, Vec2, Vec3, Vec4, Uint, Mat4 };

std::string_view interfaceTypeName(InterfaceType type);  // GLSL spelling, used in reflection
InterfaceType interfaceTypeOf(ValueType type);          // bool is stored as uint
enum class FrameFieldType : std::uint8_t;
InterfaceType interfaceTypeOf(FrameFieldType type);     // a frame field's (nodes/frame_fields.hpp)

struct BlockMember {
  std::string name;        // logical name (parameter name as the user wrote it)
  std::string identifier;  // emitted name
  InterfaceType type;
  std::uint32_t offset = 0;
  std::uint32_t size = 0;
  int parameter = -1;  // index into IrGraph::parameters for material members
};

struct UniformBlock {
  std::string name;        // logical block name
  std::string identifier;  // emitted block type name
  std::uint32_t set = 0, binding = 0;
  std::uint32_t size = 0;  // std140 size, a multiple of 16
  std::vector<BlockMember> members;
};

struct TextureBinding {
  int texture = -1;  // index into IrGraph::textures
  std::string name;
  std::string textureIdentifier, samplerIdentifier;
  std::uint32_t set = 1, textureBinding = 0, samplerBinding = 0;
  bool cube = false;  // a cube map; the rest are 2D textures
};

struct StageVariable {
  std::string name;        // logical name
  std::string identifier;  // emitted name
  InterfaceType type;
  std::uint32_t location = 0;
};

struct MaterialInterface {
  const UniformBlock* frame = nullptr;  // the shared frame block (frameBlock()); never copied
  UniformBlock material;  // empty members: the block is not emitted
  std::vector<TextureBinding> textures;
  // Shared weather maps (set 0) that some op of this material samples; their
  // bindings are fixed so every material agrees.
  std::vector<TextureBinding> weatherMaps;
  std::vector<StageVariable> vertexInputs;  // "texcoord1" only when the graph reads it
  std::vector<StageVariable> varyings;
  // IrGraph::interpolants[k] travels in varyings[interpolantVaryings[k]].
  std::vector<std::size_t> interpolantVaryings;
  bool hasTexcoord1() const;
};

// Lays out members with std140 rules (which glslang also applies to HLSL cbuffers).
void layoutStd140(UniformBlock& block);

MaterialInterface buildMaterialInterface(const IrGraph& graph);

// The frame and weather block every material shares (set 0, binding 0).
const UniformBlock& frameBlock();
// A frame member as shaders name it: weather_<name> for what the weather owns or
// places (a surface's names), frame_<name> for the host's.
std::string frameMemberIdentifier(const FrameField& field);

}  // namespace wg
