// Every static-switch variant of every bundled graph, in `--variants all` order.
#pragma once
#include <vector>

#include "bench/bench_common.hpp"
#include "driver/batch_compile.hpp"

namespace wg::bench {

inline std::vector<CompileJob> bundledVariants() {
  std::vector<CompileJob> jobs;
  VariantSelection all;
  all.all = true;
  for (const auto& g : bundledGraphs()) {
    std::string error;
    for (auto& v : enumerateVariants(declaredSwitchesOf(g.path), all, error)) jobs.push_back({g.path, std::move(v)});
  }
  return jobs;
}

}  // namespace wg::bench
