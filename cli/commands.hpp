// CLI subcommands. Each returns the process exit code.
#pragma once

namespace wg {

enum ExitCode : int { kExitOk = 0, kExitBadInput = 1, kExitUsage = 2, kExitInternal = 3 };

int runCompileCommand(int argc, char** argv);
int runListCommand(int argc, char** argv);
int runEvalCommand(int argc, char** argv);
int runRenderCommand(int argc, char** argv);
int runBenchRenderCommand(int argc, char** argv);
int runBenchSnowCommand(int argc, char** argv);
int runImportCommand(int argc, char** argv);
int runStatsCommand(int argc, char** argv);

}  // namespace wg
