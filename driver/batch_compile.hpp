// Compiles many graphs across threads. Results come back in input order, so the
// output is byte-identical whatever the job count.
#pragma once
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "driver/material_compiler.hpp"

namespace wg {

// One compile of a batch: a graph file and the variant (static switch values) to build.
struct CompileJob {
  std::string graph;
  SwitchValues switches;
  std::optional<std::string> weatherPreset = std::nullopt;  // replaces the batch options' preset
  std::optional<std::string> quality = std::nullopt;        // the tier, replacing the batch options'
};

// onDone(index, completedCount) is called after each graph, from the worker that did
// it, one call at a time.
std::vector<CompileResult> compileBatch(const std::vector<CompileJob>& batch, const CompileOptions& options, int jobs,
                                        const std::function<void(std::size_t, std::size_t)>& onDone = {});
// Every graph with its default variant.
std::vector<CompileResult> compileBatch(const std::vector<std::string>& graphs, const CompileOptions& options, int jobs,
                                        const std::function<void(std::size_t, std::size_t)>& onDone = {});

}  // namespace wg
