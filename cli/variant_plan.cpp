#include "cli/variant_plan.hpp"

#include <set>

#include "compiler/literal.hpp"

namespace wg {

std::string planVariants(const std::vector<std::string>& graphs, const std::optional<VariantSelection>& selection,
                         VariantPlan& plan) {
  std::set<std::string> declaredAnywhere;
  for (std::size_t g = 0; g < graphs.size(); ++g) {
    plan.switchesOf.push_back(selection ? declaredSwitchesOf(graphs[g]) : std::vector<SwitchDecl>{});
    std::vector<SwitchValues> variants(1);
    if (selection) {
      for (const auto& s : plan.switchesOf.back()) declaredAnywhere.insert(s.name);
      std::string error;
      variants = enumerateVariants(plan.switchesOf.back(), *selection, error);
      if (!error.empty()) return quoteUserText(graphs[g]) + ": " + error;
    }
    for (auto& v : variants) {
      plan.jobs.push_back({graphs[g], std::move(v)});
      plan.graphOf.push_back(g);
    }
  }
  if (selection)
    for (const auto& [name, values] : selection->chosen)
      if (!declaredAnywhere.contains(name))
        return "--variants names switch '" + quoteUserText(name) + "', which no input graph declares";
  return "";
}

}  // namespace wg
