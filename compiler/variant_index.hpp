// NAME.variants.json, written with --variants: which file set each variant uses.
// Variants whose shaders are identical share one set, named by its content hash, so
// the index is the only place that knows the variant names.
#pragma once
#include <string>
#include <vector>

#include "compiler/material_graph.hpp"
#include "compiler/static_switches.hpp"

namespace wg {

struct VariantEntry {
  SwitchValues switches;
  std::string contentHash;
  std::string fileStem;  // NAME.HASH: the reflection is fileStem + ".reflect.json"
};

std::string buildVariantIndexJson(const std::string& material, const std::vector<SwitchDecl>& switches,
                                  const std::vector<VariantEntry>& variants);

}  // namespace wg
