// list-ops, list-passes, list-diagnostics, list-generators, list-scenes: the tables.
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <string>

#include "cli/commands.hpp"
#include "compiler/diagnostic_codes.hpp"
#include "compiler/diagnostics_doc.hpp"
#include "compiler/pass_pipeline.hpp"
#include "host/scene/scene.hpp"
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
// "name: type = default, ..." for the text listing.
std::string signatureOf(const OpDef& op) {
  std::string signature;
  for (const auto& p : op.inputs)
    signature += (signature.empty() ? "" : ", ") + std::string(p.name) + ": " + std::string(portTypeName(p.type)) +
                 (p.defaultValue ? " = " + defaultText(p) : "");
  return signature;
}

nlohmann::ordered_json inputsJson(const OpDef& op) {
  nlohmann::ordered_json inputs = nlohmann::ordered_json::array();
  for (const auto& p : op.inputs) {
    nlohmann::ordered_json port = {{"name", p.name}, {"type", portTypeName(p.type)}, {"default", defaultText(p)}};
    if (std::isfinite(p.min) && std::isfinite(p.max) && p.min > -1e29f && p.max < 1e29f) {
      port["min"] = p.min;
      port["max"] = p.max;
    }
    inputs.push_back(std::move(port));
  }
  return inputs;
}

int listOps(bool json) {
  nlohmann::ordered_json all = nlohmann::ordered_json::array();
  for (const OpDef* op : allOps()) {
    std::string outputs;
    for (const auto& o : op->outputs) outputs += (outputs.empty() ? "" : ", ") + std::string(o.name);
    all.push_back({{"name", op->name}, {"category", op->category}, {"summary", op->summary},
                   {"inputs", inputsJson(*op)}, {"outputs", outputs}});
    if (!json)
      std::printf("%-16s %-10s (%s) -> %s\n%18s%s\n", std::string(op->name).c_str(), std::string(op->category).c_str(),
                  signatureOf(*op).c_str(), outputs.c_str(), "", std::string(op->summary).c_str());
  }
  if (json) std::printf("%s\n", all.dump(2).c_str());
  return kExitOk;
}

int listPasses() {
  int index = 1;
  for (const auto& pass : passPipeline())
    std::printf("%d. %-15s %s\n", index++, std::string(pass.name).c_str(), std::string(pass.summary).c_str());
  return kExitOk;
}

int listDiagnostics(bool markdown) {
  if (markdown) {
    std::fputs(diagnosticsMarkdown().c_str(), stdout);
    return kExitOk;
  }
  for (const auto& d : allDiagnostics())
    std::printf("%s  %-24s %s\n", std::string(d.id).c_str(), std::string(d.name).c_str(),
                std::string(d.messageTemplate).c_str());
  return kExitOk;
}

// The bundled scenes, one "NAME<TAB>summary" line each: the scripts that render every
// scene read their names from here.
int listScenes() {
  for (auto name : scene::sceneNames())
    std::printf("%s\t%s\n", std::string(name).c_str(), std::string(scene::sceneSummary(name)).c_str());
  return kExitOk;
}

int listGenerators() {
  for (const auto& g : textureGenerators()) {
    std::printf("%s: %s\n", std::string(g.name).c_str(), std::string(g.summary).c_str());
    for (const auto& o : g.options)
      std::printf("    %-10s [%g, %g]  %s\n", std::string(o.name).c_str(), o.min, o.max, std::string(o.doc).c_str());
  }
  return kExitOk;
}

}  // namespace

// Only the argument after the command is read (--json, --markdown); the rest is ignored.
int runListCommand(int argc, char** argv) {
  const std::string command = argv[1];
  const std::string option = argc > 2 ? argv[2] : "";
  if (command == "list-ops") return listOps(option == "--json");
  if (command == "list-passes") return listPasses();
  if (command == "list-diagnostics") return listDiagnostics(option == "--markdown");
  if (command == "list-generators") return listGenerators();
  if (command == "list-scenes") return listScenes();
  std::fprintf(stderr, "weathergen: error WG9001: unknown command\n  hint: run 'weathergen --help' for usage\n");
  return kExitUsage;
}

}  // namespace wg
