// The graph's data types and the single implicit conversion (scalar splat).
#pragma once
#include <cstdint>
#include <optional>
#include <string_view>

namespace wg {

enum class ValueType : std::uint8_t { Float, Vec2, Vec3, Vec4, Bool, Texture };

// Number of float components; 1 for float and bool, 0 for texture.
int componentCount(ValueType type);
bool isFloatVector(ValueType type);  // float, vec2, vec3 or vec4
ValueType floatVectorOfWidth(int width);  // 1..4
std::string_view typeName(ValueType type);  // graph spelling: "float", "vec3", ...
std::optional<ValueType> parseTypeName(std::string_view name);

// The only implicit conversion: a float feeding a vecN port is splatted.
bool isImplicitlyConvertible(ValueType from, ValueType to);

}  // namespace wg
