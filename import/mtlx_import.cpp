#include "import/mtlx_import.hpp"

#include <filesystem>
#include <map>

#include "compiler/json_text.hpp"
#include "compiler/literal.hpp"
#include "import/gltf_resources.hpp"
#include "import/mtlx_graph_writer.hpp"
#include "nodes/regular_file.hpp"

namespace wg::mtlx {

namespace {

namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;

constexpr std::uintmax_t kMaxImageBytes = 512ull << 20, kMaxImagesTotalBytes = 1ull << 30;
constexpr std::size_t kMaxMaterials = 16384;

std::string asText(const Json& json) { return jsonText(json, 2) + "\n"; }

std::string imageExtension(std::string_view bytes) {
  if (bytes.starts_with("\x89PNG\r\n\x1a\n")) return ".png";
  if (bytes.starts_with("\xff\xd8\xff")) return ".jpg";
  return "";
}

// Finds, reads and names every image the graphs sample; each file is written once.
class ImageCollector {
 public:
  ImageCollector(const Document& doc, const std::string& stem, MissingImages missing, DiagnosticList& diags)
      : doc_(doc), stem_(stem), missing_(missing), diags_(diags) {}

  std::optional<std::string> fileFor(pugi::xml_node input, const std::string& path) {
    std::string written = input.attribute("value").value();
    SourceLocation at = doc_.locate(input);
    if (path.find("://") != std::string::npos || fs::path(path).is_absolute()) {
      diags_.report(DiagCode::MtlxResource, at, {"image '" + quoteUserText(path) + "'", "only relative paths inside the search path are read",
                                                 "write the path relative to a --search-path folder"});
      return std::nullopt;
    }
    bool notRegular = false;
    fs::path found = doc_.find(path, &notRegular);
    if (found.empty()) found = doc_.find(written, &notRegular);  // the name alone, for stand-ins beside the document
    if (found.empty() && notRegular) {  // "not found" would send the user looking for a file that is there
      diags_.report(DiagCode::MtlxResource, at, {"image '" + quoteUserText(path) + "'", "it is a folder, FIFO or device, not a file",
                                                 "point the input at a PNG or JPEG file"});
      return std::nullopt;
    }
    if (found.empty()) return missing(at, path);
    if (auto known = names_.find(found); known != names_.end()) return known->second;
    std::string bytes;
    FileRead read = readRegularFile(found.string(), kMaxImageBytes, bytes);
    std::string extension = imageExtension(bytes);
    std::string problem = read.status == FileReadStatus::TooLarge ? "larger than 512 MiB"
                          : read.status != FileReadStatus::Ok    ? read.reason
                          : extension.empty()                    ? "neither PNG nor JPEG"
                          : (totalBytes_ += bytes.size()) > kMaxImagesTotalBytes ? "the images together exceed 1 GiB"
                                                                                 : "";
    std::string fix = "convert it to PNG or JPEG";
    gltf::ImageHeader header;
    if (problem.empty())  // as compile will read it, so that the imported graph compiles
      if (auto bad = gltf::imageHeaderProblem(reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size(), extension == ".png", header))
        problem = bad->message, fix = bad->hint;
    if (!problem.empty()) {
      diags_.report(DiagCode::MtlxResource, at, {"image '" + quoteUserText(path) + "'", problem, fix});
      return std::nullopt;
    }
    std::string name = stem_ + "_image" + std::to_string(files_.size()) + extension;
    names_[found] = name;
    files_.push_back({name, std::move(bytes)});
    sources_.push_back(Json{{"file", name}, {"source", path}});
    return name;
  }

  std::vector<gltf::ImportedFile>& files() { return files_; }
  std::vector<fs::path> read() const {
    std::vector<fs::path> paths;
    for (const auto& [path, name] : names_) paths.push_back(path);
    return paths;
  }
  const Json& index() const { return sources_; }

 private:
  std::optional<std::string> missing(const SourceLocation& at, const std::string& path) {
    std::string searched;
    for (const auto& root : doc_.roots) searched += (searched.empty() ? "" : ", ") + quoteUserText(root.string(), 120);
    if (missing_ == MissingImages::Error) {
      diags_.report(DiagCode::MtlxResource, at, {"image '" + quoteUserText(path) + "'", "not found in " + searched +
                                                 " (paths leaving these folders are not followed)",
                                                 "add the folder that holds it with --search-path, or pass --missing-images placeholder"});
      return std::nullopt;
    }
    diags_.report(DiagCode::MtlxFeatureAdjusted, at, {"image '" + quoteUserText(path) + "' is not found in " + searched +
                                                      "; the placeholder image is used",
                                                      "put the image in a --search-path folder and import again"});
    std::string name = stem_ + "_placeholder.png";
    if (!placeholderWritten_) {
      files_.push_back({name, std::string(placeholderPng())});
      sources_.push_back(Json{{"file", name}, {"source", nullptr}});
      placeholderWritten_ = true;
    }
    return name;
  }

