// The frame and weather uniform block shared by every material. Its members are fixed
// internal names; the runtime fills it from reflection.
#include <array>

#include "compiler/material_interface.hpp"

namespace wg {

namespace {
struct FrameField {
  std::string_view name;
  InterfaceType type;
};
// Ordered so std140 packs without holes: matrices and vec4s first, then each vec3
// followed by a float, then the scalars.
constexpr std::array<FrameField, 26> kFrameFields = {{
    {"model", InterfaceType::Mat4},
    {"viewProjection", InterfaceType::Mat4},
    {"normalMatrix", InterfaceType::Mat4},  // inverse transpose of model
    {"lightViewProjection", InterfaceType::Mat4},  // world -> sun shadow-map clip space
    {"skyExposureRegion", InterfaceType::Vec4},    // xz origin, 1/size: world -> exposure-map uv
    {"terrainRegion", InterfaceType::Vec4},        // xz origin, 1/size: world -> height-map uv (eq. 3.11)
    {"cameraPosition", InterfaceType::Vec3},
    {"time", InterfaceType::Float},           // seconds
    {"sunDirection", InterfaceType::Vec3},    // unit vector towards the sun
    {"sunIntensity", InterfaceType::Float},   // [0, 1]: weather's sun strength; radiance = sunColor * this
    {"sunColor", InterfaceType::Vec3},        // linear radiance at full intensity
    {"ambientIntensity", InterfaceType::Float},
    {"skyColor", InterfaceType::Vec3},
    {"temperature", InterfaceType::Float},    // degrees Celsius
    {"windDirection", InterfaceType::Vec2},   // unit vector in world xz (y is up)
    {"windIntensity", InterfaceType::Float},  // [0, 1]
    {"precipitation", InterfaceType::Float},  // [0, 1]
    {"snowLevel", InterfaceType::Float},      // accumulated levels, each [0, 1]
    {"wetnessLevel", InterfaceType::Float},
    {"mossLevel", InterfaceType::Float},
    {"frostLevel", InterfaceType::Float},
    {"puddleLevel", InterfaceType::Float},
    {"exposure", InterfaceType::Float},       // tone-mapping exposure
    {"debugView", InterfaceType::Uint},       // 0 = lit; others select an AOV
    {"terrainHeightScale", InterfaceType::Float},  // metres per unit of the terrain height map
    {"shadowMapTexel", InterfaceType::Float},      // 1 / shadow-map size; 0 turns sun shadows off
}};
UniformBlock makeFrameBlock();
}  // namespace

const UniformBlock& frameBlock() {
  static const UniformBlock kBlock = makeFrameBlock();  // immutable; shared by every compile
  return kBlock;
}

namespace {
UniformBlock makeFrameBlock() {
  UniformBlock block;
  block.name = "Frame";
  block.identifier = "FrameBlock";
  block.set = 0;
  block.binding = 0;
  for (const auto& field : kFrameFields)
    block.members.push_back({std::string(field.name), "frame_" + std::string(field.name), field.type});
  layoutStd140(block);
  return block;
}
}  // namespace

}  // namespace wg
