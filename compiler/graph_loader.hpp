// Stage 1: JSON document -> MaterialGraph, checking the structure the JSON Schema in
// graphs/schema/ describes (field names, kinds, required fields, texture sources).
#pragma once
#include <optional>
#include <string>

#include "compiler/diagnostic.hpp"
#include "compiler/json_document.hpp"
#include "compiler/material_graph.hpp"

namespace wg {

// Reads a graph file's bytes (WG1002 when unreadable, WG1007 when too large).
std::optional<std::string> readGraphFile(const std::string& path, DiagnosticList& diagnostics);

// Returns a graph when no error was reported; all errors found are reported. Graph
// libraries it includes are mounted on `document`, so their diagnostics name their file.
std::optional<MaterialGraph> loadMaterialGraph(JsonDocument& document, DiagnosticList& diagnostics);

}  // namespace wg