  const Document& doc_;
  std::string stem_;
  MissingImages missing_;
  DiagnosticList& diags_;
  std::map<fs::path, std::string> names_;
  std::vector<gltf::ImportedFile> files_;
  Json sources_ = Json::array();
  std::uintmax_t totalBytes_ = 0;
  bool placeholderWritten_ = false;
};

std::vector<pugi::xml_node> elementsNamed(const Document& doc, std::string_view category) {
  std::vector<pugi::xml_node> found;
  for (pugi::xml_node e : doc.elements)
    if (category == e.name()) found.push_back(e);
  return found;
}

// Looks are indexed, not applied: each assignment names its material's graph.
Json looksIndex(const Document& doc, const std::map<std::string, std::string>& graphOf, DiagnosticList& diags) {
  Json looks = Json::array();
  for (pugi::xml_node look : elementsNamed(doc, "look")) {
    Json assignments = Json::array();
    for (pugi::xml_node assign : look.children("materialassign")) {
      std::string material = assign.attribute("material").value();
      auto graph = graphOf.find(material);
      if (graph == graphOf.end() && std::string_view(doc.topLevel(material).name()) != "surfacematerial") {
        diags.report(DiagCode::MtlxBadReference, doc.locate(assign),
                     {"materialassign '" + quoteUserText(assign.attribute("name").value()) + "' names material '" +
                          quoteUserText(material) + "', which does not exist",
                      "name a surfacematerial of the document or of one it includes"});
        continue;
      }
      if (graph == graphOf.end()) continue;  // its material failed, and said why
      assignments.push_back(Json{{"name", assign.attribute("name").value()}, {"geom", assign.attribute("geom").value()},
                                 {"material", material}, {"graph", graph->second}});
    }
    looks.push_back(Json{{"name", look.attribute("name").value()}, {"assignments", assignments}});
  }
  return looks;
}

}  // namespace

std::string_view placeholderPng() {
  static constexpr char kBytes[] =
      "\x89\x50\x4e\x47\x0d\x0a\x1a\x0a\x00\x00\x00\x0d\x49\x48\x44\x52\x00\x00\x00\x01\x00\x00\x00\x01\x08\x02\x00\x00\x00"
      "\x90\x77\x53\xde\x00\x00\x00\x0c\x49\x44\x41\x54\x78\xda\x63\x68\x68\xf8\x0f\x00\x03\x83\x02\x00\x3e\x58\x28\x25\x00"
      "\x00\x00\x00\x49\x45\x4e\x44\xae\x42\x60\x82";
  return {kBytes, sizeof kBytes - 1};
}

std::optional<ImportedDocument> importDocument(const Document& document, const ImportSettings& settings,
                                               DiagnosticList& diagnostics) {
  std::size_t before = diagnostics.items().size();
  std::vector<pugi::xml_node> materials = elementsNamed(document, "surfacematerial");
  SourceLocation whole = document.locate(document.files[0]->xml.document_element());
  if (materials.empty()) {
    diagnostics.report(DiagCode::MtlxBadReference, whole, {"the document has no surfacematerial", "add a surfacematerial, or include a document that has one"});
    return std::nullopt;
  }
  if (materials.size() > kMaxMaterials) {
    diagnostics.report(DiagCode::ResourceLimit, whole, {"the material count", std::to_string(materials.size()), std::to_string(kMaxMaterials)});
    return std::nullopt;
  }
  std::string stem = gltf::modelFileStem(document.files[0]->path);
  std::vector<std::string> names;
  for (pugi::xml_node m : materials) names.push_back(m.attribute("name").value());
  std::vector<std::string> stems = gltf::materialStems(names, stem);
  ImageCollector images(document, stem, settings.missingImages, diagnostics);
  ImageFiles imageFiles = [&images](pugi::xml_node input, const std::string& path) { return images.fileFor(input, path); };
  ImportedDocument out;
  Json index;
  index["document"] = fs::path(document.files[0]->path).filename().string();
  index["generator"] = std::string("weathergen ") + WEATHERGEN_VERSION;
  index["materials"] = Json::array();
  std::map<std::string, std::string> graphOf;
  std::size_t nodesLeft = kMaxImportGraphNodes;
  for (std::size_t i = 0; i < materials.size(); ++i) {
    GraphNaming naming{stems[i], "MaterialX material '" + names[i] + "' of " + index["document"].get<std::string>(),
                       settings.presets.presetFor(names[i]), settings.snowDisplacement};
    auto graph = materialGraph(document, materials[i], naming, imageFiles, nodesLeft, diagnostics);
    if (!graph && nodesLeft == 0) return std::nullopt;  // every later material would be over the limit too
    if (!graph) continue;
    std::string file = stems[i] + ".json";
    out.files.push_back({file, asText(*graph)});
    out.materialGraphs.push_back(file);
    graphOf[names[i]] = file;
    pugi::xml_node shader = surfaceShader(document, materials[i]);
    index["materials"].push_back(Json{{"name", names[i]}, {"shader", shader.attribute("name").value()},
                                      {"shadingModel", shader.name()}, {"graph", file}, {"weatherPreset", naming.weatherPreset}});
  }
  index["images"] = images.index();
  index["looks"] = looksIndex(document, graphOf, diagnostics);
  for (std::size_t i = before; i < diagnostics.items().size(); ++i)
    if (diagnostics.items()[i].info().severity == Severity::Error) return std::nullopt;
  out.imageCount = images.files().size();
  out.imagesRead = images.read();
  for (auto& f : images.files()) out.files.push_back(std::move(f));
  out.indexFile = stem + ".import.json";
  out.files.push_back({out.indexFile, asText(index)});
  return out;
}

}  // namespace wg::mtlx
