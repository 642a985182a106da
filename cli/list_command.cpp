// list-ops, list-passes, list-diagnostics, list-generators: the compiler's tables.
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <string>

#include "cli/commands.hpp"
#include "compiler/diagnostic_codes.hpp"
#include "compiler/diagnostics_doc.hpp"
#include "compiler/pass_pipeline.hpp"
#include "nodes/op_registry.hpp"
#include "nodes/texture_generators.hpp"

namespace wg {

namespace {
std::string_view portTypeName(PortType t) {
  switch (t) {
    case PortType::Float: return "float";
    case PortType::Vec2: return "vec2";
    case PortType::Vec3: return "vec3";
    case PortType::Vec4: return "vec4";
    case PortType::Bool: return "bool";
    case PortType::Generic: return "T";
    case PortType::TextureName: return "texture";
    case PortType::Text: return "text";
  }
  return "?";
}

std::string defaultText(const PortSpec& p) {
  if (!p.defaultValue) return "required";
  const Value& v = *p.defaultValue;
  if (v.width() == 1) return formatFloat(v.v[0]);
  std::string out = "[";
  for (int i = 0; i < v.width(); ++i) out += (i ? ", " : "") + formatFloat(v.v[i]);
  return out + "]";
}
}  // namespace

int runListCommand(int argc, char** argv) {
  std::string command = argv[1];
  bool json = argc > 2 && std::string(argv[2]) == "--json";
  if (command == "list-ops") {
    nlohmann::ordered_json all = nlohmann::ordered_json::array();
    for (const OpDef* op : allOps()) {
      nlohmann::ordered_json inputs = nlohmann::ordered_json::array();
      std::string signature;
      for (const auto& p : op->inputs) {
        nlohmann::ordered_json port = {{"name", p.name}, {"type", portTypeName(p.type)}, {"default", defaultText(p)}};
        if (std::isfinite(p.min) && std::isfinite(p.max) && p.min > -1e29f && p.max < 1e29f) {
          port["min"] = p.min;
          port["max"] = p.max;
        }
        inputs.push_back(std::move(port));
        signature += (signature.empty() ? "" : ", ") + std::string(p.name) + ": " + std::string(portTypeName(p.type)) +
                     (p.defaultValue ? " = " + defaultText(p) : "");
      }
      std::string outputs;
      for (const auto& o : op->outputs) outputs += (outputs.empty() ? "" : ", ") + std::string(o.name);
      all.push_back({{"name", op->name}, {"category", op->category}, {"summary", op->summary},
                     {"inputs", inputs}, {"outputs", outputs}});
      if (!json)
        std::printf("%-16s %-10s (%s) -> %s\n%18s%s\n", std::string(op->name).c_str(), std::string(op->category).c_str(),
                    signature.c_str(), outputs.c_str(), "", std::string(op->summary).c_str());
    }
    if (json) std::printf("%s\n", all.dump(2).c_str());
    return kExitOk;
  }
  if (command == "list-passes") {
    int index = 1;
    for (const auto& pass : passPipeline())
      std::printf("%d. %-15s %s\n", index++, std::string(pass.name).c_str(), std::string(pass.summary).c_str());
    return kExitOk;
  }
  if (command == "list-diagnostics") {
    if (argc > 2 && std::string(argv[2]) == "--markdown") {
      std::fputs(diagnosticsMarkdown().c_str(), stdout);
      return kExitOk;
    }
    for (const auto& d : allDiagnostics())
      std::printf("%s  %-24s %s\n", std::string(d.id).c_str(), std::string(d.name).c_str(),
                  std::string(d.messageTemplate).c_str());
    return kExitOk;
  }
  if (command == "list-generators") {
    for (const auto& g : textureGenerators()) {
      std::printf("%s: %s\n", std::string(g.name).c_str(), std::string(g.summary).c_str());
      for (const auto& o : g.options)
        std::printf("    %-10s [%g, %g]  %s\n", std::string(o.name).c_str(), o.min, o.max, std::string(o.doc).c_str());
    }
    return kExitOk;
  }
  std::fprintf(stderr, "weathergen: error WG9001: unknown command\n  hint: run 'weathergen --help' for usage\n");
  return kExitUsage;
}

}  // namespace wg
