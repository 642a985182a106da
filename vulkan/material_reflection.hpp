// The compiler's reflection JSON, parsed: the runtime's only source for descriptor
// layouts, uniform offsets and vertex formats.
#pragma once
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

namespace wg::vk {

struct ReflectedMember {
  std::string name, type;  // type: float, vec2, vec3, vec4, uint, mat4
  std::uint32_t offset = 0, size = 0;
  nlohmann::json defaultValue;  // material parameters only
};

struct ReflectedBlock {
  std::uint32_t set = 0, binding = 0, size = 0;
  std::vector<ReflectedMember> members;
  const ReflectedMember* find(std::string_view name) const;
};

struct ReflectedTexture {
  std::string name;
  std::uint32_t set = 0, binding = 0, samplerBinding = 0;
  std::string wrapU = "repeat", wrapV = "repeat";
  std::string minFilter = "linear", magFilter = "linear";
  std::string colorSpace = "linear";  // "srgb": upload with an _SRGB format
  nlohmann::json source;  // procedural generator or file
};

struct ReflectedVertexInput {
  std::string name, type;
  std::uint32_t location = 0;
};

struct MaterialReflection {
  std::string materialName, contentHash;
  ReflectedBlock frame, material;
  std::vector<ReflectedTexture> textures, weatherMaps;
  std::vector<ReflectedVertexInput> vertexInputs;
  bool alphaTested = false;
  std::string alphaMode = "opaque";  // "blend": blended colour pipeline, drawn after opaque objects
  bool doubleSided = false;
  bool blended() const { return alphaMode == "blend"; }
  const ReflectedTexture* weatherMap(std::string_view name) const;
};

// Throws std::runtime_error naming the JSON pointer on malformed reflection.
MaterialReflection parseReflection(const std::string& json);

// Byte size of a reflected vertex or uniform type.
std::uint32_t reflectedTypeSize(std::string_view type);

}  // namespace wg::vk
