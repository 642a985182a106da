#include "compiler/graph_loader.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <span>
#include <sstream>

#include "compiler/literal.hpp"
#include "compiler/sampler_state_loader.hpp"
#include "compiler/static_switches.hpp"
#include "nodes/image_file.hpp"
#include "nodes/regular_file.hpp"
#include "nodes/op_registry.hpp"
#include "nodes/texture_generators.hpp"

namespace wg {

std::optional<std::string> readGraphFile(const std::string& path, DiagnosticList& diagnostics) {
  std::string text;
  FileRead read = readRegularFile(path, JsonLimits{}.maxBytes, text);
  switch (read.status) {
    case FileReadStatus::Ok: return text;
    case FileReadStatus::TooLarge:
      diagnostics.report(DiagCode::ResourceLimit, {path, "", 1, 1},
                         {"the file size", std::to_string(read.size) + " bytes", std::to_string(JsonLimits{}.maxBytes) + " bytes"});
      return std::nullopt;
    case FileReadStatus::NotFound:
      diagnostics.report(DiagCode::FileUnreadable, {path, "", 0, 0},
                         {quoteUserText(path), read.reason, "check the path; it is relative to the working directory"});
      return std::nullopt;
    default:
      diagnostics.report(DiagCode::FileUnreadable, {path, "", 0, 0}, {quoteUserText(path), read.reason, "pass the path of a graph file"});
      return std::nullopt;
  }
}

namespace {

// A JSON number with an integral value (3 and 3.0 alike), else nullopt.
std::optional<std::int64_t> integralValue(const nlohmann::json& j) {
  if (j.is_number_integer()) return j.get<std::int64_t>();
  if (!j.is_number_float()) return std::nullopt;
  double d = j.get<double>();
  constexpr double kLimit = 9.0e15;  // within double's exact-integer range
  if (!(std::fabs(d) < kLimit) || d != std::floor(d)) return std::nullopt;
  return static_cast<std::int64_t>(d);
}

// Switch names and values appear in variant names ("quality=low,snow=on") and on the
// command line, and include aliases prefix names ("stone.albedo"), so all are plain words.
constexpr std::size_t kMaxSwitchValues = 16;
bool isPlainWord(std::string_view word) {
  constexpr std::size_t kMaxWord = 32;
  if (word.empty() || word.size() > kMaxWord || !std::isalpha(static_cast<unsigned char>(word[0]))) return false;
  return std::all_of(word.begin(), word.end(),
                     [](unsigned char c) { return std::isalnum(c) || c == '_' || c == '-'; });
}

// Texture sizes: powers of two keep procedural tiles seamless and mips complete.
constexpr int kMinTextureSize = 16;
constexpr int kMaxTextureSize = 2048;

class Loader {
 public:
  // Where the elements being loaded come from: the graph itself, or a library it
  // includes, whose names get the alias as a prefix ("stone.albedo").
  struct Scope {
    std::string pointer;                // prefix of every pointer: "" or "/include/stone"
    std::string names;                  // prefix of every name: "" or "stone."
    std::filesystem::path fileBase;     // file textures are found relative to this
    std::filesystem::path writtenBase;  // ... and reported relative to the graph with this
  };

  Loader(JsonDocument& doc, DiagnosticList& diags, MaterialGraph& graph, Scope scope)
      : doc_(doc), diags_(diags), graph_(graph), scope_(std::move(scope)) {}

