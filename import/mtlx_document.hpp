// One MaterialX document (1.38-1.39 XML), read with pugixml and checked before anything
// uses it: the XML itself (no DOCTYPE, so no entities to expand), the size of the file
// and of every attribute, the element count, and every xi:include, which must stay
// inside the search roots and never include itself. Each element keeps the file it came
// from, so a diagnostic names that file with a line and column and the element path
// (/materialx/nodegraph[NG]/image[img]/input[file]) as its pointer.
#pragma once
#include <pugixml.hpp>

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "compiler/diagnostic.hpp"

namespace wg::mtlx {

// One XML file read: its bytes (kept for line and column) and its tree.
struct SourceFile {
  std::string path;  // as the user named it, or as an include resolved it
  std::string text;
  pugi::xml_document xml;
  std::vector<std::size_t> lineStarts;  // byte offset of each line
};

class Document {
 public:
  // The document's own folder first, then each --search-path folder: every file the
  // document reads (includes, images) must resolve inside one of them.
  std::vector<std::filesystem::path> roots;
  std::vector<std::unique_ptr<SourceFile>> files;  // [0]: the document named on the command line
  // The top-level elements of the document and of every file it includes, in document
  // order with each include in its place; an element whose name came earlier is left out.
  std::vector<pugi::xml_node> elements;

  SourceLocation locate(pugi::xml_node node) const;
  // The top-level element named `name`, or an empty node.
  pugi::xml_node topLevel(std::string_view name) const;
  // Appends `element` to `elements` unless its name came earlier; false when it did.
  bool addTopLevel(pugi::xml_node element);
  // The first <input> (or <output>, or other element: a node) of `parent` named `name`.
  pugi::xml_node input(pugi::xml_node parent, std::string_view name) const { return childIn(inputs_, parent, name); }
  pugi::xml_node output(pugi::xml_node parent, std::string_view name) const { return childIn(outputs_, parent, name); }
  pugi::xml_node childNode(pugi::xml_node parent, std::string_view name) const { return childIn(nodes_, parent, name); }
  // Indexes the children of every element of `file` for the three look-ups above.
  void indexChildren(const SourceFile& file);
  // `relative` (a path as a document writes it) resolved inside the roots: the first root
  // holding it; "" when none does or it would leave every root. `notRegular` (when given)
  // is set when a root holds it, but as a folder, FIFO or device rather than a file.
  std::filesystem::path find(const std::string& relative, bool* notRegular = nullptr) const;
  // The document and every file it includes, for the check that no output replaces them.
  std::vector<std::filesystem::path> inputFiles() const;

 private:
  // Elements by name: a document of 200 000 elements is looked up once per reference,
  // and a scan per look-up would take minutes.
  using ChildIndex = std::unordered_map<std::string, pugi::xml_node>;  // key: parent address, then the name
  static pugi::xml_node childIn(const ChildIndex& index, pugi::xml_node parent, std::string_view name);
  std::unordered_map<std::string, pugi::xml_node> byName_;
  ChildIndex inputs_, outputs_, nodes_;
};

// "/materialx/nodegraph[NG]/input[file]": where an element is, as a JSON-pointer-like path.
std::string elementPath(pugi::xml_node node);

// Reads `path` and its includes; on any error returns nullopt with diagnostics (WG1002,
// WG1007, WG5201, WG5202, WG5205).
std::optional<Document> loadDocument(const std::string& path, const std::vector<std::string>& searchPath,
                                     DiagnosticList& diagnostics);

}  // namespace wg::mtlx
