#include "nodes/value_type.hpp"

#include <array>

namespace wg {

namespace {
constexpr std::array<std::string_view, 6> kTypeNames = {"float", "vec2", "vec3",
                                                         "vec4",  "bool", "texture"};
}

int componentCount(ValueType type) {
  switch (type) {
    case ValueType::Float: return 1;
    case ValueType::Vec2: return 2;
    case ValueType::Vec3: return 3;
    case ValueType::Vec4: return 4;
    case ValueType::Bool: return 1;
    case ValueType::Texture: return 0;
  }
  return 0;
}

bool isFloatVector(ValueType type) {
  return type == ValueType::Float || type == ValueType::Vec2 || type == ValueType::Vec3 ||
         type == ValueType::Vec4;
}

ValueType floatVectorOfWidth(int width) {
  switch (width) {
    case 2: return ValueType::Vec2;
    case 3: return ValueType::Vec3;
    case 4: return ValueType::Vec4;
    default: return ValueType::Float;
  }
}

std::string_view typeName(ValueType type) { return kTypeNames[static_cast<int>(type)]; }

std::optional<ValueType> parseTypeName(std::string_view name) {
  for (std::size_t i = 0; i < kTypeNames.size(); ++i)
    if (kTypeNames[i] == name) return static_cast<ValueType>(i);
  return std::nullopt;
}

bool isImplicitlyConvertible(ValueType from, ValueType to) {
  if (from == to) return true;
  return from == ValueType::Float && isFloatVector(to);
}

}  // namespace wg
