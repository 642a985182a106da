// Builds IR from inline JSON for pass and compiler unit tests.
#pragma once
#include <gtest/gtest.h>

#include <string>

#include "compiler/graph_loader.hpp"
#include "compiler/ir_builder.hpp"

namespace wg::testing {

// The typed IR before any pass runs; fails the test on diagnostics.
inline IrGraph irBeforePasses(const std::string& json) {
  DiagnosticList diagnostics;
  auto document = parseJsonDocument("inline.json", json, diagnostics);
  std::optional<IrGraph> ir;
  if (document)
    if (auto graph = loadMaterialGraph(*document, diagnostics)) ir = buildIr(*graph, *document, diagnostics);
  for (const auto& d : diagnostics.items()) ADD_FAILURE() << formatDiagnosticText(d);
  return ir ? std::move(*ir) : IrGraph{};
}

// Wraps nodes and outputs in a minimal graph document.
inline std::string graphJson(const std::string& nodes, const std::string& output,
                             const std::string& extra = "") {
  return R"({"name": "t", )" + extra + R"("nodes": [)" + nodes + R"(], "output": {)" + output + "}}";
}

}  // namespace wg::testing
