#include "backends/shader_syntax.hpp"

namespace wg {

std::string ShaderSyntax::constant(const Value& value) const {
  if (value.type == ValueType::Bool) return value.asBool() ? "true" : "false";
  if (value.width() == 1) return formatFloat(value.v[0]);
  bool uniform = true;
  for (int i = 1; i < value.width(); ++i) uniform = uniform && value.v[i] == value.v[0];
  if (uniform) return splat(value.type, formatFloat(value.v[0]));
  std::string out(typeName(value.type));
  out += '(';
  for (int i = 0; i < value.width(); ++i) out += (i ? ", " : "") + formatFloat(value.v[i]);
  return out + ')';
}

std::string_view ShaderSyntax::alphaStatement(const StageSource& source) {
  return source.alphaBlended ? "  float wg_alpha = frame_debugView == 0u ? wg_opacity : 1.0;\n" : "  float wg_alpha = 1.0;\n";
}

std::string ShaderSyntax::parameterRead(const BlockMember& member, ValueType type) const {
  if (type == ValueType::Bool) return "(" + member.identifier + " != 0u)";
  return member.identifier;
}

const ShaderSyntax& syntaxFor(ShaderLanguage language) {
  return language == ShaderLanguage::Glsl ? glslSyntax() : hlslSyntax();
}

}  // namespace wg
