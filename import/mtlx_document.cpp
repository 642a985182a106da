#include "import/mtlx_document.hpp"

#include <algorithm>
#include <cstring>
#include <set>

#include "compiler/literal.hpp"
#include "import/gltf_resources.hpp"
#include "nodes/regular_file.hpp"

namespace wg::mtlx {

namespace {

namespace fs = std::filesystem;

// Bounds on what a small hostile document can make us read and hold. MaterialX files are
// kilobytes; the largest of MaterialX's own examples is under 20 KiB.
constexpr std::uintmax_t kMaxFileBytes = 16u << 20;
constexpr std::size_t kMaxFiles = 64, kMaxIncludeDepth = 16;
constexpr std::size_t kMaxElements = 200000, kMaxAttributeBytes = 64u << 10;

std::vector<std::size_t> lineStartsOf(const std::string& text) {
  std::vector<std::size_t> starts{0};
  for (std::size_t i = 0; i < text.size(); ++i)
    if (text[i] == '\n') starts.push_back(i + 1);
  return starts;
}

SourceLocation locationAt(const SourceFile& file, std::ptrdiff_t offset, std::string pointer) {
  SourceLocation at{file.path, std::move(pointer)};
  if (offset < 0) return at;
  auto line = std::upper_bound(file.lineStarts.begin(), file.lineStarts.end(), static_cast<std::size_t>(offset));
  at.line = static_cast<int>(line - file.lineStarts.begin());
  at.column = static_cast<int>(static_cast<std::size_t>(offset) - *(line - 1)) + 1;
  return at;
}

std::string escapedToken(std::string_view token) {
  std::string out;
  for (char c : token) {
    if (c == '~') out += "~0";
    else if (c == '/') out += "~1";
    else out += c;
  }
  return out;
}

// Walks every element once, without recursion, checking the counts and attribute sizes.
bool withinLimits(const SourceFile& file, std::size_t& elementCount, DiagnosticList& diags) {
  std::vector<pugi::xml_node> stack{file.xml.document_element()};
  while (!stack.empty()) {
    pugi::xml_node node = stack.back();
    stack.pop_back();
    if (++elementCount > kMaxElements) {
      diags.report(DiagCode::ResourceLimit, locationAt(file, node.offset_debug(), elementPath(node)),
                   {"the element count", "over " + std::to_string(kMaxElements), std::to_string(kMaxElements)});
      return false;
    }
    for (pugi::xml_attribute a : node.attributes())
      if (std::string_view(a.value()).size() > kMaxAttributeBytes) {
        diags.report(DiagCode::ResourceLimit, locationAt(file, node.offset_debug(), elementPath(node)),
                     {"attribute '" + quoteUserText(a.name()) + "'", std::to_string(std::string_view(a.value()).size()) + " bytes",
                      std::to_string(kMaxAttributeBytes) + " bytes"});
        return false;
      }
    for (pugi::xml_node child = node.last_child(); child; child = child.previous_sibling())
      if (child.type() == pugi::node_element) stack.push_back(child);
  }
  return true;
}

class Loader {
 public:
  Loader(Document& doc, DiagnosticList& diags) : doc_(doc), diags_(diags) {}

  bool load(const fs::path& path, const std::string& shownPath, SourceLocation includedAt) {
    if (doc_.files.size() == kMaxFiles) {
      diags_.report(DiagCode::ResourceLimit, includedAt, {"the number of included documents", "over " + std::to_string(kMaxFiles),
                                                          std::to_string(kMaxFiles)});
      return false;
    }
    auto file = std::make_unique<SourceFile>();
    file->path = shownPath;
    FileRead read = readRegularFile(path.string(), kMaxFileBytes, file->text);
    if (read.status == FileReadStatus::TooLarge) {
      diags_.report(DiagCode::ResourceLimit, {shownPath}, {"the document size", std::to_string(read.size) + " bytes", "16 MiB"});
      return false;
    }
    if (read.status != FileReadStatus::Ok) {
      diags_.report(DiagCode::FileUnreadable, {shownPath}, {shownPath, read.reason, "check the path"});
      return false;
    }
    file->lineStarts = lineStartsOf(file->text);
    SourceFile& f = *file;
    doc_.files.push_back(std::move(file));
    if (!parse(f) || !withinLimits(f, elementCount_, diags_)) return false;
    doc_.indexChildren(f);
    chain_.push_back(fs::weakly_canonical(path));
    loaded_.insert(chain_.back());
    bool ok = readTopLevel(f, path.parent_path());
    chain_.pop_back();
    return ok;
  }

