// Static switches (docs/graph-format.md, "Static switches"): compile-time choices such
// as weather effects on or off and quality levels. A variant is one value per switch.
// Resolving a variant rewrites the declared graph before typing, so each variant is
// typed and optimised as if it had been written without switches, and identical
// variants get identical content hashes.
#pragma once
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "compiler/diagnostic.hpp"
#include "compiler/json_document.hpp"
#include "compiler/material_graph.hpp"

namespace wg {

inline constexpr std::string_view kSwitchOp = "switch";
inline constexpr std::string_view kSwitchOff = "off";  // the values of a bool switch
inline constexpr std::string_view kSwitchOn = "on";
// One graph's permutations are compiled in one batch; this keeps a typo in a switch
// declaration from asking for millions of compiles.
inline constexpr std::size_t kMaxVariants = 1024;

using SwitchValues = std::map<std::string, std::string>;  // switch name -> value

// "quality=low,snow=on": every switch in name order; "" for a graph without switches.
std::string variantName(const SwitchValues& values);

// Chooses `requested` (switches it does not name keep their default): replaces every
// switch node by its chosen case and every weather effect written {"switch": ...} by a
// boolean. Reports WG2015/WG2016 (and WG2002/WG2004/WG2009 for switch nodes) and
// returns false on errors.
bool resolveStaticSwitches(MaterialGraph& graph, const SwitchValues& requested, const JsonDocument& document,
                           DiagnosticList& diagnostics);

// The switches a graph file declares: empty when it declares none or does not load
// (its compile reports why, once, with the rest).
std::vector<SwitchDecl> declaredSwitchesOf(const std::string& path);

struct QualityChoice;
// What --variants enumerates for a graph file: its switches and the quality tier as the
// switch "quality" (compiler/quality_tiers.hpp), defaulting to the tier it compiles at.
std::vector<SwitchDecl> variantAxesOf(const std::string& path, const QualityChoice& quality);

// The CLI's --variants: "all", or a comma-separated list of SWITCH (all its values) and
// SWITCH=V1|V2 (those values). Switches not named keep their default.
struct VariantSelection {
  bool all = false;
  std::map<std::string, std::vector<std::string>> chosen;  // empty list: every value
};
std::optional<VariantSelection> parseVariantSelection(std::string_view text, std::string& error);

// The variants of one graph that a selection asks for: switches in name order, values
// in declared order, so the list is stable. A named switch the graph does not declare
// is skipped (a batch mixes graphs); an unknown value or more than kMaxVariants
// permutations sets `error`.
std::vector<SwitchValues> enumerateVariants(const std::vector<SwitchDecl>& switches, const VariantSelection& selection,
                                            std::string& error);

}  // namespace wg
