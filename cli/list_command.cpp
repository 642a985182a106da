// list-ops, list-passes, list-diagnostics, list-generators, list-scenes: the tables.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <string>

#include "cli/commands.hpp"
#include "cli/diagnostic_output.hpp"
#include "cli/option_table.hpp"
#include "compiler/literal.hpp"
#include "compiler/diagnostic.hpp"
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
std::string outputsText(const OpDef& op) {
  std::string outputs;
  for (const auto& o : op.outputs) outputs += (outputs.empty() ? "" : ", ") + std::string(o.name);
  return outputs;
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

nlohmann::ordered_json opsJson() {
  nlohmann::ordered_json all = nlohmann::ordered_json::array();
  for (const OpDef* op : allOps())
    all.push_back({{"name", op->name}, {"category", op->category}, {"summary", op->summary},
                   {"inputs", inputsJson(*op)}, {"outputs", outputsText(*op)}});
  return all;
}

void printOps() {
  for (const OpDef* op : allOps())
    std::printf("%-16s %-10s (%s) -> %s\n%18s%s\n", std::string(op->name).c_str(), std::string(op->category).c_str(),
                signatureOf(*op).c_str(), outputsText(*op).c_str(), "", std::string(op->summary).c_str());
}

nlohmann::ordered_json passesJson() {
  nlohmann::ordered_json all = nlohmann::ordered_json::array();
  for (const auto& pass : passPipeline()) all.push_back({{"name", pass.name}, {"summary", pass.summary}});
  return all;
}

void printPasses() {
  int index = 1;
  for (const auto& pass : passPipeline())
    std::printf("%d. %-15s %s\n", index++, std::string(pass.name).c_str(), std::string(pass.summary).c_str());
}

// A diagnostic's category decides the exit code (docs/diagnostics.md).
std::pair<std::string_view, int> categoryAndExitCode(DiagCategory c) {
  switch (c) {
    case DiagCategory::Input: return {"input", kExitBadInput};
    case DiagCategory::Usage: return {"usage", kExitUsage};
    case DiagCategory::Internal: return {"internal", kExitInternal};
  }
  return {"internal", kExitInternal};
}

nlohmann::ordered_json diagnosticsJson() {
  nlohmann::ordered_json all = nlohmann::ordered_json::array();
  for (const auto& d : allDiagnostics()) {
    nlohmann::ordered_json arguments = nlohmann::ordered_json::array();
    for (std::size_t at = 0; at < d.arguments.size();) {
      const std::size_t space = std::min(d.arguments.find(' ', at), d.arguments.size());
      if (space > at) arguments.push_back(d.arguments.substr(at, space - at));
      at = space + 1;
    }
    const auto [category, exitCode] = categoryAndExitCode(d.category);
    all.push_back({{"code", d.id}, {"name", d.name}, {"severity", severityName(d.severity)}, {"category", category},
                   {"exitCode", exitCode}, {"message", d.messageTemplate},
                   {"hint", d.hintTemplate}, {"arguments", std::move(arguments)}});
  }
  return all;
}

void printDiagnosticsTable() {
  for (const auto& d : allDiagnostics())
    std::printf("%s  %-24s %s\n", std::string(d.id).c_str(), std::string(d.name).c_str(),
                std::string(d.messageTemplate).c_str());
}

nlohmann::ordered_json generatorsJson() {
  nlohmann::ordered_json all = nlohmann::ordered_json::array();
  for (const auto& g : textureGenerators()) {
    nlohmann::ordered_json options = nlohmann::ordered_json::array();
    for (const auto& o : g.options) options.push_back({{"name", o.name}, {"min", o.min}, {"max", o.max}, {"doc", o.doc}});
    all.push_back({{"name", g.name}, {"summary", g.summary}, {"options", std::move(options)}});
  }
  return all;
}

void printGenerators() {
  for (const auto& g : textureGenerators()) {
    std::printf("%s: %s\n", std::string(g.name).c_str(), std::string(g.summary).c_str());
    for (const auto& o : g.options)
      std::printf("    %-10s [%g, %g]  %s\n", std::string(o.name).c_str(), o.min, o.max, std::string(o.doc).c_str());
  }
}

nlohmann::ordered_json scenesJson() {
  nlohmann::ordered_json all = nlohmann::ordered_json::array();
  for (auto name : scene::sceneNames()) all.push_back({{"name", name}, {"summary", scene::sceneSummary(name)}});
  return all;
}

// One "NAME<TAB>summary" line each: the scripts that render every scene read their
// names from here.
void printScenes() {
  for (auto name : scene::sceneNames())
    std::printf("%s\t%s\n", std::string(name).c_str(), std::string(scene::sceneSummary(name)).c_str());
}

void printDiagnosticsMarkdown() { std::fputs(diagnosticsMarkdown().c_str(), stdout); }

// The list commands: each prints a table as text, or as one JSON array with --json.
struct ListCommand {
  std::string_view name;
  std::string_view lists;
  void (*printText)();
  nlohmann::ordered_json (*json)();
  void (*printMarkdown)() = nullptr;  // --markdown, where the table is also a document
};

const ListCommand kListCommands[] = {
    {"list-ops", "every node op: its category, ports (type, default, range) and outputs", printOps, opsJson},
    {"list-passes", "the IR pass pipeline, in order", printPasses, passesJson},
    {"list-diagnostics", "every diagnostic: code, name, severity, exit code, message and hint",
     printDiagnosticsTable, diagnosticsJson, printDiagnosticsMarkdown},
    {"list-generators", "the built-in procedural textures and their options", printGenerators, generatorsJson},
    {"list-scenes", "the bundled validation scenes, one \"NAME<TAB>summary\" line each", printScenes, scenesJson},
};

}  // namespace

int runListCommand(int argc, char** argv) {
  const std::string_view name = argv[1];
  const ListCommand* command = nullptr;
  for (const ListCommand& c : kListCommands)
    if (c.name == name) command = &c;
  if (!command) return usageError("unknown command " + quoteUserText(name));
  bool json = false, markdown = false, help = false;
  OptionTable table{.options = {{"--json", "", "", "one JSON array on stdout instead of text", storeFlag(json)},
                                {"--help", "-h", "", "this help", storeFlag(help), true}}};
  if (command->printMarkdown)
    table.options.insert(table.options.begin() + 1,
                         {"--markdown", "", "", "the table as docs/diagnostics.md has it", storeFlag(markdown)});
  const OptionParseResult parsed = parseOptions(table, argc, argv, 2);
  if (parsed.status == OptionParse::Failed) return usageError(parsed.error);
  if (help) {
    std::printf("Usage: weathergen %s [options]\n\nPrints %s.\n\nOptions:\n%s", std::string(name).c_str(),
                std::string(command->lists).c_str(), formatOptionList(table).c_str());
    return kExitOk;
  }
  if (json && markdown) return usageError("--json and --markdown cannot be used together");
  if (json) std::printf("%s\n", command->json().dump(2).c_str());
  else if (markdown) command->printMarkdown();
  else command->printText();
  return kExitOk;
}

}  // namespace wg
