#include "cli/variant_plan.hpp"

#include <algorithm>
#include <set>

#include "compiler/literal.hpp"

namespace wg {

namespace {
// The variant's job: the tier moves from its switches to the job's own tier unless the
// graph declares the switch (then it stays, and follows the tier: bindQualitySwitch).
// Only the built-in axis has no place (pointer) in the graph's file. A value of a
// declared "quality" that names no tier ("draft") picks none, as through the engine API.
CompileJob jobFor(const std::string& graph, const SwitchValues& variant, const std::vector<SwitchDecl>& axes) {
  CompileJob job{graph, variant};
  auto tier = job.switches.find(std::string(kQualitySwitch));
  if (tier == job.switches.end()) return job;
  if (findQualityTier(tier->second)) job.quality = tier->second;
  if (std::none_of(axes.begin(), axes.end(), [](const SwitchDecl& s) { return s.name == kQualitySwitch && !s.pointer.empty(); }))
    job.switches.erase(tier);
  return job;
}
}  // namespace

std::string planVariants(const std::vector<std::string>& graphs, const std::optional<VariantSelection>& selection,
                         const QualityChoice& quality, VariantPlan& plan) {
  std::set<std::string> declaredAnywhere;
  for (std::size_t g = 0; g < graphs.size(); ++g) {
    plan.switchesOf.push_back(selection ? variantAxesOf(graphs[g], quality) : std::vector<SwitchDecl>{});
    std::vector<SwitchValues> variants(1);
    if (selection) {
      for (const auto& s : plan.switchesOf.back()) declaredAnywhere.insert(s.name);
      std::string error;
      variants = enumerateVariants(plan.switchesOf.back(), *selection, error);
      if (!error.empty()) return quoteUserText(graphs[g]) + ": " + error;
    }
    for (auto& v : variants) {
      plan.jobs.push_back(jobFor(graphs[g], v, plan.switchesOf.back()));
      plan.graphOf.push_back(g);
      plan.variantOf.push_back(std::move(v));
    }
  }
  if (selection)
    for (const auto& [name, values] : selection->chosen)
      if (!declaredAnywhere.contains(name))
        return "--variants names switch '" + quoteUserText(name) + "', which no input graph declares";
  return "";
}

}  // namespace wg
