// The frame and weather uniform block shared by every material, laid out from the one
// table of its members (nodes/frame_fields.hpp). Its members are fixed internal names;
// the runtime fills it from reflection.
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

namespace {
UniformBlock makeFrameBlock() {
  UniformBlock block;
  block.name = "Frame";
  block.identifier = "FrameBlock";
  block.set = 0;
  block.binding = 0;
  for (const auto& field : frameFields())
    block.members.push_back({std::string(field.name), "frame_" + std::string(field.name), interfaceTypeOf(field.type)});
  layoutStd140(block);
  return block;
}
}  // namespace

const UniformBlock& frameBlock() {
  static const UniformBlock kBlock = makeFrameBlock();  // immutable; shared by every compile
  return kBlock;
}

}  // namespace wg
