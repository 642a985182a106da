// A constant or CPU-evaluated value of one graph type.
#pragma once
#include <array>
#include <string>

#include "nodes/value_type.hpp"

namespace wg {

struct Value {
  ValueType type = ValueType::Float;
  std::array<float, 4> v{0.f, 0.f, 0.f, 0.f};  // bool: v[0] is 0 or 1; texture: v[0] is its index

  static Value scalar(float x) { return {ValueType::Float, {x, 0.f, 0.f, 0.f}}; }
  static Value vec2(float x, float y) { return {ValueType::Vec2, {x, y, 0.f, 0.f}}; }
  static Value vec3(float x, float y, float z) { return {ValueType::Vec3, {x, y, z, 0.f}}; }
  static Value vec4(float x, float y, float z, float w) { return {ValueType::Vec4, {x, y, z, w}}; }
  static Value boolean(bool b) { return {ValueType::Bool, {b ? 1.f : 0.f, 0.f, 0.f, 0.f}}; }
  static Value texture(int index) {
    return {ValueType::Texture, {static_cast<float>(index), 0.f, 0.f, 0.f}};
  }

  int width() const { return componentCount(type); }
  float x() const { return v[0]; }
  bool asBool() const { return v[0] != 0.f; }
  // Component i, splatting scalars (the one implicit conversion).
  float at(int i) const { return width() == 1 ? v[0] : v[i]; }
  // This value converted to `target` (scalar splat or identity).
  Value convertedTo(ValueType target) const;
  bool allFinite() const;

  friend bool operator==(const Value&, const Value&) = default;
};

// Shortest text that round-trips the float exactly, always with a '.' or exponent
// ("1.0", "0.25", "1e-07"); locale-independent, so emitted code is deterministic.
std::string formatFloat(float x);
// formatFloat's text, appended to out without a temporary.
void appendFloat(std::string& out, float x);

}  // namespace wg
