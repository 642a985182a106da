// Bazel's persistent worker protocol, JSON form: one process serves many actions, so
// the process start and glslang's built-in symbol tables (half of a one-material
// compile) are paid once per worker, not once per material (docs/scaling.md).
#pragma once
#include <functional>
#include <string>
#include <vector>

namespace wg {

// Runs `command` with each request's arguments, as `weathergen compile ARGS` would, and
// answers with its exit code and everything it printed. Reads WorkRequests from stdin
// until it ends; writes only WorkResponses to stdout. Returns the process exit code.
using WorkerCommand = std::function<int(const std::vector<std::string>& arguments)>;
int runPersistentWorker(const WorkerCommand& command);

}  // namespace wg
