#include "compiler/static_switches.hpp"

#include <algorithm>
#include <set>

#include "compiler/graph_loader.hpp"
#include "compiler/literal.hpp"
#include "compiler/quality_tiers.hpp"

namespace wg {

std::string variantName(const SwitchValues& values) {
  std::string name;
  for (const auto& [sw, value] : values) name += (name.empty() ? "" : ",") + sw + "=" + value;
  return name;
}

namespace {

class SwitchResolver {
 public:
  SwitchResolver(MaterialGraph& graph, const JsonDocument& doc, DiagnosticList& diags)
      : graph_(graph), doc_(doc), diags_(diags) {}

  bool run(const SwitchValues& requested) {
    chooseValues(requested);
    if (failed_) return false;
    collectSwitchNodes();
    if (failed_) return false;
    for (auto& n : graph_.nodes)
      for (auto& [port, source] : n.inputs) substitute(source);
    for (auto& [field, source] : graph_.outputs) substitute(source);
    std::erase_if(graph_.nodes, [](const NodeDecl& n) { return n.op == kSwitchOp; });
    resolveWeatherEffects();
    return !failed_;
  }

 private:
  void report(DiagCode code, const std::string& pointer, std::initializer_list<std::string_view> args) {
    failed_ = true;
    diags_.report(code, doc_.locate(pointer), args);
  }

  const SwitchDecl* findSwitch(const std::string& name) const {
    for (const auto& s : graph_.switches)
      if (s.name == name) return &s;
    return nullptr;
  }

  // The hint for an undeclared switch: the closest name, or the declared ones.
  std::string declaredSwitches(const std::string& missing) const {
    std::vector<std::string_view> candidates;
    for (const auto& s : graph_.switches) candidates.push_back(s.name);
    if (candidates.empty()) return "the graph declares no switches; add them under \"switches\"";
    return unknownNameHint(missing, candidates, "declared switches");
  }

  void chooseValues(const SwitchValues& requested) {
    for (const auto& s : graph_.switches) values_[s.name] = s.defaultValue;
    for (const auto& [name, value] : requested) {
      const SwitchDecl* s = findSwitch(name);
      if (!s) {
        report(DiagCode::UnknownSwitch, "/switches", {quoteUserText(name), declaredSwitches(name)});
        continue;
      }
      if (std::find(s->values.begin(), s->values.end(), value) == s->values.end()) {
        report(DiagCode::UnknownSwitchValue, s->pointer, {quoteUserText(name), "'" + quoteUserText(value) + "'", listNames(s->values)});
        continue;
      }
      values_[name] = value;
    }
  }

  void collectSwitchNodes() {
    std::map<std::string, const NodeDecl*> otherIds;
    for (const auto& n : graph_.nodes)
      if (n.op != kSwitchOp) otherIds.emplace(n.id, &n);
    for (const auto& n : graph_.nodes) {
      if (n.op != kSwitchOp || n.switchName.empty()) continue;
      if (auto other = otherIds.find(n.id); other != otherIds.end() || switchNodes_.contains(n.id)) {
        std::string at = other != otherIds.end() ? other->second->pointer : switchNodes_.at(n.id)->pointer;
        report(DiagCode::DuplicateId, appendPointer(n.pointer, "id"), {quoteUserText(n.id), "the node at " + at});
        continue;
      }
      const SwitchDecl* s = findSwitch(n.switchName);
      if (!s) {
        report(DiagCode::UnknownSwitch, appendPointer(n.pointer, "switch"), {quoteUserText(n.switchName), declaredSwitches(n.switchName)});
        continue;
      }
      checkCases(n, *s);
      switchNodes_.emplace(n.id, &n);
    }
  }

  // Every value of the switch has exactly one case, so every variant is complete.
  void checkCases(const NodeDecl& n, const SwitchDecl& s) {
    std::string shown = quoteUserText(s.name);
    for (const auto& [value, source] : n.cases)
      if (std::find(s.values.begin(), s.values.end(), value) == s.values.end())
        report(DiagCode::SwitchCasesMismatch, source.pointer,
               {quoteUserText(n.id), "has a case '" + quoteUserText(value) + "', which is not a value of switch '" + shown + "'", shown,
                listNames(s.values)});
    for (const auto& value : s.values) {
      bool covered = std::any_of(n.cases.begin(), n.cases.end(), [&](const auto& c) { return c.first == value; });
      if (!covered)
        report(DiagCode::SwitchCasesMismatch, appendPointer(n.pointer, "cases"),
               {quoteUserText(n.id), "has no case for value '" + value + "'", shown, listNames(s.values)});
    }
  }

