#include "vulkan/material_reflection.hpp"

#include <stdexcept>

namespace wg::vk {

const ReflectedMember* ReflectedBlock::find(std::string_view name) const {
  for (const auto& m : members)
    if (m.name == name) return &m;
  return nullptr;
}

const ReflectedTexture* MaterialReflection::weatherMap(std::string_view name) const {
  for (const auto& t : weatherMaps)
    if (t.name == name) return &t;
  return nullptr;
}

std::uint32_t reflectedTypeSize(std::string_view type) {
  if (type == "float" || type == "uint") return 4;
  if (type == "vec2") return 8;
  if (type == "vec3") return 12;
  if (type == "vec4") return 16;
  if (type == "mat4") return 64;
  throw std::runtime_error("reflection: unknown type '" + std::string(type) + "'");
}

namespace {
ReflectedBlock parseBlock(const nlohmann::json& j) {
  ReflectedBlock b;
  b.set = j.at("set");
  b.binding = j.at("binding");
  b.size = j.at("size");
  for (const auto& m : j.at("members"))
    b.members.push_back({m.at("name"), m.at("type"), m.at("offset"), m.at("size"), m.value("default", nlohmann::json())});
  return b;
}

// Per-axis and per-direction settings fall back to "wrap" and "filter", which weather
// maps (and reflection written before them) carry alone.
std::vector<ReflectedTexture> parseTextures(const nlohmann::json& list) {
  std::vector<ReflectedTexture> out;
  for (const auto& t : list) {
    const std::string wrap = t.value("wrap", "repeat"), filter = t.value("filter", "linear");
    out.push_back({t.at("name"), t.at("set"), t.at("binding"), t.at("samplerBinding"), t.value("wrapU", wrap),
                   t.value("wrapV", wrap), t.value("minFilter", filter), t.value("magFilter", filter),
                   t.value("colorSpace", "linear"), t.value("source", nlohmann::json())});
  }
  return out;
}
}  // namespace

MaterialReflection parseReflection(const std::string& text) {
  try {
    auto j = nlohmann::json::parse(text);
    MaterialReflection r;
    r.materialName = j.at("material");
    r.contentHash = j.at("contentHash");
    for (const auto& block : j.at("blocks")) {
      std::string name = block.at("name");
      if (name == "Frame") r.frame = parseBlock(block);
      else if (name == "Material") r.material = parseBlock(block);
    }
    r.textures = parseTextures(j.at("textures"));
    r.weatherMaps = parseTextures(j.at("weatherMaps"));
    for (const auto& v : j.at("vertexInputs")) r.vertexInputs.push_back({v.at("name"), v.at("type"), v.at("location")});
    r.alphaTested = j.at("alphaTested");
    r.alphaMode = j.value("alphaMode", r.alphaTested ? "mask" : "opaque");
    r.doubleSided = j.value("doubleSided", false);
    return r;
  } catch (const nlohmann::json::exception& e) {
    throw std::runtime_error(std::string("malformed reflection JSON: ") + e.what());
  }
}

}  // namespace wg::vk
