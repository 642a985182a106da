// Component-wise CPU kernels for generic (float..vec4) ops. The result width is the
// widest input; narrower inputs are scalars and splat, matching the shader semantics.
#pragma once
#include <algorithm>

#include "nodes/value.hpp"

namespace wg {

inline ValueType widestType(std::initializer_list<const Value*> values) {
  int width = 1;
  for (const Value* v : values) width = std::max(width, v->width());
  return floatVectorOfWidth(width);
}

template <typename F>
Value mapComponents(const Value& a, F&& f) {
  Value out{a.type, {}};
  for (int i = 0; i < a.width(); ++i) out.v[i] = f(a.v[i]);
  return out;
}

template <typename F>
Value mapComponents(const Value& a, const Value& b, F&& f) {
  Value out{widestType({&a, &b}), {}};
  for (int i = 0; i < out.width(); ++i) out.v[i] = f(a.at(i), b.at(i));
  return out;
}

template <typename F>
Value mapComponents(const Value& a, const Value& b, const Value& c, F&& f) {
  Value out{widestType({&a, &b, &c}), {}};
  for (int i = 0; i < out.width(); ++i) out.v[i] = f(a.at(i), b.at(i), c.at(i));
  return out;
}

inline float dotProduct(const Value& a, const Value& b) {
  float sum = 0.f;
  for (int i = 0; i < std::max(a.width(), b.width()); ++i) sum += a.at(i) * b.at(i);
  return sum;
}

}  // namespace wg
