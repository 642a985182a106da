// weathergen compile --dump-ir-after=PASS: a debugging aid that runs the front half of
// each compile (load, IR, passes) and prints the IR after one pass, or after every
// pass with "all", on stdout. It writes no files and generates no shaders.
#pragma once
#include <string>
#include <vector>

#include "driver/batch_compile.hpp"

namespace wg {

inline constexpr const char* kDumpIrAfterEveryPass = "all";

// "" when `name` is a pass of `weathergen list-passes` or "all", else a usage message
// with a did-you-mean hint.
std::string checkDumpIrPassName(const std::string& name);

// Dumps each job in order; the IR is verified after every pass. Diagnostics go to
// stderr. Returns the exit code.
int dumpIrAfterPass(const std::vector<CompileJob>& jobs, const std::string& passName, CompileOptions options, bool json);

}  // namespace wg