  bool runGraph() {
    const auto& root = doc_.root();
    if (!expectKind(root, "", nlohmann::json::value_t::object, "the document", "an object")) return false;
    if (isImportIndex(root)) return false;
    checkFields(root, "", {"$schema", "name", "description", "include", "parameters", "textures", "switches", "nodes",
                           "output", "weather", "alphaCutoff", "alphaMode", "doubleSided"});
    graph_.sourceFile = doc_.file();
    if (auto* name = required(root, "", "name", nlohmann::json::value_t::string, "a string")) {
      graph_.name = name->get<std::string>();
      if (graph_.name.empty()) report(DiagCode::EmptyName, "/name", {"material name"});
    }
    loadDeclarations(root);
    if (root.contains("include") && expectKind(root["include"], "/include", nlohmann::json::value_t::object, "'include'", "an object") &&
        withinIncludeCount(root["include"]))
      for (const auto& [alias, path] : root["include"].items()) loadLibrary(alias, path);
    if (root.contains("switches") && expectKind(root["switches"], "/switches", nlohmann::json::value_t::object, "'switches'", "an object"))
      for (const auto& [key, value] : root["switches"].items()) loadSwitch(key, value);
    if (auto* output = required(root, "", "output", nlohmann::json::value_t::object, "an object"))
      loadOutput(*output);
    if (root.contains("weather")) {
      const auto& w = root["weather"];
      if (!w.is_string() && !w.is_object())
        report(DiagCode::WrongJsonKind, "/weather", {"'weather'", "a preset name or an object", describeJsonKind(w)});
      else {
        graph_.weather = w;
        graph_.weatherPointer = "/weather";
      }
    }
    if (root.contains("alphaCutoff")) {
      const auto& a = root["alphaCutoff"];
      if (!a.is_number())
        report(DiagCode::WrongJsonKind, "/alphaCutoff", {"'alphaCutoff'", "a number", describeJsonKind(a)});
      else if (double v = a.get<double>(); !(v >= 0.0 && v <= 1.0))
        report(DiagCode::LiteralOutOfRange, "/alphaCutoff", {"alphaCutoff", formatFloat(static_cast<float>(v)), "0", "1"});
      else
        graph_.alphaCutoff = static_cast<float>(v);
    }
    loadAlphaMode(root);
    if (root.contains("doubleSided") && expectKind(root["doubleSided"], "/doubleSided", nlohmann::json::value_t::boolean, "'doubleSided'", "true or false"))
      graph_.doubleSided = root["doubleSided"].get<bool>();
    sortAndCheckNames();
    return !failed_;
  }

 private:
  // "alphaMode": "opaque" | "mask" | "blend"; absent, the rule follows output.opacity.
  void loadAlphaMode(const nlohmann::json& root) {
    auto* mode = optionalString(root, "", "alphaMode");
    if (!mode) return;
    graph_.alphaMode = parseAlphaMode(mode->get<std::string>());
    if (!graph_.alphaMode)
      report(DiagCode::UnknownAlphaMode, "/alphaMode",
             {quoteUserText(mode->get<std::string>()),
              unknownNameHint(mode->get<std::string>(), {"opaque", "mask", "blend"}, "alpha modes")});
  }

  // Parameters, textures and nodes: what a graph and a library both declare.
  void loadDeclarations(const nlohmann::json& root) {
    std::string at = scope_.pointer;
    if (root.contains("parameters") && expectKind(root["parameters"], at + "/parameters", nlohmann::json::value_t::object, "'parameters'", "an object"))
      for (const auto& [key, value] : root["parameters"].items()) loadParameter(key, value);
    if (root.contains("textures") && expectKind(root["textures"], at + "/textures", nlohmann::json::value_t::object, "'textures'", "an object"))
      for (const auto& [key, value] : root["textures"].items()) loadTexture(key, value);
    if (auto* nodes = required(root, at, "nodes", nlohmann::json::value_t::array, "an array"))
      for (std::size_t i = 0; i < nodes->size(); ++i) loadNode((*nodes)[i], appendPointer(at + "/nodes", i));
  }

  // Limits on the whole: each library is within the file limit, but 300 aliases of one
  // 15 MiB library would still read 4.5 GiB.
  static constexpr std::size_t kMaxIncludes = 64;
  static constexpr std::uintmax_t kMaxTotalBytes = 32u << 20;  // graph and libraries together

  bool withinIncludeCount(const nlohmann::json& includes) {
    if (includes.size() <= kMaxIncludes) return true;
    report(DiagCode::ResourceLimit, "/include",
           {"the number of included libraries", std::to_string(includes.size()), std::to_string(kMaxIncludes)});
    return false;
  }

  // Counts the library's size towards the total before it is read.
  bool withinTotalBytes(const std::string& at, std::uintmax_t size) {
    if (bytesRead_ == 0) bytesRead_ = doc_.text().size();
    if (bytesRead_ > kMaxTotalBytes) return false;  // reported once, at the first library over
    bytesRead_ += size;
    if (bytesRead_ <= kMaxTotalBytes) return true;
    report(DiagCode::ResourceLimit, at,
           {"the size of the graph and the libraries it includes, up to this one", std::to_string(bytesRead_) + " bytes",
            std::to_string(kMaxTotalBytes) + " bytes"});
    return false;
  }

