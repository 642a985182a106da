// The part of the glTF 2.0 JSON schema that weathergen reads, as one table: the kind
// of every property, the required ones, and which collection each index refers to.
// Checking it before tinygltf parses the file turns wrong types, missing properties and
// out-of-range indices into diagnostics with a JSON pointer, line and column, where
// tinygltf would skip the property silently or index out of bounds.
#pragma once
#include "compiler/diagnostic.hpp"
#include "compiler/json_document.hpp"

namespace wg::gltf {

// Reports WG5002 for wrong kinds and missing required properties, and WG5003 for
// indices that name no element (a node's mesh, a primitive's accessors, a texture's
// image...). Returns false when it reported an error.
bool checkSchema(const JsonDocument& document, DiagnosticList& diagnostics);

}  // namespace wg::gltf