  const InputSource& chosenCase(const NodeDecl& n) const {
    const std::string& value = values_.at(n.switchName);
    for (const auto& [v, source] : n.cases)
      if (v == value) return source;
    return n.cases.front().second;  // unreachable: checkCases covers every value
  }

  // A link to a switch node becomes the chosen case, following switches of switches.
  void substitute(InputSource& source) {
    std::set<std::string> visited;
    while (source.kind == InputSource::Kind::Link) {
      auto dot = source.text.rfind('.');
      if (dot == std::string::npos) return;  // the IR builder reports the malformed link
      auto it = switchNodes_.find(source.text.substr(0, dot));
      if (it == switchNodes_.end()) return;
      const NodeDecl& n = *it->second;
      if (std::string output = source.text.substr(dot + 1); output != "out") {
        report(DiagCode::DanglingLink, source.pointer,
               {quoteUserText(source.text), quoteUserText(output), kSwitchOp, "a switch has one output, 'out'"});
        return;
      }
      if (!visited.insert(n.id).second) {
        report(DiagCode::Cycle, source.pointer, {"switch node '" + quoteUserText(n.id) + "' chooses itself"});
        return;
      }
      source = chosenCase(n);
    }
  }

  // "effects": {"moss": {"switch": "moss"}} or {"switch": "quality", "when": ["high"]}.
  void resolveWeatherEffects() {
    if (!graph_.weather || !graph_.weather->is_object()) return;
    auto effects = graph_.weather->find("effects");
    if (effects == graph_.weather->end() || !effects->is_object()) return;
    std::string effectsPointer = appendPointer(graph_.weatherPointer, "effects");
    for (auto& item : effects->items()) {
      if (!item.value().is_object()) continue;  // booleans and wrong kinds: the weather resolver
      std::string at = appendPointer(effectsPointer, item.key());
      if (auto on = effectFromSwitch(item.value(), at, quoteUserText(item.key()))) item.value() = *on;
    }
  }

  std::optional<bool> effectFromSwitch(const nlohmann::json& setting, const std::string& at, const std::string& effect) {
    for (const auto& [key, value] : setting.items())
      if (key != "switch" && key != "when") {
        report(DiagCode::UnknownField, appendPointer(at, key), {quoteUserText(key), "a switched effect takes 'switch' and 'when'"});
        return std::nullopt;
      }
    auto name = setting.find("switch");
    if (name == setting.end() || !name->is_string()) {
      report(DiagCode::WeatherEffectForm, at, {effect});
      return std::nullopt;
    }
    const SwitchDecl* s = findSwitch(name->get<std::string>());
    if (!s) {
      report(DiagCode::UnknownSwitch, appendPointer(at, "switch"), {quoteUserText(name->get<std::string>()), declaredSwitches(name->get<std::string>())});
      return std::nullopt;
    }
    const std::string& value = values_.at(s->name);
    auto when = setting.find("when");
    if (when == setting.end()) {
      if (s->values != std::vector<std::string>{std::string(kSwitchOff), std::string(kSwitchOn)}) {
        report(DiagCode::WeatherEffectNeedsWhen, at, {effect, quoteUserText(s->name), s->values.back()});
        return std::nullopt;
      }
      return value == kSwitchOn;
    }
    std::string whenPointer = appendPointer(at, "when");
    if (!when->is_array()) {
      report(DiagCode::WrongJsonKind, whenPointer, {"'when'", "an array of switch values", describeJsonKind(*when)});
      return std::nullopt;
    }
    bool on = false;
    for (std::size_t i = 0; i < when->size(); ++i) {
      const auto& v = (*when)[i];
      if (!v.is_string() || std::find(s->values.begin(), s->values.end(), v.get<std::string>()) == s->values.end()) {
        report(DiagCode::UnknownSwitchValue, appendPointer(whenPointer, i),
               {quoteUserText(s->name), v.is_string() ? "'" + quoteUserText(v.get<std::string>()) + "'" : describeJsonKind(v),
                listNames(s->values)});
        return std::nullopt;
      }
      on = on || v.get<std::string>() == value;
    }
    return on;
  }

