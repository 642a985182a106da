// A parsed JSON file that remembers where every value came from, so that diagnostics
// can name file:line:col for any JSON pointer.
#pragma once
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "compiler/diagnostic.hpp"

namespace wg {

class JsonDocument {
 public:
  JsonDocument(std::string file, std::string text, nlohmann::json root);

  const std::string& file() const { return file_; }
  const std::string& text() const { return text_; }
  const nlohmann::json& root() const { return root_; }

  // Location of the value at `pointer`; falls back to the nearest located ancestor.
  SourceLocation locate(const std::string& pointer) const;
  // Location of the key naming the object member at `pointer` (for unknown fields).
  SourceLocation locateKey(const std::string& pointer) const;

  // Pointers under `prefix` locate in `document` from then on: a graph library's
  // elements keep pointers of the including graph ("/include/stone/nodes/2"), and
  // their diagnostics still name the library's file, line and column.
  void mount(std::string prefix, std::shared_ptr<const JsonDocument> document);

 private:
  std::string file_;
  std::string text_;
  nlohmann::json root_;
  void buildIndex() const;
  // The mounted document holding `pointer`, with the pointer inside it; or nullptr.
  const JsonDocument* mountedAt(const std::string& pointer, std::string& inner) const;
  std::vector<std::pair<std::string, std::shared_ptr<const JsonDocument>>> mounts_;
  using PositionIndex = std::unordered_map<std::string, std::pair<int, int>>;
  mutable std::unique_ptr<PositionIndex> values_;  // built on the first diagnostic
  mutable std::unique_ptr<PositionIndex> keys_;
};

struct JsonLimits {
  std::size_t maxBytes = 16u << 20;  // 16 MiB: far above any hand-written material
  int maxDepth = 64;                 // graphs nest 4 deep; guards the recursive consumers
};

// Parses `text`; on malformed JSON, duplicate keys or exceeded limits reports
// WG1001/WG1006/WG1007 and returns nullopt.
std::optional<JsonDocument> parseJsonDocument(std::string file, std::string text,
                                              DiagnosticList& diagnostics,
                                              const JsonLimits& limits = {});

// Where `pointer` is in the JSON file at `path`, read again (within the graph limits):
// for errors found after the document is gone, such as an image that fails to decode.
// Without a readable, valid file the location has the path and pointer only.
SourceLocation locateInJsonFile(const std::string& path, const std::string& pointer);

// Appends one RFC 6901 reference token to a pointer ("~" -> "~0", "/" -> "~1").
std::string appendPointer(const std::string& pointer, std::string_view token);
std::string appendPointer(const std::string& pointer, std::size_t index);

}  // namespace wg
