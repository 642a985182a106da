#include "nodes/op_registry.hpp"

#include <algorithm>
#include <stdexcept>
#include <string_view>
#include <unordered_map>

#include "nodes/core_library.hpp"
#include "nodes/op_template_check.hpp"
#include "nodes/pbr_shading.hpp"

namespace wg {

const PortSpec* OpDef::findInput(std::string_view port) const {
  for (const auto& p : inputs)
    if (p.name == port) return &p;
  return nullptr;
}

int OpDef::findOutput(std::string_view output) const {
  for (std::size_t i = 0; i < outputs.size(); ++i)
    if (outputs[i].name == output) return static_cast<int>(i);
  return -1;
}

namespace {
struct Registry {
  std::vector<OpDef> ops;
  std::vector<const OpDef*> sorted;
  // findOp's index: the front end and the passes look ops up by name for every node.
  std::unordered_map<std::string_view, const OpDef*> byName;
  std::vector<const ShaderLibrary*> libraries;

  Registry() {
    appendMathOps(ops);
    appendVectorOps(ops);
    appendGeometryOps(ops);
    appendTextureOps(ops);
    appendProceduralOps(ops);
    appendNormalMapOps(ops);
    appendWeatherOps(ops);
    appendSnowOps(ops);
    for (const auto& op : ops) {
      // A bad template is a bug in weathergen: refuse to start rather than emit it.
      if (auto error = templateError(op)) throw std::logic_error("op '" + std::string(op.name) + "': " + *error);
      sorted.push_back(&op);
      byName.emplace(op.name, &op);
    }
    std::sort(sorted.begin(), sorted.end(),
              [](const OpDef* a, const OpDef* b) { return a->name < b->name; });
    addLibrary(kCoreLibrary);
    addLibrary(kPbrShadingLibrary);
    for (const OpDef* op : sorted)
      for (const ShaderLibrary* library : op->libraries) addLibrary(*library);
  }

  void addLibrary(const ShaderLibrary& library) {
    if (std::find(libraries.begin(), libraries.end(), &library) != libraries.end()) return;
    libraries.push_back(&library);
    for (const ShaderLibrary* dependency : library.dependencies) addLibrary(*dependency);
  }
};

const Registry& registry() {
  static const Registry instance;  // immutable after first use; thread-safe init
  return instance;
}
}  // namespace

const OpDef* findOp(std::string_view name) {
  const auto& byName = registry().byName;
  auto it = byName.find(name);
  return it == byName.end() ? nullptr : it->second;
}

std::span<const OpDef* const> allOps() { return registry().sorted; }

std::span<const ShaderLibrary* const> allShaderLibraries() { return registry().libraries; }

std::vector<std::string_view> opNames() {
  std::vector<std::string_view> names;
  for (const OpDef* op : allOps()) names.push_back(op->name);
  return names;
}

}  // namespace wg

namespace wg {

namespace {
int swizzleIndex(char c) {
  switch (c) {
    case 'x': case 'r': return 0;
    case 'y': case 'g': return 1;
    case 'z': case 'b': return 2;
    case 'w': case 'a': return 3;
    default: return -1;
  }
}
}  // namespace

int accessorWidth(std::string_view accessor, int width) {
  if (accessor.empty()) return width;
  if (accessor.size() < 2 || accessor.size() > 5 || accessor[0] != '.') return 0;
  // GLSL and HLSL both forbid mixing the xyzw and rgba sets in one swizzle.
  std::string_view channels = accessor.substr(1);
  bool position = channels.find_first_of("xyzw") != std::string_view::npos;
  bool colour = channels.find_first_of("rgba") != std::string_view::npos;
  if (position && colour) return 0;
  for (char c : channels) {
    int index = swizzleIndex(c);
    if (index < 0 || index >= width) return 0;
  }
  return static_cast<int>(channels.size());
}

Value applyAccessor(const Value& value, std::string_view accessor) {
  if (accessor.empty()) return value;
  int width = accessorWidth(accessor, value.width());
  Value out{floatVectorOfWidth(width), {}};
  for (int i = 0; i < width; ++i) out.v[i] = value.v[swizzleIndex(accessor[i + 1])];
  return out;
}

}  // namespace wg
