// The frame and weather uniform block shared by every material, laid out from the one
// table of its members (nodes/frame_fields.hpp). Its members are fixed internal names;
// the runtime fills it from reflection. The weather's members are spelled as a
// surface reads them (weather_<name>), the host's as frame_<name>: the reference host
// declares this block for the surface it embeds.
#include "compiler/material_interface.hpp"
#include "nodes/frame_fields.hpp"

namespace wg {

InterfaceType interfaceTypeOf(FrameFieldType type) {
  switch (type) {
    case FrameFieldType::Float: return InterfaceType::Float;
    case FrameFieldType::Uint: return InterfaceType::Uint;
    case FrameFieldType::Vec2: return InterfaceType::Vec2;
    case FrameFieldType::Vec3: return InterfaceType::Vec3;
    case FrameFieldType::Vec4: return InterfaceType::Vec4;
    case FrameFieldType::Mat4: return InterfaceType::Mat4;
  }
  return InterfaceType::Float;
}

std::string frameMemberIdentifier(const FrameField& field) {
  return (field.owner == FrameFieldOwner::Host ? "frame_" : "weather_") + std::string(field.name);
}

namespace {
UniformBlock makeFrameBlock() {
  UniformBlock block;
  block.name = "Frame";
  block.identifier = "FrameBlock";
  block.set = 0;
  block.binding = 0;
  for (const auto& field : frameFields())
    block.members.push_back({std::string(field.name), frameMemberIdentifier(field), interfaceTypeOf(field.type)});
  layoutStd140(block);
  return block;
}
}  // namespace

const UniformBlock& frameBlock() {
  static const UniformBlock kBlock = makeFrameBlock();  // immutable; shared by every compile
  return kBlock;
}

}  // namespace wg