  // The texture's path as outputs record it: relative to the graph, so reflection and
  // headers do not depend on where the checkout lives (hermetic build caches). An
  // absolute path is recorded relative to the graph's folder too.
  std::string recordedTexturePath(const std::string& written, const std::string& resolved) const {
    const auto asWritten = (scope_.writtenBase / written).lexically_normal();
    if (!asWritten.is_absolute()) return asWritten.string();  // a library included by absolute path makes it so
    std::error_code ec;
    const auto graphFolder = std::filesystem::absolute(doc_.file(), ec).parent_path();
    const auto relative = std::filesystem::path(resolved).lexically_relative(graphFolder);
    return ec || relative.empty() ? std::filesystem::path(resolved).filename().string() : relative.string();
  }

  // "include": {"stone": "lib/stone.json"}: the library's parameters, textures and
  // nodes join the graph as "stone.NAME". Libraries do not include others.
  void loadLibrary(const std::string& alias, const nlohmann::json& path) {
    std::string at = appendPointer("/include", alias);
    if (!isPlainWord(alias)) {
      report(DiagCode::NotAPlainWord, at, {"include alias", quoteUserText(alias)});
      return;
    }
    if (!expectKind(path, at, nlohmann::json::value_t::string, "an include", "the path of a graph library")) return;
    if (path.get<std::string>().find('\0') != std::string::npos) {
      // The file system would read only up to the NUL: a different file than written.
      report(DiagCode::FileUnreadable, at, {quoteUserText(path.get<std::string>()), "the path holds a NUL character", "remove the \\u0000 from the path"});
      return;
    }
    std::filesystem::path written = path.get<std::string>();
    std::filesystem::path resolved = (std::filesystem::path(doc_.file()).parent_path() / written).lexically_normal();
    std::error_code ec;
    if (FileRead kind = inspectRegularFile(resolved.string()); kind.status != FileReadStatus::Ok) {
      const bool missing = kind.status == FileReadStatus::NotFound;
      report(DiagCode::FileUnreadable, at,
             {quoteUserText(written.string()), missing ? "no such library file" : kind.reason,
              missing ? "include paths are relative to the including graph" : "include a graph library file"});
      return;
    }
    // A library is never empty; files that claim size 0 include /proc entries whose
    // reads can block, and bad input must never hang the compiler.
    const std::uintmax_t size = std::filesystem::file_size(resolved, ec);
    if (size == 0 || ec) {
      report(DiagCode::FileUnreadable, at, {quoteUserText(written.string()), "the file is empty", "include a graph library file"});
      return;
    }
    if (!withinTotalBytes(at, size)) return;
    graph_.includedFiles.push_back(resolved.string());
    auto text = readGraphFile(resolved.string(), diags_);
    auto library = text ? parseJsonDocument(resolved.string(), std::move(*text), diags_) : std::nullopt;
    if (!library) {
      failed_ = true;
      return;
    }
    auto shared = std::make_shared<const JsonDocument>(std::move(*library));
    doc_.mount(at, shared);  // from here on, pointers under `at` locate in the library
    Loader child(doc_, diags_, graph_, {at, alias + ".", resolved.parent_path(), written.parent_path()});
    child.runLibrary(shared->root());
    failed_ = failed_ || child.failed_;
  }

  void runLibrary(const nlohmann::json& root) {
    if (!expectKind(root, scope_.pointer, nlohmann::json::value_t::object, "a graph library", "an object")) return;
    if (root.contains("include"))
      report(DiagCode::UnknownField, appendPointer(scope_.pointer, "include"),
             {"include", "a library cannot include other libraries; include each one from the graph"});
    checkFields(root, scope_.pointer, {"$schema", "description", "include", "parameters", "textures", "nodes"});
    loadDeclarations(root);
  }

