// Op templates are checked when the registry is built: a placeholder that names no
// port and no symbol would otherwise reach the shader as nothing at all.
#pragma once
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "nodes/op_definition.hpp"

namespace wg {

// The "{@symbol}" names the stage writer provides (backends/stage_writer.cpp).
std::span<const std::string_view> templateSymbols();

// Why the op's templates are unusable: an empty template, an unclosed '{', or a
// "{key}" that is neither "T", an input port, nor a known "@symbol" ("@texture" and
// "@sampler" also need a texture input). nullopt: they are fine.
std::optional<std::string> templateError(const OpDef& op);

}  // namespace wg
