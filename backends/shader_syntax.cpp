#include "backends/shader_syntax.hpp"

namespace wg {

void ShaderSyntax::appendConstant(std::string& out, const Value& value) const {
  if (value.type == ValueType::Bool) {
    out += value.asBool() ? "true" : "false";
    return;
  }
  if (value.width() == 1) {
    appendFloat(out, value.v[0]);
    return;
  }
  bool uniform = true;
  for (int i = 1; i < value.width(); ++i) uniform = uniform && value.v[i] == value.v[0];
  if (uniform) {
    out += splat(value.type, formatFloat(value.v[0]));
    return;
  }
  out += typeName(value.type);
  out += '(';
  for (int i = 0; i < value.width(); ++i) {
    if (i) out += ", ";
    appendFloat(out, value.v[i]);
  }
  out += ')';
}

void ShaderSyntax::appendParameterRead(std::string& out, const BlockMember& member, ValueType type) const {
  if (type != ValueType::Bool) {
    out += member.identifier;
    return;
  }
  out += '(';
  out += member.identifier;
  out += " != 0u)";
}

const ShaderSyntax& syntaxFor(ShaderLanguage language) {
  return language == ShaderLanguage::Glsl ? glslSyntax() : hlslSyntax();
}

}  // namespace wg