  // Names stay sorted, and one declared in a library may not also be the graph's.
  void sortAndCheckNames() {
    // The material block must fit the 16 KiB uniform range every Vulkan device offers
    // (a vec4 each); past about 16k members SPIR-V validation itself fails.
    constexpr std::size_t kMaxParameters = 1024;
    if (graph_.parameters.size() > kMaxParameters)
      report(DiagCode::ResourceLimit, "/parameters",
             {"the parameter count (libraries included)", std::to_string(graph_.parameters.size()), std::to_string(kMaxParameters)});
    auto byName = [](const auto& a, const auto& b) { return a.name < b.name; };
    std::stable_sort(graph_.parameters.begin(), graph_.parameters.end(), byName);
    std::stable_sort(graph_.textures.begin(), graph_.textures.end(), byName);
    for (std::size_t i = 1; i < graph_.parameters.size(); ++i)
      if (graph_.parameters[i].name == graph_.parameters[i - 1].name)
        // Reported where the graph declares it (loaded before any library), as for textures.
        report(DiagCode::DuplicateParameter, graph_.parameters[i - 1].pointer,
               {quoteUserText(graph_.parameters[i].name), graph_.parameters[i].pointer});
    for (std::size_t i = 1; i < graph_.textures.size(); ++i)
      if (graph_.textures[i].name == graph_.textures[i - 1].name)
        // Reported where the graph declares it (loaded before any library): the name to change.
        report(DiagCode::DuplicateTexture, graph_.textures[i - 1].pointer,
               {quoteUserText(graph_.textures[i].name), graph_.textures[i].pointer});
  }

  Diagnostic& report(DiagCode code, const std::string& pointer, std::initializer_list<std::string_view> args) {
    failed_ = true;
    return diags_.report(code, doc_.locate(pointer), args);
  }

  static bool isKind(const nlohmann::json& j, nlohmann::json::value_t kind) {
    return j.type() == kind || (kind == nlohmann::json::value_t::number_float && j.is_number());
  }

  bool expectKind(const nlohmann::json& j, const std::string& pointer, nlohmann::json::value_t kind,
                  std::string_view what, std::string_view expected) {
    bool ok = isKind(j, kind);
    if (!ok) report(DiagCode::WrongJsonKind, pointer, {what, expected, describeJsonKind(j)});
    return ok;
  }

  // The member's pointer and name are built only for a report: most fields are fine.
  const nlohmann::json* member(const nlohmann::json& object, const std::string& pointer, const char* key,
                               nlohmann::json::value_t kind, std::string_view expected, bool mandatory) {
    auto it = object.find(std::string_view(key));  // no strlen per comparison
    if (it == object.end()) {
      if (mandatory) report(DiagCode::MissingField, pointer, {key});
      return nullptr;
    }
    if (isKind(*it, kind)) return &*it;
    report(DiagCode::WrongJsonKind, appendPointer(pointer, key), {"'" + std::string(key) + "'", expected, describeJsonKind(*it)});
    return nullptr;
  }
  const nlohmann::json* required(const nlohmann::json& object, const std::string& pointer, const char* key,
                                 nlohmann::json::value_t kind, std::string_view expected) {
    return member(object, pointer, key, kind, expected, true);
  }
  const nlohmann::json* optionalString(const nlohmann::json& object, const std::string& pointer, const char* key) {
    return member(object, pointer, key, nlohmann::json::value_t::string, "a string", false);
  }

  // MODEL.import.json, which `compile out/*.json` meets beside the graphs: one error
  // naming the graphs it lists, not a dozen about its fields.
  bool isImportIndex(const nlohmann::json& root) {
    const auto generator = root.find("generator");
    const auto materials = root.find("materials");
    if (root.contains("nodes") || generator == root.end() || !generator->is_string() ||
        !generator->get_ref<const std::string&>().starts_with("weathergen ") || materials == root.end() ||
        !materials->is_array())
      return false;
    std::string graphs;
    std::size_t listed = 0;
    for (const auto& material : *materials) {
      const auto graph = material.is_object() ? material.find("graph") : material.end();
      if (!material.is_object() || graph == material.end() || !graph->is_string()) continue;
      if (++listed <= 3) graphs += (graphs.empty() ? "'" : ", '") + quoteUserText(graph->get<std::string>()) + "'";
    }
    if (listed > 3) graphs += " and " + std::to_string(listed - 3) + " more";
    report(DiagCode::ImportIndex, "", {graphs.empty() ? std::string("(none)") : graphs});
    return true;
  }

  void checkFields(const nlohmann::json& object, const std::string& pointer, std::initializer_list<std::string_view> known) {
    checkFields(object, pointer, std::span<const std::string_view>(known.begin(), known.size()));
  }
  void checkFields(const nlohmann::json& object, const std::string& pointer, std::span<const std::string_view> known) {
    for (const auto& [key, value] : object.items()) {
      const std::string_view name = key;  // compared without a strlen each time
      if ((name == "description" || name == "$schema") && !value.is_string())
        report(DiagCode::WrongJsonKind, appendPointer(pointer, key), {"'" + key + "'", "a string", describeJsonKind(value)});
      if (std::find(known.begin(), known.end(), name) != known.end()) continue;
      std::string hint = unknownNameHint(key, {known.begin(), known.end()}, "known fields");
      failed_ = true;
      std::string fieldPointer = appendPointer(pointer, key);
      diags_.report(DiagCode::UnknownField, doc_.locateKey(fieldPointer), {quoteUserText(key), hint});
    }
  }