 private:
  bool parse(SourceFile& f) {
    constexpr unsigned kOptions = pugi::parse_default | pugi::parse_doctype;
    pugi::xml_parse_result result = f.xml.load_buffer(f.text.data(), f.text.size(), kOptions, pugi::encoding_utf8);
    if (!result) {
      diags_.report(DiagCode::MtlxXml, locationAt(f, result.offset, ""),
                    {std::string("malformed XML: ") + result.description(), "fix the XML syntax at this position"});
      return false;
    }
    for (pugi::xml_node n : f.xml.children())
      if (n.type() == pugi::node_doctype) {
        // Entities are where "billion laughs" lives; MaterialX documents declare none.
        diags_.report(DiagCode::MtlxXml, locationAt(f, n.offset_debug(), ""),
                      {"it has a DOCTYPE; MaterialX documents have none, and its entities would not be expanded",
                       "remove the <!DOCTYPE ...> declaration"});
        return false;
      }
    pugi::xml_node root = f.xml.document_element();
    if (std::string_view(root.name()) != "materialx") {
      diags_.report(DiagCode::MtlxXml, locationAt(f, root.offset_debug(), elementPath(root)),
                    {"the root element is <" + quoteUserText(root.name()) + ">, not <materialx>", "give the file a MaterialX document"});
      return false;
    }
    std::string version = root.attribute("version").value();
    if (!version.starts_with("1.38") && !version.starts_with("1.39"))
      diags_.report(DiagCode::MtlxFeatureAdjusted, doc_.locate(root),
                    {"MaterialX version '" + quoteUserText(version) + "' is read as 1.39",
                     "the import reads MaterialX 1.38 and 1.39; upgrade older documents with MaterialX's own tools"});
    return true;
  }

  bool readTopLevel(const SourceFile& f, const fs::path& folder) {
    std::set<std::string> namesHere;
    for (pugi::xml_node e : f.xml.document_element().children()) {
      if (e.type() != pugi::node_element) continue;
      if (std::string_view(e.name()) == "xi:include") {
        if (!include(e, folder)) return false;
        continue;
      }
      std::string name = e.attribute("name").value();
      if (!namesHere.insert(name).second && !name.empty()) {
        diags_.report(DiagCode::MtlxBadReference, doc_.locate(e),
                      {"two top-level elements are named '" + quoteUserText(name) + "'", "give every element a unique name"});
        return false;
      }
      doc_.addTopLevel(e);
    }
    return true;
  }

  bool include(pugi::xml_node element, const fs::path& folder) {
    std::string href = element.attribute("href").value();
    SourceLocation at = doc_.locate(element);
    auto refuse = [&](const std::string& problem, const std::string& fix) {
      diags_.report(DiagCode::MtlxResource, at, {"xi:include '" + quoteUserText(href) + "'", problem, fix});
      return false;
    };
    if (href.empty()) return refuse("no href", "name the document to include in href");
    if (href.find("://") != std::string::npos || fs::path(href).is_absolute())
      return refuse("only relative paths inside the search path are read", "copy the document into a --search-path folder");
    bool outside = false, notRegular = false;
    fs::path resolved = confinedInRoots(folder, href, outside, notRegular);
    if (resolved.empty() && notRegular)
      return refuse("it is a folder, FIFO or device, not a file", "name a MaterialX document in href");
    if (resolved.empty() && outside)
      return refuse("it leaves the document's folder and every --search-path folder; it is not read",
                    "copy the document into a --search-path folder");
    if (resolved.empty())
      return refuse("not found in the document's folder or a --search-path folder", "add the folder that holds it with --search-path");
    if (std::find(chain_.begin(), chain_.end(), resolved) != chain_.end()) {
      std::string loop;
      for (const auto& p : chain_) loop += p.filename().string() + " -> ";
      return refuse("an include loop: " + quoteUserText(loop + resolved.filename().string(), 200), "remove the include that closes the loop");
    }
    if (chain_.size() == kMaxIncludeDepth) {
      diags_.report(DiagCode::ResourceLimit, at, {"the include depth", "over " + std::to_string(kMaxIncludeDepth), std::to_string(kMaxIncludeDepth)});
      return false;
    }
    if (loaded_.count(resolved)) return true;  // included once already
    return load(resolved, resolved.string(), at);
  }

