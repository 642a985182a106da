#include "cli/ir_dump.hpp"

#include <cstdio>

#include "cli/commands.hpp"
#include "cli/diagnostic_output.hpp"
#include "compiler/graph_loader.hpp"
#include "compiler/ir_text.hpp"
#include "compiler/literal.hpp"
#include "compiler/quality_tiers.hpp"

namespace wg {

std::string checkDumpIrPassName(const std::string& name) {
  if (name == kDumpIrAfterEveryPass || findPass(name)) return "";
  std::vector<std::string_view> names{kDumpIrAfterEveryPass};
  for (const Pass& pass : passPipeline()) names.push_back(pass.name);
  return "--dump-ir-after: unknown pass '" + quoteUserText(name) + "'; " +
         unknownNameHintOr(name, names, "run 'weathergen list-passes' to see them, or use 'all'");
}

namespace {

// "# rock.json [moss=off] after cse": which compile and which pass the IR below is.
std::string dumpHeader(const CompileJob& job, std::string_view pass) {
  SwitchValues values = job.switches;  // with the job's tier, as --variants names it
  if (job.quality) values[std::string(kQualitySwitch)] = *job.quality;
  std::string variant = values.empty() ? "" : " [" + quoteUserText(variantName(values)) + "]";
  return "# " + quoteUserText(job.graph) + variant + " after " + std::string(pass) + "\n";
}

}  // namespace

int dumpIrAfterPass(const std::vector<CompileJob>& jobs, const std::string& passName, CompileOptions options, bool json) {
  DiagnosticList diagnostics;
  options.passes.verifyBetweenPasses = true;  // a debugging session wants the first broken invariant
  const QualityChoice quality = options.quality;
  for (const CompileJob& job : jobs) {
    options.switches = job.switches;
    options.quality.requested = job.quality ? job.quality : quality.requested;
    options.passes.afterPass = [&](const Pass& pass, const IrGraph& graph) {
      if (passName != kDumpIrAfterEveryPass && pass.name != passName) return;
      std::fputs((dumpHeader(job, pass.name) + formatIrText(graph)).c_str(), stdout);
    };
    if (auto text = readGraphFile(job.graph, diagnostics))
      (void)buildOptimizedIr(job.graph, std::move(*text), diagnostics, options);
  }
  std::fflush(stdout);
  if (!diagnostics.empty()) printDiagnostics(diagnostics.items(), json);
  bool internal = false;
  for (const auto& d : diagnostics.items()) internal = internal || d.info().category == DiagCategory::Internal;
  if (internal) return kExitInternal;
  return diagnostics.hasErrors() ? kExitBadInput : kExitOk;
}

}  // namespace wg