  void loadParameter(const std::string& name, const nlohmann::json& j) {
    std::string pointer = appendPointer(scope_.pointer + "/parameters", name);
    if (!expectKind(j, pointer, nlohmann::json::value_t::object, "a parameter", "an object")) return;
    checkFields(j, pointer, {"type", "default", "min", "max", "label", "description"});
    ParameterDecl p;
    p.name = scope_.names + name;
    p.pointer = pointer;
    std::string shown = quoteUserText(name);
    if (name.empty()) report(DiagCode::EmptyName, pointer, {"parameter name"});
    if (auto* type = required(j, pointer, "type", nlohmann::json::value_t::string, "a string")) {
      auto t = parseTypeName(type->get<std::string>());
      if (!t || *t == ValueType::Texture) {
        report(DiagCode::InvalidParameterType, appendPointer(pointer, "type"), {shown, quoteUserText(type->get<std::string>())});
        return;
      }
      p.type = *t;
    } else {
      return;
    }
    for (const char* bound : {"min", "max"}) {
      if (!j.contains(bound)) continue;
      if (p.type == ValueType::Bool) {
        report(DiagCode::BoolParameterRange, appendPointer(pointer, bound), {shown, bound});
        continue;
      }
      const auto& b = j[bound];
      if (!expectKind(b, appendPointer(pointer, bound), nlohmann::json::value_t::number_float, "'" + std::string(bound) + "'", "a number")) continue;
      LiteralResult r = parseLiteral(b);
      if (r.notFinite) {
        report(DiagCode::LiteralNotFinite, appendPointer(pointer, bound), {std::string(bound)});
        continue;
      }
      (std::string_view(bound) == "min" ? p.min : p.max) = r.value->x();
    }
    bool boundsValid = !(p.min && p.max && *p.min > *p.max);
    if (!boundsValid)
      report(DiagCode::ParameterRangeInverted, appendPointer(pointer, "min"), {shown, formatFloat(*p.min), formatFloat(*p.max)});
    if (auto* label = optionalString(j, pointer, "label")) p.label = label->get<std::string>();
    auto it = j.find("default");
    if (it == j.end()) {
      report(DiagCode::MissingField, pointer, {"default"});
      return;
    }
    std::string dp = appendPointer(pointer, "default");
    LiteralResult r = parseLiteral(*it);
    if (!r.value) {
      report(DiagCode::TypeMismatch, dp, {"parameter '" + shown + "'", std::string(typeName(p.type)), r.shapeError,
                                          "write the default as a " + std::string(typeName(p.type)) + " literal"});
      return;
    }
    if (r.notFinite) {
      report(DiagCode::LiteralNotFinite, dp, {"the default of '" + shown + "'"});
      return;
    }
    if (r.value->type != p.type) {
      report(DiagCode::TypeMismatch, dp, {"parameter '" + shown + "'", std::string(typeName(p.type)),
                                          std::string(typeName(r.value->type)),
                                          "write the default as a " + std::string(typeName(p.type)) + " literal"});
      return;
    }
    p.defaultValue = *r.value;
    for (int i = 0; boundsValid && i < p.defaultValue.width() && p.type != ValueType::Bool; ++i) {
      float x = p.defaultValue.v[i];
      if ((p.min && x < *p.min) || (p.max && x > *p.max)) {
        report(DiagCode::LiteralOutOfRange, dp, {"the default of '" + shown + "'", formatFloat(x),
                                                 p.min ? formatFloat(*p.min) : "-inf", p.max ? formatFloat(*p.max) : "inf"});
        break;
      }
    }
    graph_.parameters.push_back(std::move(p));
  }