  // The include resolved beside the including file, else in each root; it must exist
  // and stay inside a root. `outside`: a candidate exists, but outside every root;
  // `notRegular`: one exists inside a root, but is not a regular file.
  fs::path confinedInRoots(const fs::path& folder, const std::string& href, bool& outside, bool& notRegular) const {
    std::vector<fs::path> bases{folder};
    bases.insert(bases.end(), doc_.roots.begin(), doc_.roots.end());
    for (const auto& base : bases) {
      std::error_code ec;
      fs::path candidate = fs::weakly_canonical(base / href, ec);
      if (ec || !fs::exists(candidate, ec)) continue;
      if (!fs::is_regular_file(candidate, ec)) {
        notRegular = notRegular || insideARoot(candidate);
        continue;
      }
      if (insideARoot(candidate)) return candidate;
      outside = true;
    }
    return {};
  }

  bool insideARoot(const fs::path& candidate) const {
    std::error_code ec;
    for (const auto& root : doc_.roots)
      if (!gltf::confinedPath(root, fs::relative(candidate, root, ec).string()).empty()) return true;
    return false;
  }

  Document& doc_;
  DiagnosticList& diags_;
  std::vector<fs::path> chain_;
  std::set<fs::path> loaded_;
  std::size_t elementCount_ = 0;
};

}  // namespace

std::string elementPath(pugi::xml_node node) {
  std::vector<std::string> tokens;
  for (; node && node.type() == pugi::node_element; node = node.parent()) {
    std::string token = node.name();
    if (pugi::xml_attribute name = node.attribute("name")) token += "[" + std::string(name.value()) + "]";
    tokens.push_back(escapedToken(token));
  }
  std::string path;
  for (auto it = tokens.rbegin(); it != tokens.rend(); ++it) path += "/" + *it;
  return path;
}

SourceLocation Document::locate(pugi::xml_node node) const {
  for (const auto& file : files)
    if (node.root() == file->xml.root()) {
      std::ptrdiff_t offset = node.offset_debug();  // an element's is its name's; show its '<'
      return locationAt(*file, offset > 0 && node.type() == pugi::node_element ? offset - 1 : offset, elementPath(node));
    }
  return {files.empty() ? "" : files[0]->path, elementPath(node)};
}

pugi::xml_node Document::topLevel(std::string_view name) const {
  auto it = byName_.find(std::string(name));
  return it == byName_.end() ? pugi::xml_node() : it->second;
}

namespace {
std::string childKey(pugi::xml_node parent, std::string_view name) {
  std::string key(sizeof(void*), '\0');
  const void* address = parent.internal_object();
  std::memcpy(key.data(), &address, sizeof address);
  return key.append(name);
}
}  // namespace

pugi::xml_node Document::childIn(const ChildIndex& index, pugi::xml_node parent, std::string_view name) {
  auto it = index.find(childKey(parent, name));
  return it == index.end() ? pugi::xml_node() : it->second;
}

void Document::indexChildren(const SourceFile& file) {
  std::vector<pugi::xml_node> stack{file.xml.document_element()};
  while (!stack.empty()) {
    pugi::xml_node parent = stack.back();
    stack.pop_back();
    for (pugi::xml_node child : parent.children()) {
      if (child.type() != pugi::node_element) continue;
      std::string_view kind = child.name();
      ChildIndex& index = kind == "input" ? inputs_ : kind == "output" ? outputs_ : nodes_;
      index.emplace(childKey(parent, child.attribute("name").value()), child);  // the first of a name wins
      stack.push_back(child);
    }
  }
}

bool Document::addTopLevel(pugi::xml_node element) {
  std::string name = element.attribute("name").value();
  if (!name.empty() && !byName_.emplace(name, element).second) return false;
  elements.push_back(element);
  return true;
}

fs::path Document::find(const std::string& relative, bool* notRegular) const {
  if (relative.empty() || relative.find("://") != std::string::npos) return {};
  for (const auto& root : roots) {
    fs::path resolved = gltf::confinedPath(root, relative);
    std::error_code ec;
    if (resolved.empty()) continue;
    if (fs::is_regular_file(resolved, ec)) return resolved;
    if (notRegular && fs::exists(resolved, ec)) *notRegular = true;
  }
  return {};
}

std::vector<fs::path> Document::inputFiles() const {
  std::vector<fs::path> paths;
  for (const auto& f : files) paths.push_back(f->path);
  return paths;
}

std::optional<Document> loadDocument(const std::string& path, const std::vector<std::string>& searchPath,
                                     DiagnosticList& diagnostics) {
  Document doc;
  std::error_code ec;
  doc.roots.push_back(fs::weakly_canonical(fs::absolute(path, ec).parent_path(), ec));
  for (const auto& folder : searchPath) doc.roots.push_back(fs::weakly_canonical(fs::absolute(folder, ec), ec));
  Loader loader(doc, diagnostics);
  if (!loader.load(path, path, {path})) return std::nullopt;
  return doc;
}

}  // namespace wg::mtlx
