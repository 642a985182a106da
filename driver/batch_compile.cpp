#include "driver/batch_compile.hpp"

#include <algorithm>
#include <mutex>

#include "driver/compile_cache.hpp"
#include "driver/concurrent_indices.hpp"

namespace wg {

namespace {

// One graph's compile. An exception escaping it (a weathergen bug, or memory running
// out) is that graph's WG9900, naming it, and the rest of the batch still compiles.
CompileResult compileGuarded(const std::string& graph, const CompileOptions& options) {
  try {
    return options.cache ? options.cache->compileFile(graph, options) : compileMaterialFile(graph, options);
  } catch (const std::exception& e) {
    CompileResult failed;
    failed.diagnostics.report(DiagCode::InternalException, {graph, "", 0, 0}, {e.what()});
    return failed;
  }
}

}  // namespace

std::vector<CompileResult> compileBatch(const std::vector<CompileJob>& batch, const CompileOptions& options, int jobs,
                                        const std::function<void(std::size_t, std::size_t)>& onDone) {
  std::vector<CompileResult> results(batch.size());
  SpirvModuleCache modules;
  std::mutex reportLock;
  std::size_t completed = 0;
  auto compileOne = [&](std::size_t i, const CompileOptions& shared) {
    CompileOptions variant = shared;
    if (!variant.modules) variant.modules = &modules;
    variant.switches = batch[i].switches;
    if (batch[i].weatherPreset) variant.weatherPreset = batch[i].weatherPreset;
    if (batch[i].quality) variant.quality.requested = batch[i].quality;
    results[i] = compileGuarded(batch[i].graph, variant);
    std::lock_guard<std::mutex> lock(reportLock);
    ++completed;
    if (onDone) onDone(i, completed);
  };
  if (batch.empty()) return results;
  // The first compile runs alone, its stages across the threads: glslang sets up
  // process-wide tables on first use (Filament's matc does the same). The rest share
  // the threads graph by graph, and a batch smaller than the threads gives the spare
  // ones to each graph's stages.
  const std::size_t threads = static_cast<std::size_t>(std::max(jobs, 1));
  const std::size_t remaining = batch.size() - 1;
  CompileOptions first = options, rest = options;
  first.stageThreads = static_cast<int>(threads);
  rest.stageThreads = static_cast<int>(std::max<std::size_t>(1, threads / std::max<std::size_t>(remaining, 1)));
  compileOne(0, first);
  forEachIndexConcurrently(remaining, jobs, [&](std::size_t i) { compileOne(i + 1, rest); });
  return results;
}

std::vector<CompileResult> compileBatch(const std::vector<std::string>& graphs, const CompileOptions& options, int jobs,
                                        const std::function<void(std::size_t, std::size_t)>& onDone) {
  std::vector<CompileJob> batch;
  for (const auto& g : graphs) batch.push_back({g, options.switches});
  return compileBatch(batch, options, jobs, onDone);
}

}  // namespace wg
