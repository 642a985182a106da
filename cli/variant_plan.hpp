// Turns the graphs of a `weathergen compile` and its --variants selection into the
// batch of compiles: one job per graph and variant, graphs in command-line order and
// each graph's variants in enumerateVariants' stable order.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "driver/batch_compile.hpp"
#include "compiler/quality_tiers.hpp"
#include "compiler/static_switches.hpp"

namespace wg {

struct VariantPlan {
  std::vector<CompileJob> jobs;
  std::vector<std::size_t> graphOf;                 // job -> index into the graph list
  std::vector<SwitchValues> variantOf;              // job -> its variant, the tier as "quality"
  std::vector<std::vector<SwitchDecl>> switchesOf;  // graph -> its switches and the tier
};

// Without a selection, each graph's default variant. With one, the quality tier is a
// switch of every graph (variantAxesOf): a job gets it as its tier, and as a switch only
// where the graph declares "quality" itself. Returns "" or a usage error. A graph that
// does not load gets its default job, whose compile reports the errors.
std::string planVariants(const std::vector<std::string>& graphs, const std::optional<VariantSelection>& selection,
                         const QualityChoice& quality, VariantPlan& plan);

}  // namespace wg
