// A material graph as declared in its JSON file, after structural checks and before
// typing. Every element keeps its JSON pointer for diagnostics.
#pragma once
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "compiler/alpha_mode.hpp"
#include "compiler/json_document.hpp"
#include "compiler/pbr_output.hpp"
#include "nodes/value.hpp"
#include "nodes/texture_sampling.hpp"

namespace wg {

// An input as written: a link "nodeId.output", or a literal.
struct InputSource {
  enum class Kind : std::uint8_t { Link, Literal, Text } kind = Kind::Literal;
  std::string text;        // link, texture name or swizzle channels
  nlohmann::json literal;  // number, bool or array
  std::string pointer;
};

struct ParameterDecl {
  std::string name;
  ValueType type = ValueType::Float;
  Value defaultValue;
  std::optional<float> min, max;
  std::string label;
  std::string pointer;
};

struct TextureDecl {
  std::string name;
  std::string file;          // as written; empty for procedural textures
  std::string resolvedPath;  // relative to the graph file
  std::string generator;     // procedural generator name
  std::uint32_t seed = 0;
  int size = 256;
  nlohmann::json options = nlohmann::json::object();
  SamplerState sampler;  // wrap per axis, min/mag filter, colour space
  std::string pointer;
};

// A static switch: a compile-time choice among named values. Each permutation of a
// graph's switches is one shader variant (docs/graph-format.md, "Static switches").
struct SwitchDecl {
  std::string name;
  std::vector<std::string> values;  // declared order; a bool switch is ["off", "on"]
  std::string defaultValue;
  std::string pointer;
};

struct NodeDecl {
  std::string id;
  std::string op;
  std::string param;  // for op "parameter"
  std::vector<std::pair<std::string, InputSource>> inputs;
  // Op "switch": the switch it follows and one source per switch value. It is resolved
  // before typing, so it never reaches the IR.
  std::string switchName;
  std::vector<std::pair<std::string, InputSource>> cases;
  std::string pointer;
};

struct MaterialGraph {
  std::string name;
  std::string sourceFile;
  std::vector<std::string> includedFiles;  // graph libraries, resolved paths, include order
  std::vector<ParameterDecl> parameters;  // sorted by name
  std::vector<TextureDecl> textures;      // sorted by name
  std::vector<SwitchDecl> switches;       // sorted by name
  std::vector<NodeDecl> nodes;            // file order
  std::map<PbrField, InputSource> outputs;
  std::optional<nlohmann::json> weather;
  std::string weatherPointer;
  float alphaCutoff = 0.5f;
  std::optional<AlphaMode> alphaMode;  // nullopt: mask when output.opacity is set, else opaque
  bool doubleSided = false;
};

}  // namespace wg