  void loadTexture(const std::string& name, const nlohmann::json& j) {
    std::string pointer = appendPointer(scope_.pointer + "/textures", name);
    std::string shown = quoteUserText(name);
    if (!expectKind(j, pointer, nlohmann::json::value_t::object, "a texture", "an object")) return;
    TextureDecl t;
    t.name = scope_.names + name;
    t.pointer = pointer;
    if (name.empty())
      report(DiagCode::EmptyName, pointer, {"texture name"});
    bool hasFile = j.contains("file"), hasGenerator = j.contains("generator");
    if (!loadSamplerState(j, pointer, shown, hasGenerator && !hasFile, doc_, diags_, t.sampler)) failed_ = true;
    if (hasFile == hasGenerator) {
      report(DiagCode::TextureSourceConflict, pointer,
             {shown, hasFile ? "both 'file' and 'generator'" : "neither 'file' nor 'generator'"});
      return;
    }
    if (hasFile) {
      checkFields(j, pointer, {"file", "wrap", "filter", "colorSpace", "description"});
      auto* file = optionalString(j, pointer, "file");
      if (!file) return;
      if (file->get<std::string>().find('\0') != std::string::npos) {
        // The file system would read only up to the NUL: a different file than written.
        report(DiagCode::FileUnreadable, appendPointer(pointer, "file"),
               {quoteUserText(file->get<std::string>()), "the path holds a NUL character", "remove the \\u0000 from the path"});
        return;
      }
      // A library's file is reported relative to the including graph, like the graph's own.
      t.resolvedPath = (scope_.fileBase / file->get<std::string>()).lexically_normal().string();
      t.file = recordedTexturePath(file->get<std::string>(), t.resolvedPath);
      int width = 0, height = 0;
      std::string error;
      switch (probeImageFile(t.resolvedPath, width, height, error)) {
        case ImageFileStatus::Ok: break;
        case ImageFileStatus::NotFound:
          report(DiagCode::TextureFileMissing, appendPointer(pointer, "file"), {shown, quoteUserText(t.file)});
          return;
        case ImageFileStatus::Unsupported:
          report(DiagCode::TextureUnsupported, appendPointer(pointer, "file"),
                 {shown, "file '" + quoteUserText(t.file) + "': " + quoteUserText(error)});
          return;
        case ImageFileStatus::TooLarge:
          report(DiagCode::ResourceLimit, appendPointer(pointer, "file"),
                 {"texture '" + shown + "' (file '" + quoteUserText(t.file) + "')",
                  std::to_string(width) + "x" + std::to_string(height), "8192x8192"});
          return;
      }
    } else {
      auto* generatorName = optionalString(j, pointer, "generator");
      if (!generatorName) return;
      t.generator = generatorName->get<std::string>();
      const GeneratorSpec* spec = findTextureGenerator(t.generator);
      if (!spec) {
        std::vector<std::string_view> names;
        for (const auto& g : textureGenerators()) names.push_back(g.name);
        std::string hint = unknownNameHint(t.generator, names, "built-in generators");
        report(DiagCode::UnknownGenerator, appendPointer(pointer, "generator"), {shown, quoteUserText(t.generator), hint});
        return;
      }
      if (j.contains("seed")) {
        auto seed = integralValue(j["seed"]);
        if (!seed || *seed < 0 || *seed > 0xFFFFFFFFll)
          report(DiagCode::InvalidGeneratorOption, appendPointer(pointer, "seed"),
                 {shown, "the seed must be a whole number in [0, 4294967295]"});
        else
          t.seed = static_cast<std::uint32_t>(*seed);
      }
      if (j.contains("size")) {
        std::int64_t n = integralValue(j["size"]).value_or(0);
        if (n < kMinTextureSize || n > kMaxTextureSize || (n & (n - 1)) != 0)
          report(DiagCode::InvalidGeneratorOption, appendPointer(pointer, "size"),
                 {shown, "size must be a power of two from 16 to 2048"});
        else
          t.size = static_cast<int>(n);
      }
      nlohmann::json options = nlohmann::json::object();
      for (const auto& [key, value] : j.items())
        if (key != "generator" && key != "seed" && key != "size" && key != "wrap" && key != "filter" && key != "colorSpace" &&
            key != "description")
          options[key] = value;
      std::string error = validateGeneratorOptions(*spec, options);
      if (!error.empty())
        // Our own message (it may quote a user's option name, hence the escaping).
        report(DiagCode::InvalidGeneratorOption, pointer, {shown, quoteUserText(error, 400)});
      t.options = std::move(options);
    }
    graph_.textures.push_back(std::move(t));
  }