  MaterialGraph& graph_;
  const JsonDocument& doc_;
  DiagnosticList& diags_;
  SwitchValues values_;
  std::map<std::string, const NodeDecl*> switchNodes_;
  bool failed_ = false;
};

}  // namespace

bool resolveStaticSwitches(MaterialGraph& graph, const SwitchValues& requested, const JsonDocument& document,
                           DiagnosticList& diagnostics) {
  return SwitchResolver(graph, document, diagnostics).run(requested);
}

namespace {
// The graph, or nullopt when it does not load (its compile reports why, once).
std::optional<MaterialGraph> loadQuietly(const std::string& path) {
  DiagnosticList ignored;
  auto text = readGraphFile(path, ignored);
  auto document = text ? parseJsonDocument(path, std::move(*text), ignored) : std::nullopt;
  return document ? loadMaterialGraph(*document, ignored) : std::nullopt;
}
}  // namespace

std::vector<SwitchDecl> declaredSwitchesOf(const std::string& path) {
  auto graph = loadQuietly(path);
  return graph ? graph->switches : std::vector<SwitchDecl>{};
}

std::vector<SwitchDecl> variantAxesOf(const std::string& path, const QualityChoice& quality) {
  auto graph = loadQuietly(path);
  if (!graph) return withQualityAxis({}, quality.fallback);
  return withQualityAxis(graph->switches, chosenTierName(quality, graph->weather));
}

std::optional<VariantSelection> parseVariantSelection(std::string_view text, std::string& error) {
  VariantSelection selection;
  if (text == "all") {
    selection.all = true;
    return selection;
  }
  std::size_t start = 0;
  while (start <= text.size()) {
    std::size_t comma = std::min(text.find(',', start), text.size());
    std::string_view item = text.substr(start, comma - start);
    std::size_t eq = item.find('=');
    std::string name(item.substr(0, eq));
    if (name.empty()) {
      error = "--variants takes 'all' or SWITCH[=VALUE|VALUE...],... (an item is empty)";
      return std::nullopt;
    }
    auto& values = selection.chosen[name];
    if (eq != std::string_view::npos) {
      std::string_view rest = item.substr(eq + 1);
      std::size_t vs = 0;
      while (vs <= rest.size()) {
        std::size_t bar = std::min(rest.find('|', vs), rest.size());
        std::string value(rest.substr(vs, bar - vs));
        if (value.empty()) {
          error = "--variants: switch '" + quoteUserText(name) + "' has an empty value";
          return std::nullopt;
        }
        if (std::find(values.begin(), values.end(), value) == values.end()) values.push_back(value);
        vs = bar + 1;
      }
    }
    start = comma + 1;
  }
  return selection;
}

std::vector<SwitchValues> enumerateVariants(const std::vector<SwitchDecl>& switches, const VariantSelection& selection,
                                            std::string& error) {
  // Each switch's values in this selection, switches in name order.
  std::vector<std::pair<std::string, std::vector<std::string>>> axes;
  std::size_t count = 1;
  for (const auto& s : switches) {
    std::vector<std::string> values;
    auto chosen = selection.chosen.find(s.name);
    if (selection.all || (chosen != selection.chosen.end() && chosen->second.empty())) {
      values = s.values;
    } else if (chosen != selection.chosen.end()) {
      for (const auto& v : s.values)  // declared order, whatever order the list has
        if (std::find(chosen->second.begin(), chosen->second.end(), v) != chosen->second.end()) values.push_back(v);
      for (const auto& v : chosen->second)
        if (std::find(s.values.begin(), s.values.end(), v) == s.values.end()) {
          error = "switch '" + s.name + "' has no value '" + quoteUserText(v) + "' (values: " + listNames(s.values) + ")";
          return {};
        }
    } else {
      values = {s.defaultValue};
    }
    count *= values.size();
    if (count > kMaxVariants) {
      error = "the selection asks for more than " + std::to_string(kMaxVariants) + " variants of one graph";
      return {};
    }
    axes.emplace_back(s.name, std::move(values));
  }
  std::vector<SwitchValues> variants(1);
  for (const auto& [name, values] : axes) {
    std::vector<SwitchValues> next;
    for (const auto& partial : variants)
      for (const auto& v : values) {
        SwitchValues extended = partial;
        extended[name] = v;
        next.push_back(std::move(extended));
      }
    variants = std::move(next);
  }
  return variants;
}

}  // namespace wg
