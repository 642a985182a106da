#include "driver/batch_compile.hpp"

#include <atomic>
#include <mutex>
#include <thread>

#include "driver/compile_cache.hpp"

namespace wg {

std::vector<CompileResult> compileBatch(const std::vector<CompileJob>& batch, const CompileOptions& options, int jobs,
                                        const std::function<void(std::size_t, std::size_t)>& onDone) {
  std::vector<CompileResult> results(batch.size());
  SpirvModuleCache modules;
  std::mutex reportLock;
  std::size_t completed = 0;
  auto compileOne = [&](std::size_t i) {
    CompileOptions variant = options;
    if (!variant.modules) variant.modules = &modules;
    variant.switches = batch[i].switches;
    if (batch[i].weatherPreset) variant.weatherPreset = batch[i].weatherPreset;
    if (batch[i].quality) variant.quality.requested = batch[i].quality;
    results[i] = variant.cache ? variant.cache->compileFile(batch[i].graph, variant)
                               : compileMaterialFile(batch[i].graph, variant);
    std::lock_guard<std::mutex> lock(reportLock);
    ++completed;
    if (onDone) onDone(i, completed);
  };
  if (batch.empty()) return results;
  // The first compile runs alone: glslang sets up process-wide tables on first use
  // (Filament's matc does the same).
  compileOne(0);
  std::atomic<std::size_t> next{1};
  auto worker = [&] {
    for (std::size_t i = next++; i < batch.size(); i = next++) compileOne(i);
  };
  std::size_t threads = std::min<std::size_t>(static_cast<std::size_t>(std::max(jobs, 1)), batch.size() - 1);
  std::vector<std::thread> pool;
  for (std::size_t t = 1; t < threads; ++t) pool.emplace_back(worker);
  worker();
  for (auto& t : pool) t.join();
  return results;
}

std::vector<CompileResult> compileBatch(const std::vector<std::string>& graphs, const CompileOptions& options, int jobs,
                                        const std::function<void(std::size_t, std::size_t)>& onDone) {
  std::vector<CompileJob> batch;
  for (const auto& g : graphs) batch.push_back({g, options.switches});
  return compileBatch(batch, options, jobs, onDone);
}

}  // namespace wg