  InputSource loadInput(const nlohmann::json& j, const std::string& pointer) {
    InputSource s;
    s.pointer = pointer;
    if (j.is_string()) {
      s.kind = InputSource::Kind::Link;
      s.text = j.get<std::string>();
    } else {
      s.kind = InputSource::Kind::Literal;
      s.literal = j;
    }
    return s;
  }

  void loadNode(const nlohmann::json& j, const std::string& pointer) {
    if (!expectKind(j, pointer, nlohmann::json::value_t::object, "a node", "an object")) return;
    checkFields(j, pointer, {"id", "op", "inputs", "param", "switch", "cases", "description"});
    NodeDecl n;
    n.pointer = pointer;
    auto* id = required(j, pointer, "id", nlohmann::json::value_t::string, "a string");
    auto* op = required(j, pointer, "op", nlohmann::json::value_t::string, "a string");
    if (!id || !op) return;
    n.id = scope_.names + id->get_ref<const std::string&>();
    n.op = op->get_ref<const std::string&>();
    if (id->get_ref<const std::string&>().empty()) report(DiagCode::EmptyName, appendPointer(pointer, "id"), {"node id"});
    if (auto* param = optionalString(j, pointer, "param")) n.param = scope_.names + param->get<std::string>();
    if (n.op == kSwitchOp) {
      loadSwitchNode(j, n);
      for (auto& [value, source] : n.cases) renameLocal(source, false);
      graph_.nodes.push_back(std::move(n));
      return;
    }
    for (const char* field : {"switch", "cases"})
      if (j.contains(std::string_view(field)))
        report(DiagCode::UnknownField, appendPointer(pointer, field), {field, "only op 'switch' takes 'switch' and 'cases'"});
    if (auto found = j.find(std::string_view("inputs")); found != j.end()) {
      const auto& inputs = *found;
      std::string ip = appendPointer(pointer, "inputs");
      const OpDef* def = findOp(n.op);
      if (expectKind(inputs, ip, nlohmann::json::value_t::object, "'inputs'", "an object"))
        for (const auto& [port, value] : inputs.items()) {
          InputSource source = loadInput(value, appendPointer(ip, port));
          // A Text port's string is a setting (swizzle channels), not a name.
          const PortSpec* spec = def ? def->findInput(port) : nullptr;
          renameLocal(source, spec && spec->type == PortType::Text);
          n.inputs.emplace_back(port, std::move(source));
        }
    }
    graph_.nodes.push_back(std::move(n));
  }

  // Inside a library, links and texture names refer to the library's own elements.
  void renameLocal(InputSource& source, bool isSetting) const {
    if (!scope_.names.empty() && source.kind == InputSource::Kind::Link && !isSetting) source.text = scope_.names + source.text;
  }

  // {"type": "bool", "default": true} or {"values": ["low", "high"], "default": "high"}.
  void loadSwitch(const std::string& name, const nlohmann::json& j) {
    std::string pointer = appendPointer("/switches", name);
    if (!expectKind(j, pointer, nlohmann::json::value_t::object, "a switch", "an object")) return;
    checkFields(j, pointer, {"type", "values", "default", "description"});
    SwitchDecl sw;
    sw.name = name;
    sw.pointer = pointer;
    if (!isPlainWord(name)) report(DiagCode::NotAPlainWord, pointer, {"switch", quoteUserText(name)});
    std::optional<bool> isBool = switchIsBool(sw, j);
    if (!isBool) return;
    if (*isBool)
      sw.values = {std::string(kSwitchOff), std::string(kSwitchOn)};
    else if (!loadSwitchValues(sw, j["values"]))
      return;
    if (loadSwitchDefault(sw, j, *isBool)) graph_.switches.push_back(std::move(sw));
  }

  // Whether the switch is a bool, or nullopt when it is neither or both.
  std::optional<bool> switchIsBool(const SwitchDecl& sw, const nlohmann::json& j) {
    bool isBool = false;
    if (auto* type = optionalString(j, sw.pointer, "type")) {
      isBool = type->get<std::string>() == "bool";
      if (!isBool) {
        report(DiagCode::InvalidSwitchType, appendPointer(sw.pointer, "type"),
               {quoteUserText(sw.name), quoteUserText(type->get<std::string>())});
        return std::nullopt;
      }
    }
    if (isBool != j.contains("values")) return isBool;
    report(DiagCode::SwitchKindAmbiguous, sw.pointer, {quoteUserText(sw.name)});
    return std::nullopt;
  }

  bool loadSwitchValues(SwitchDecl& sw, const nlohmann::json& values) {
    std::string vp = appendPointer(sw.pointer, "values");
    if (!expectKind(values, vp, nlohmann::json::value_t::array, "'values'", "an array of strings")) return false;
    if (values.size() < 2 || values.size() > kMaxSwitchValues) {
      report(DiagCode::SwitchValueCount, vp,
             {quoteUserText(sw.name), std::to_string(values.size()) + (values.size() == 1 ? " value" : " values"),
              std::to_string(kMaxSwitchValues)});
      return false;
    }
    for (std::size_t i = 0; i < values.size(); ++i) {
      std::string at = appendPointer(vp, i);
      if (!expectKind(values[i], at, nlohmann::json::value_t::string, "a switch value", "a string")) return false;
      std::string v = values[i].get<std::string>();
      if (!isPlainWord(v)) {
        report(DiagCode::NotAPlainWord, at, {"switch '" + quoteUserText(sw.name) + "': value", quoteUserText(v)});
        return false;
      }
      if (std::find(sw.values.begin(), sw.values.end(), v) != sw.values.end()) {
        report(DiagCode::DuplicateSwitchValue, at, {quoteUserText(sw.name), v});
        return false;
      }
      sw.values.push_back(v);
    }
    return true;
  }

  bool loadSwitchDefault(SwitchDecl& sw, const nlohmann::json& j, bool isBool) {
    auto it = j.find("default");
    if (it == j.end()) {
      report(DiagCode::MissingField, sw.pointer, {"default"});
      return false;
    }
    std::string dp = appendPointer(sw.pointer, "default");
    if (isBool) {
      if (!expectKind(*it, dp, nlohmann::json::value_t::boolean, "the default of a bool switch", "true or false")) return false;
      sw.defaultValue = it->get<bool>() ? kSwitchOn : kSwitchOff;
      return true;
    }
    if (!expectKind(*it, dp, nlohmann::json::value_t::string, "the default", "one of the values")) return false;
    sw.defaultValue = it->get<std::string>();
    if (std::find(sw.values.begin(), sw.values.end(), sw.defaultValue) != sw.values.end()) return true;
    report(DiagCode::UnknownSwitchValue, dp,
           {quoteUserText(sw.name), "'" + quoteUserText(sw.defaultValue) + "'", listNames(sw.values)});
    return false;
  }

  // {"id": "detail", "op": "switch", "switch": "quality", "cases": {"low": 0.5, "high": "noise.out"}}
  void loadSwitchNode(const nlohmann::json& j, NodeDecl& n) {
    if (j.contains("inputs"))
      report(DiagCode::UnknownField, appendPointer(n.pointer, "inputs"), {"inputs", "op 'switch' takes 'cases', one source per switch value"});
    if (auto* name = required(j, n.pointer, "switch", nlohmann::json::value_t::string, "a string"))
      n.switchName = name->get<std::string>();
    if (auto* cases = required(j, n.pointer, "cases", nlohmann::json::value_t::object, "an object")) {
      std::string cp = appendPointer(n.pointer, "cases");
      for (const auto& [value, source] : cases->items()) n.cases.emplace_back(value, loadInput(source, appendPointer(cp, value)));
    }
  }

  void loadOutput(const nlohmann::json& j) {
    std::vector<std::string_view> known;
    for (const auto& f : pbrFields()) known.push_back(f.name);
    checkFields(j, "/output", known);
    for (const auto& [key, value] : j.items())
      if (auto field = findPbrField(key)) graph_.outputs[*field] = loadInput(value, appendPointer("/output", key));
  }

  JsonDocument& doc_;
  std::uintmax_t bytesRead_ = 0;  // the graph and the libraries read so far
  DiagnosticList& diags_;
  MaterialGraph& graph_;
  Scope scope_;
  bool failed_ = false;
};

}  // namespace

std::optional<MaterialGraph> loadMaterialGraph(JsonDocument& document, DiagnosticList& diagnostics) {
  MaterialGraph graph;
  std::filesystem::path dir = std::filesystem::path(document.file()).parent_path();
  if (!Loader(document, diagnostics, graph, {"", "", dir, ""}).runGraph()) return std::nullopt;
  return graph;
}

}  // namespace wg
