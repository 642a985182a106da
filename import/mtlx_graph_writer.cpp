#include "import/mtlx_graph_writer.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <set>

#include "compiler/literal.hpp"
#include "import/mtlx_shading_models.hpp"

namespace wg::mtlx {

namespace {

using Json = nlohmann::ordered_json;

// The compiler's node limit (docs/graph-format.md): a graph past it could not compile,
// and the import stops before it holds that much. The translation recurses along node
// chains, a few KiB of stack a node: 256 keeps it near 1 MiB; MaterialX's own examples
// chain at most 13 nodes.
constexpr std::size_t kMaxGraphNodes = 100000, kMaxChainDepth = 256;

// A value in the graph: a literal, or a link to a node's output; with its MaterialX type.
// A material parameter is a link that keeps its default as `literal`, for the few inputs
// the graph needs as constants.
struct Value {
  Json literal;
  std::string link;
  std::string type;  // float, integer, boolean, vector2, color3, vector3, color4, vector4
  bool tangentNormal = false;  // from a normalmap node: a tangent-space normal

  Json input() const { return link.empty() ? literal : Json(link); }
  bool isLiteral() const { return link.empty(); }
  // The value at compile time: the literal, or a parameter's default; nullopt for a link.
  std::optional<double> constant() const {
    return literal.is_number() ? std::optional(literal.get<double>()) : std::nullopt;
  }
};

int widthOf(std::string_view type) {
  if (type == "float" || type == "integer" || type == "boolean") return 1;
  if (type == "vector2") return 2;
  if (type == "color3" || type == "vector3") return 3;
  if (type == "color4" || type == "vector4") return 4;
  return 0;
}

// "0.5, 0.25, 1" as a literal of `type`; nullopt when it is not one.
std::optional<Json> parseLiteral(const std::string& text, const std::string& type) {
  if (type == "boolean") {
    if (text == "true" || text == "false") return Json(text == "true");
    return std::nullopt;
  }
  int width = widthOf(type);
  if (width == 0) return std::nullopt;
  Json values = Json::array();
  std::size_t at = 0;
  while (at <= text.size()) {
    std::size_t comma = std::min(text.find(',', at), text.size());
    std::string part = text.substr(at, comma - at);
    part.erase(0, part.find_first_not_of(" \t\n\r"));
    part.erase(part.find_last_not_of(" \t\n\r") + 1);
    // Decimal only, as MaterialX writes and reads numbers: strtod alone would take
    // "0x10" as 16 and "infinity", where MaterialX's own stream parsing reads 0 or fails.
    if (part.find_first_not_of("0123456789+-.eE") != std::string::npos) return std::nullopt;
    char* end = nullptr;
    double v = std::strtod(part.c_str(), &end);
    if (part.empty() || *end != '\0' || !std::isfinite(v) || std::fabs(v) > 3.4e38) return std::nullopt;
    if (type == "integer" && v != std::floor(v)) return std::nullopt;
    values.push_back(v);
    at = comma + 1;
  }
  if (static_cast<int>(values.size()) != width) return std::nullopt;
  return width == 1 ? values[0] : values;
}

// The graph's parameter type of a MaterialX value type.
const char* parameterType(std::string_view type) {
  switch (widthOf(type)) {
    case 1: return type == "boolean" ? "bool" : "float";
    case 2: return "vec2";
    case 3: return "vec3";
    default: return "vec4";
  }
}

Json splat(double v, int width) { return width == 1 ? Json(v) : Json(std::vector<double>(width, v)); }

// A short decimal: 0.04 / 0.08 is 0.5, not 0.5000000000000001.
// A number the document gave where an integer is meant, held within int range: the
// literal may be anything up to 3.4e38, and converting that to int would be undefined.
int clampedInt(double v) { return static_cast<int>(std::clamp(v, -2147483648.0, 2147483647.0)); }

// A number as the document gave it, for a message: integers without a fraction.
std::string shownNumber(double v) {
  if (v == std::floor(v) && std::fabs(v) < 1e15) return std::to_string(static_cast<long long>(v));
  return Json(v).dump();
}

double rounded(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.7g", v);
  return std::strtod(text, nullptr);
}

std::string nameOf(pugi::xml_node node) { return node.attribute("name").value(); }

std::string plainName(std::string name) {
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_') c = '_';
  return name.empty() ? "parameter" : name;
}

class GraphWriter {
 public:
  GraphWriter(const Document& doc, const GraphNaming& naming, const ImageFiles& images, std::size_t& nodesLeft,
              DiagnosticList& diags)
      : doc_(doc), naming_(naming), images_(images), nodesLeft_(nodesLeft), diags_(diags) {}

  std::optional<Json> build(pugi::xml_node material) {
    pugi::xml_node shader = surfaceShader(doc_, material);
    if (!shader) {
      problem(DiagCode::MtlxBadReference, material,
              "material '" + quoteUserText(nameOf(material)) + "' has no surfaceshader input naming a shader node",
              "connect its surfaceshader input to a shader node with nodename");
      return std::nullopt;
    }
    const ShadingModel* model = shadingModel(shader.name());
    if (!model) {
      diags_.report(DiagCode::MtlxUnsupportedNode, doc_.locate(shader),
                    {quoteUserText(nameOf(shader)), quoteUserText(shader.name()),
                     "use standard_surface, open_pbr_surface, gltf_pbr or UsdPreviewSurface"});
      return std::nullopt;
    }
    shader_ = shader;
    model_ = model;
    Json output = shaderOutput();
    nodesLeft_ = overLimit_ ? 0 : nodesLeft_ - std::min(nodesLeft_, nodes_.size());
    if (failed_) return std::nullopt;
    dropUnreadParameters(output);
    Json graph;
    graph["name"] = naming_.name;
    graph["description"] = naming_.description;
    if (!parameters_.empty()) graph["parameters"] = parameters_;
    if (!textures_.empty()) graph["textures"] = textures_;
    graph["nodes"] = nodes_;
    graph["output"] = output;
    graph["alphaMode"] = alphaMode_;
    if (alphaMode_ == "mask") graph["alphaCutoff"] = alphaCutoff_;
    graph["doubleSided"] = false;
    graph["weather"] = naming_.weatherPreset == "none" || naming_.snowDisplacement
                           ? Json(naming_.weatherPreset)
                           : Json{{"preset", naming_.weatherPreset}, {"effects", {{"displacement", false}}}};
    return graph;
  }

 private:
  // --- diagnostics ---

  void problem(DiagCode code, pugi::xml_node at, const std::string& what, const std::string& fix) {
    diags_.report(code, doc_.locate(at), {what, fix});
    if (diagnosticInfo(code).severity == Severity::Error) failed_ = true;
  }

  Value failedValue(const std::string& type) {
    failed_ = true;
    return {splat(0, std::max(1, widthOf(type))), "", type};
  }

  Value schemaError(pugi::xml_node at, const std::string& what, const std::string& expected, const std::string& actual,
                    const std::string& type) {
    diags_.report(DiagCode::MtlxSchema, doc_.locate(at), {what, expected, actual});
    return failedValue(type);
  }

  // --- graph nodes ---

  std::string uniqueId(std::string id) {
    for (char& c : id)
      if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_' && c != '.') c = '_';
    if (ids_.insert(id).second) return id;
    // Suffixes below the one tried last for this base are all taken: ids are never freed.
    // Starting there keeps ten thousand names that sanitise alike from taking minutes.
    const std::string base = id;
    int& n = nextSuffix_.try_emplace(base, 2).first->second;
    while (!ids_.insert(id = base + "_" + std::to_string(n)).second) ++n;
    return id;
  }

  // Adds a node and returns the value of its output.
  Value node(const std::string& id, const char* op, Json inputs, const std::string& type, const char* output = "out") {
    if (!overLimit_ && (nodes_.size() >= kMaxGraphNodes || nodes_.size() >= nodesLeft_)) {
      bool own = nodes_.size() >= kMaxGraphNodes;
      std::size_t limit = own ? kMaxGraphNodes : kMaxImportGraphNodes;
      diags_.report(DiagCode::ResourceLimit, doc_.locate(shader_),
                    {own ? "the graph node count" : "the graph node count of all materials together", "over " + std::to_string(limit),
                     std::to_string(limit)});
      failed_ = overLimit_ = true;
    }
    std::string unique = uniqueId(id);
    Json n{{"id", unique}, {"op", op}};
    if (!inputs.empty()) n["inputs"] = std::move(inputs);
    nodes_.push_back(std::move(n));
    return {Json(), unique + "." + output, type};
  }

  Value swizzle(const std::string& id, const Value& in, const std::string& channels, const std::string& type) {
    return node(id, "swizzle", {{"in", in.input()}, {"channels", channels}}, type);
  }

  // MaterialX texture coordinates start at the bottom of the image, the graph's (as glTF's) at the top.
  Value flippedV(const std::string& id, const Value& uv) {
    Value u = swizzle(id + "_u", uv, "x", "float"), v = swizzle(id + "_v", uv, "y", "float");
    Value up = node(id + "_flip", "one_minus", {{"in", v.input()}}, "float");
    return node(id, "combine2", {{"x", u.input()}, {"y", up.input()}}, "vector2");
  }

  // --- the shader ---

  Json shaderOutput() {
    const ShadingModel& m = *model_;
    warnIgnoredInputs();
    Json output;
    Value base = shaderInput(m.baseColor, "color3");
    if (*m.baseWeight) base = product("baseColor", base, shaderInput(m.baseWeight, "float"));
    output["baseColor"] = base.input();
    output["metallic"] = shaderInput(m.metallic, "float").input();
    output["roughness"] = shaderInput(m.roughness, "float").input();
    if (auto specular = specularLevel()) output["specular"] = *specular;
    if (auto normal = normalOutput()) output["normal"] = *normal;
    if (*m.occlusion) {
      Value occlusion = shaderInput(m.occlusion, "float");
      if (!(occlusion.isLiteral() && occlusion.literal == Json(1.0))) output["ambientOcclusion"] = occlusion.input();
    }
    Value emissive = shaderInput(m.emissive, "color3");
    if (*m.emissiveWeight) emissive = product("emissive", emissive, shaderInput(m.emissiveWeight, "float"));
    if (!(emissive.isLiteral() && emissive.literal == splat(0, 3))) output["emissive"] = emissive.input();
    addOpacity(output);
    return output;
  }

  // a x b, folded when both are literals so constant materials stay literal.
  Value product(const std::string& id, const Value& a, const Value& b) {
    if (b.isLiteral() && b.literal == Json(1.0)) return a;
    if (a.isLiteral() && b.isLiteral() && b.literal.is_number()) {
      Json out = a.literal;
      for (auto& v : out) v = rounded(v.get<double>() * b.literal.get<double>());
      if (out.is_number()) out = rounded(a.literal.get<double>() * b.literal.get<double>());
      return {out, "", a.type};
    }
    return node(nameOf(shader_) + "." + id, "multiply", {{"a", a.input()}, {"b", b.input()}}, a.type);
  }

  // The value of a shader input (its default when absent), checked against `type`.
  Value shaderInput(const char* name, const std::string& type) {
    pugi::xml_node input = childInput(shader_, name);
    if (input) return inputValue(input, {}, type);
    for (const auto& [input, text] : model_->defaults)
      if (std::string_view(input) == name) return {*parseLiteral(text, type), "", type};
    return {splat(0, widthOf(type)), "", type};
  }

  // F0 = specular weight x ((ior - 1) / (ior + 1))^2, as the graph's specular = F0 / 0.08.
  std::optional<Json> specularLevel() {
    const ShadingModel& m = *model_;
    Value ior = shaderInput(m.ior, "float");
    Value weight = *m.specularWeight ? shaderInput(m.specularWeight, "float") : Value{Json(1.0), "", "float"};
    if (!ior.isLiteral() || !weight.isLiteral()) {
      warnAdjusted(shader_, "the specular level of shader '" + quoteUserText(nameOf(shader_)) +
                                "' is connected; the graph keeps the dielectric default (F0 0.04)",
                   "give the IOR and specular weight as values");
      return std::nullopt;
    }
    double r = (ior.literal.get<double>() - 1) / (ior.literal.get<double>() + 1);
    double level = rounded(weight.literal.get<double>() * r * r / 0.08);
    if (level > 1) {
      warnAdjusted(shader_, "the specular level of shader '" + quoteUserText(nameOf(shader_)) + "' (F0 " +
                                std::to_string(level * 0.08) + ") is above the UE4 model's 0.08; it is clamped",
                   "an IOR above 1.79 cannot be held by the graph's specular output");
      level = 1;
    }
    return level;
  }

  std::optional<Json> normalOutput() {
    pugi::xml_node input = childInput(shader_, model_->normal);
    if (!input) return std::nullopt;
    Value normal = inputValue(input, {}, "vector3");
    if (normal.tangentNormal) return normal.input();
    if (std::string_view(model_->category) == "UsdPreviewSurface") return normal.input();  // tangent space already
    if (failed_ || (!input.attribute("nodename") && !input.attribute("nodegraph"))) return std::nullopt;  // failed, or the surface's own
    warnAdjusted(input, "the normal of shader '" + quoteUserText(nameOf(shader_)) +
                            "' does not come from a normalmap node; the graph keeps the surface normal",
                 "connect the normal through a normalmap node");
    return std::nullopt;
  }

  void addOpacity(Json& output) {
    const ShadingModel& m = *model_;
    bool colour = std::string_view(m.category) == "standard_surface";
    Value opacity = shaderInput(m.opacity, colour ? "color3" : "float");
    if (colour) {  // the UE4 model has one opacity: the mean of the three
      if (opacity.isLiteral())
        opacity = {rounded((opacity.literal[0].get<double>() + opacity.literal[1].get<double>() + opacity.literal[2].get<double>()) / 3),
                   "", "float"};
      else
        opacity = node(nameOf(shader_) + ".opacity", "dot", {{"a", opacity.input()}, {"b", splat(1.0 / 3, 3)}}, "float");
    }
    alphaMode_ = opacity.isLiteral() && opacity.literal == Json(1.0) ? "opaque" : "blend";
    if (std::string_view(m.category) == "gltf_pbr") gltfAlphaMode();
    if (std::string_view(m.category) == "UsdPreviewSurface") usdAlphaMode();
    if (alphaMode_ != "opaque") output["opacity"] = opacity.input();
  }

  // gltf_pbr's alpha_mode: 0 opaque, 1 mask (with alpha_cutoff), 2 blend.
  void gltfAlphaMode() {
    Value mode = shaderInput("alpha_mode", "integer");
    Value cutoff = shaderInput("alpha_cutoff", "float");
    if (!mode.isLiteral() || !cutoff.isLiteral()) {
      warnAdjusted(shader_, "alpha_mode and alpha_cutoff of shader '" + quoteUserText(nameOf(shader_)) + "' are connected; the material is opaque",
                   "give them as values");
      alphaMode_ = "opaque";
      return;
    }
    int value = mode.literal.is_number() ? clampedInt(mode.literal.get<double>()) : 0;
    alphaMode_ = value == 1 ? "mask" : value == 2 ? "blend" : "opaque";
    alphaCutoff_ = std::clamp(cutoff.isLiteral() && cutoff.literal.is_number() ? cutoff.literal.get<double>() : 0.5, 0.0, 1.0);
  }

  // UsdPreviewSurface: opacityThreshold > 0 cuts out, else opacity below 1 blends.
  void usdAlphaMode() {
    Value threshold = shaderInput("opacityThreshold", "float");
    if (threshold.isLiteral() && threshold.literal.is_number() && threshold.literal.get<double>() > 0) {
      alphaMode_ = "mask";
      alphaCutoff_ = std::clamp(threshold.literal.get<double>(), 0.0, 1.0);
    }
  }

  void warnIgnoredInputs() {
    for (pugi::xml_node input : shader_.children("input")) {
      std::string name = nameOf(input);
      for (const auto& ignored : model_->ignored) {
        std::string_view prefix = ignored.prefix;
        bool matches = prefix.ends_with('_') ? name.starts_with(prefix) : name == prefix;
        if (!matches || inert(input, ignored)) continue;
        diags_.report(DiagCode::MtlxInputIgnored, doc_.locate(input), {quoteUserText(nameOf(shader_)), quoteUserText(name)});
        break;
      }
    }
  }

  // An ignored input changes nothing when it holds its neutral value, or its lobe is off.
  bool inert(pugi::xml_node input, const IgnoredInput& ignored) const {
    auto holds = [](pugi::xml_node in, const char* neutral) {
      if (!in.attribute("value") || in.attribute("nodename") || in.attribute("nodegraph") || in.attribute("interfacename"))
        return false;
      std::string type = in.attribute("type").value();
      auto a = parseLiteral(in.attribute("value").value(), type), b = parseLiteral(neutral, type);
      return a && b && *a == *b;
    };
    if (*ignored.neutral && holds(input, ignored.neutral)) return true;
    if (!*ignored.weight) return false;
    pugi::xml_node weight = childInput(shader_, ignored.weight);
    return !weight || holds(weight, "0") || holds(weight, "0, 0, 0");
  }

  void warnAdjusted(pugi::xml_node at, const std::string& what, const std::string& fix) {
    problem(DiagCode::MtlxFeatureAdjusted, at, what, fix);
  }

  // --- inputs and connections ---

  pugi::xml_node childInput(pugi::xml_node node, std::string_view name) const { return doc_.input(node, name); }

  // The value an <input> gives, in `scope` (a nodegraph, or empty for the document).
  Value inputValue(pugi::xml_node input, pugi::xml_node scope, const std::string& expected) {
    std::string type = input.attribute("type") ? input.attribute("type").value() : expected;
    if (widthOf(type) == 0)
      return schemaError(input, "the type of input '" + quoteUserText(nameOf(input)) + "'", "a MaterialX value type (float, color3, vector2...)",
                         "'" + quoteUserText(type) + "'", expected);
    if (widthOf(type) != widthOf(expected) && !(expected == "float" && type == "integer"))
      return schemaError(input, "input '" + quoteUserText(nameOf(input)) + "'", expected, type, expected);
    Value v = connectedValue(input, scope, type);
    if (v.type != type && !failed_)
      return schemaError(input, "the connection of input '" + quoteUserText(nameOf(input)) + "' (" + type + ")",
                         "an output of type " + type, "one of type " + v.type, type);
    return v;
  }

  Value connectedValue(pugi::xml_node input, pugi::xml_node scope, const std::string& type) {
    if (pugi::xml_attribute nodename = input.attribute("nodename")) {
      pugi::xml_node upstream = scope ? childNode(scope, nodename.value()) : doc_.topLevel(nodename.value());
      if (!upstream) return missingReference(input, "node '" + quoteUserText(nodename.value()) + "'", type);
      return nodeOutput(upstream, scope, input.attribute("output").value());
    }
    if (pugi::xml_attribute graph = input.attribute("nodegraph")) {
      pugi::xml_node ng = doc_.topLevel(graph.value());
      if (!ng || std::string_view(ng.name()) != "nodegraph")
        return missingReference(input, "node graph '" + quoteUserText(graph.value()) + "'", type);
      return graphOutput(input, ng, input.attribute("output").value(), type);
    }
    if (pugi::xml_attribute iface = input.attribute("interfacename")) {
      pugi::xml_node declared = scope ? childInput(scope, iface.value()) : pugi::xml_node();
      if (!declared) return missingReference(input, "interface input '" + quoteUserText(iface.value()) + "'", type);
      Value value = inputValue(declared, {}, type);
      return value.isLiteral() && !failed_ ? parameter(scope, declared, value) : value;
    }
    if (pugi::xml_attribute value = input.attribute("value")) {
      if (auto literal = parseLiteral(value.value(), type)) return {*literal, "", type};
      return schemaError(input, "the value of input '" + quoteUserText(nameOf(input)) + "'", "a " + type,
                         "'" + quoteUserText(value.value()) + "'", type);
    }
    return {splat(0, widthOf(type)), "", type};
  }

  // A node graph's interface input as a material parameter, tunable as glTF import's
  // factors are: named as the input, or NODEGRAPH_INPUT when two graphs share the name
  // (letters, digits and '_' only: "weather." is the weather's prefix).
  Value parameter(pugi::xml_node graph, pugi::xml_node declared, const Value& value) {
    auto key = std::make_pair(declared.internal_object(), std::string("parameter"));
    if (auto done = done_.find(key); done != done_.end()) return done->second;
    std::string name = plainName(nameOf(declared));
    if (parameterNames_.count(name)) name = plainName(nameOf(graph)) + "_" + name;
    if (parameterNames_.count(name)) {  // suffixes below the last one tried for this base are taken, as for ids
      const std::string base = plainName(nameOf(graph) + "_" + nameOf(declared));
      int& n = nextParameterSuffix_.try_emplace(base, 2).first->second;
      while (parameterNames_.count(name = base + "_" + std::to_string(n))) ++n;
    }
    parameterNames_.insert(name);
    Json declaration{{"type", parameterType(value.type)}, {"default", value.literal}};
    if (pugi::xml_attribute label = declared.attribute("uiname")) declaration["label"] = label.value();
    // New by parameterNames_: appended without ordered_map's search through every key.
    static_cast<Json::object_t::Container&>(parameters_.get_ref<Json::object_t&>()).emplace_back(name, std::move(declaration));
    std::string id = uniqueId(name);
    nodes_.push_back(Json{{"id", id}, {"op", "parameter"}, {"param", name}});
    return done_[key] = Value{value.literal, id + ".out", value.type};
  }

  // Interface inputs read only as constants (octaves, an extract index) would be
  // parameters that change nothing: they are left out.
  void dropUnreadParameters(const Json& output) {
    std::set<std::string> read;
    auto collect = [&read](const Json& inputs) {
      for (const auto& [port, value] : inputs.items())
        if (value.is_string()) read.insert(value.get<std::string>());
    };
    collect(output);
    for (const auto& n : nodes_)
      if (n.contains("inputs")) collect(n["inputs"]);
    Json kept = Json::array();
    std::set<std::string> unread;
    for (auto& n : nodes_) {
      if (n["op"] == "parameter" && !read.count(n["id"].get<std::string>() + ".out")) unread.insert(n["param"].get<std::string>());
      else kept.push_back(std::move(n));
    }
    nodes_ = std::move(kept);
    Json declared = Json::object();  // in one pass: erasing key by key searches every key each time
    auto& entries = static_cast<Json::object_t::Container&>(declared.get_ref<Json::object_t&>());
    for (auto& [name, declaration] : parameters_.items())
      if (!unread.count(name)) entries.emplace_back(name, std::move(declaration));
    parameters_ = std::move(declared);
  }

  // `input`: the <input> or <output> that names `what`.
  Value missingReference(pugi::xml_node input, const std::string& what, const std::string& type) {
    problem(DiagCode::MtlxBadReference, input,
            quoteUserText(input.name()) + " '" + quoteUserText(nameOf(input)) + "' names " + what + ", which does not exist",
            "connect it to an element of the document");
    return failedValue(type);
  }

  pugi::xml_node childNode(pugi::xml_node scope, std::string_view name) const { return doc_.childNode(scope, name); }

  Value graphOutput(pugi::xml_node from, pugi::xml_node graph, std::string_view outputName, const std::string& type) {
    pugi::xml_node output = outputName.empty() ? graph.child("output") : doc_.output(graph, outputName);
    if (!output) return missingReference(from, "output '" + quoteUserText(std::string(outputName)) + "' of its node graph", type);
    pugi::xml_node upstream = childNode(graph, output.attribute("nodename").value());
    if (!upstream) return missingReference(output, "node '" + quoteUserText(output.attribute("nodename").value()) + "'", type);
    return nodeOutput(upstream, graph, output.attribute("output").value());
  }

  // --- nodes ---

  Value nodeOutput(pugi::xml_node node, pugi::xml_node scope, const std::string& output) {
    auto key = std::make_pair(node.internal_object(), output);
    if (auto done = done_.find(key); done != done_.end()) return done->second;
    if (std::find(path_.begin(), path_.end(), node) != path_.end()) return cycle(node);
    if (path_.size() == kMaxChainDepth) {
      diags_.report(DiagCode::ResourceLimit, doc_.locate(node), {"the node chain depth", "over " + std::to_string(kMaxChainDepth),
                                                                 std::to_string(kMaxChainDepth)});
      return failedValue(node.attribute("type").value());
    }
    if (failedNodes_.count(node.internal_object()) || overLimit_) return failedValue(node.attribute("type").value());
    path_.push_back(node);
    std::size_t errorsBefore = diags_.items().size();
    Value v = translate(node, scope, output);
    path_.pop_back();
    done_[key] = v;
    if (diags_.items().size() != errorsBefore && failed_) failedNodes_.insert(node.internal_object());  // report a node once
    return v;
  }

  Value cycle(pugi::xml_node node) {
    std::string loop;
    for (auto it = std::find(path_.begin(), path_.end(), node); it != path_.end(); ++it) loop += nameOf(*it) + " -> ";
    problem(DiagCode::MtlxBadReference, node, "the node graph has a cycle: " + quoteUserText(loop + nameOf(node), 200),
            "break the cycle; a node cannot depend on its own output");
    return failedValue(node.attribute("type").value());
  }

  struct Context {
    pugi::xml_node node, scope;
    std::string id, type;
  };

  // One MaterialX node, as graph nodes.
  Value translate(pugi::xml_node n, pugi::xml_node scope, const std::string& output) {
    const std::string category = n.name(), type = n.attribute("type").value();
    const std::string id = (scope ? nameOf(scope) + "." : std::string()) + nameOf(n);
    if (widthOf(type) == 0 && type != "multioutput")
      return schemaError(n, "the type of node '" + quoteUserText(nameOf(n)) + "'", "a MaterialX value type (float, color3, vector2...)",
                         "'" + quoteUserText(type) + "'", "float");
    Context c{n, scope, id, type};
    static const std::map<std::string, Value (GraphWriter::*)(const Context&)> kNodes = {
        {"constant", &GraphWriter::constant},     {"add", &GraphWriter::binary},          {"subtract", &GraphWriter::binary},
        {"multiply", &GraphWriter::binary},       {"divide", &GraphWriter::binary},       {"max", &GraphWriter::binary},
        {"min", &GraphWriter::binary},            {"power", &GraphWriter::power},         {"dotproduct", &GraphWriter::dotProduct},
        {"mix", &GraphWriter::mix},               {"clamp", &GraphWriter::clamp},         {"sin", &GraphWriter::unary},
        {"cos", &GraphWriter::unary},             {"absval", &GraphWriter::unary},        {"floor", &GraphWriter::unary},
        {"sqrt", &GraphWriter::unary},            {"invert", &GraphWriter::invert},       {"convert", &GraphWriter::convert},
        {"swizzle", &GraphWriter::swizzleNode},   {"extract", &GraphWriter::extract},     {"combine2", &GraphWriter::combine},
        {"combine3", &GraphWriter::combine},      {"combine4", &GraphWriter::combine},    {"texcoord", &GraphWriter::texcoord},
        {"position", &GraphWriter::geometry},     {"normal", &GraphWriter::geometry},     {"image", &GraphWriter::image},
        {"tiledimage", &GraphWriter::image},      {"hextiledimage", &GraphWriter::image}, {"normalmap", &GraphWriter::normalMap},
        {"noise2d", &GraphWriter::noise2d},       {"noise3d", &GraphWriter::noise3d},     {"fractal3d", &GraphWriter::fractal3d},
        {"ifgreater", &GraphWriter::ifGreater},   {"ifgreatereq", &GraphWriter::ifGreater}, {"rgbtohsv", &GraphWriter::rgbToHsv},
        {"hsvtorgb", &GraphWriter::hsvToRgb},
        {"place2d", &GraphWriter::place2d},       {"gltf_image", &GraphWriter::gltfImage},
        {"gltf_normalmap", &GraphWriter::gltfNormalMap}, {"geomcolor", &GraphWriter::vertexColour},
        {"geompropvalue", &GraphWriter::geometricProperty},
    };
    if (category.starts_with("separate")) return separate(c, output);
    if (category == "gltf_colorimage") return gltfColorImage(c, output);
    auto it = kNodes.find(category);
    if (it == kNodes.end()) {
      diags_.report(DiagCode::MtlxUnsupportedNode, doc_.locate(n),
                    {quoteUserText(nameOf(n)), quoteUserText(category), "docs/materialx-import.md lists the nodes the import maps; "
                                                                        "replace this one in the document"});
      return failedValue(type);
    }
    return (this->*(it->second))(c);
  }

  // The node's input `name` as `type` (its MaterialX default when absent).
  Value in(const Context& c, const char* name, const std::string& type, Json fallback) {
    pugi::xml_node input = childInput(c.node, name);
    if (!input) return {std::move(fallback), "", type};
    return inputValue(input, c.scope, type);
  }

  // An input of the type it declares (fallbackType when absent or not a value type).
  Value declared(const Context& c, const char* name, const std::string& fallbackType) {
    pugi::xml_node input = childInput(c.node, name);
    std::string type = input ? input.attribute("type").value() : fallbackType;
    if (widthOf(type) == 0) type = fallbackType;
    return in(c, name, type, splat(0, widthOf(type)));
  }

  // An input of the node's own type.
  Value own(const Context& c, const char* name, double fallback) { return in(c, name, c.type, splat(fallback, widthOf(c.type))); }

  // An input that may be a float or the node's own type (MaterialX's "FA" variants).
  Value inEither(const Context& c, const char* name, double fallback) {
    pugi::xml_node input = childInput(c.node, name);
    std::string type = input && std::string_view(input.attribute("type").value()) == "float" ? "float" : c.type;
    return in(c, name, type, splat(fallback, widthOf(type)));
  }

  // A literal that must be given as a value: an op option the graph needs at compile time.
  std::optional<double> literalInput(const Context& c, const char* name, double fallback) {
    Value v = in(c, name, "float", fallback);
    if (auto constant = v.constant()) return constant;
    schemaError(childInput(c.node, name), "input '" + std::string(name) + "' of node '" + quoteUserText(nameOf(c.node)) + "'",
                "a value", "a connection", "float");
    return std::nullopt;
  }

  Value constant(const Context& c) { return own(c, "value", 0); }

  Value binary(const Context& c) {
    std::string op = c.node.name();
    double identity = op == "multiply" || op == "divide" ? 1 : 0;
    Value a = own(c, "in1", identity), b = inEither(c, "in2", identity);
    return node(c.id, op.c_str(), {{"a", a.input()}, {"b", b.input()}}, c.type);
  }

  Value power(const Context& c) {
    Value a = own(c, "in1", 0), b = inEither(c, "in2", 1);
    return node(c.id, "pow", {{"base", a.input()}, {"exponent", b.input()}}, c.type);
  }

  Value dotProduct(const Context& c) {
    Value a = declared(c, "in1", "vector3"), b = in(c, "in2", a.type, splat(0, widthOf(a.type)));
    return node(c.id, "dot", {{"a", a.input()}, {"b", b.input()}}, "float");
  }

  Value mix(const Context& c) {
    Value fg = own(c, "fg", 0), bg = own(c, "bg", 0);
    Value t = inEither(c, "mix", 0);
    return node(c.id, "lerp", {{"a", bg.input()}, {"b", fg.input()}, {"t", t.input()}}, c.type);
  }

  Value clamp(const Context& c) {
    Value x = own(c, "in", 0);
    Value low = inEither(c, "low", 0), high = inEither(c, "high", 1);
    return node(c.id, "clamp", {{"x", x.input()}, {"low", low.input()}, {"high", high.input()}}, c.type);
  }

  Value unary(const Context& c) {
    std::string op = c.node.name();
    Value x = own(c, "in", 0);
    return node(c.id, op == "absval" ? "abs" : op.c_str(), {{"in", x.input()}}, c.type);
  }

  Value invert(const Context& c) {
    Value x = own(c, "in", 0), amount = inEither(c, "amount", 1);
    return node(c.id, "subtract", {{"a", amount.input()}, {"b", x.input()}}, c.type);
  }

  // convert: float to any width (splatted), colour <-> vector of one width, 3 <-> 4 (alpha 1), 2 <-> 3 (z 0).
  Value convert(const Context& c) {
    Value x = declared(c, "in", "float");
    int a = widthOf(x.type), b = widthOf(c.type);
    if (x.type == "boolean") return node(c.id, "select", {{"condition", x.input()}, {"ifTrue", 1.0}, {"ifFalse", 0.0}}, c.type);
    if (a == b) return {x.literal, x.link, c.type};
    if (a == 1) return node(c.id, "multiply", {{"a", x.input()}, {"b", splat(1, b)}}, c.type);
    if (b < a) return swizzle(c.id, x, std::string("xyzw").substr(0, b), c.type);
    Json parts;
    const char* names[] = {"x", "y", "z", "w"};
    for (int i = 0; i < b; ++i)
      parts[names[i]] = i < a ? swizzle(c.id + "_" + names[i], x, names[i], "float").input() : Json(b == 4 && i == 3 ? 1.0 : 0.0);
    return node(c.id, b == 3 ? "combine3" : "combine4", parts, c.type);
  }

  Value swizzleNode(const Context& c) {
    Value x = declared(c, "in", "float");
    const std::string& from = x.type;
    std::string channels = childInput(c.node, "channels").attribute("value").value(), mapped;
    for (char ch : channels) {
      std::size_t at = std::string_view("rgbaxyzw").find(ch);
      if (at == std::string::npos || static_cast<int>(at % 4) >= widthOf(from))
        return schemaError(c.node, "the channels of swizzle '" + quoteUserText(nameOf(c.node)) + "'",
                           "1 to 4 of the input's channels (rgba or xyzw)", "'" + quoteUserText(channels) + "'", c.type);
      mapped += "xyzw"[at % 4];
    }
    if (static_cast<int>(mapped.size()) != widthOf(c.type))
      return schemaError(c.node, "the channel count of swizzle '" + quoteUserText(nameOf(c.node)) + "'",
                         std::to_string(widthOf(c.type)) + " for type " + c.type, std::to_string(mapped.size()), c.type);
    return swizzle(c.id, x, mapped, c.type);
  }

  Value extract(const Context& c) {
    Value x = declared(c, "in", "vector3");
    const std::string& from = x.type;
    Value index = in(c, "index", "integer", 0.0);
    int i = index.constant() ? clampedInt(*index.constant()) : -1;
    if (i < 0 || i >= widthOf(from))
      return schemaError(c.node, "the index of extract '" + quoteUserText(nameOf(c.node)) + "'",
                         "a value from 0 to " + std::to_string(widthOf(from) - 1), index.constant() ? index.literal.dump() : "a connection", "float");
    return swizzle(c.id, x, std::string(1, "xyzw"[i]), "float");
  }

  // separate2/3/4: outputs outx.. or outr..
  Value separate(const Context& c, const std::string& output) {
    Value x = declared(c, "in", "vector3");
    const std::string& from = x.type;
    std::size_t at = output.size() == 4 && output.starts_with("out") ? std::string_view("rgbaxyzw").find(output[3]) : std::string::npos;
    if (at == std::string::npos || static_cast<int>(at % 4) >= widthOf(from))
      return schemaError(c.node, "the output of " + std::string(c.node.name()) + " '" + quoteUserText(nameOf(c.node)) + "'",
                         "outr, outg, outb, outa or outx, outy, outz, outw", "'" + quoteUserText(output) + "'", "float");
    return swizzle(c.id + "_" + output, x, std::string(1, "xyzw"[at % 4]), "float");
  }

  Value combine(const Context& c) {
    int width = widthOf(c.type);
    Json parts;
    const char* names[] = {"x", "y", "z", "w"};
    const char* inputs[] = {"in1", "in2", "in3", "in4"};
    for (int i = 0; i < width; ++i) parts[names[i]] = in(c, inputs[i], "float", 0.0).input();
    return node(c.id, width == 2 ? "combine2" : width == 3 ? "combine3" : "combine4", parts, c.type);
  }

  Value texcoord(const Context& c) {
    Value index = in(c, "index", "integer", 0.0);
    int set = index.constant() ? clampedInt(*index.constant()) : 0;
    if (set != 0 && set != 1) warnAdjusted(c.node, "texcoord '" + quoteUserText(nameOf(c.node)) + "' reads set " + shownNumber(*index.constant()) + "; set 0 is read",
                              "the graph has texture coordinate sets 0 and 1");
    Value uv = flippedV(c.id, node(c.id + "_mesh", set == 1 ? "texcoord1" : "texcoord", Json::object(), "vector2"));
    if (c.type == "vector3") return node(c.id + "_3", "combine3", {{"x", swizzle(c.id + "_x", uv, "x", "float").input()},
                                                                    {"y", swizzle(c.id + "_y", uv, "y", "float").input()}, {"z", 0.0}}, c.type);
    return uv;
  }

  Value geometry(const Context& c) {
    std::string space = childInput(c.node, "space").attribute("value").value();
    if (space != "world")
      warnAdjusted(c.node, std::string(c.node.name()) + " '" + quoteUserText(nameOf(c.node)) + "' is in " +
                               (space.empty() ? "object" : quoteUserText(space)) + " space; the graph reads world space",
                   "the graph knows world space only; it equals object space for an object at the origin, unrotated and unscaled");
    bool position = std::string_view(c.node.name()) == "position";
    return node(c.id, position ? "world_position" : "world_normal", Json::object(), "vector3");
  }

  // The mesh's vertex colour (colour set 0), as wide as the node's type.
  Value vertexColour(const Context& c) {
    Value colour = node(c.id + "_rgba", "vertex_color", Json::object(), "color4");
    int width = widthOf(c.type);
    return width == 4 ? Value{Json(), colour.link, c.type} : swizzle(c.id, colour, std::string("xyz").substr(0, width), c.type);
  }

  // geompropvalue: the texture coordinates and vertex colours the graph has, by their
  // usual names (UV0/st, UV1; Cd/displayColor/color).
  Value geometricProperty(const Context& c) {
    std::string name = childInput(c.node, "geomprop").attribute("value").value();
    bool uv = name == "UV0" || name == "st" || name == "UV1", colour = name == "Cd" || name == "displayColor" || name == "color";
    if (uv && c.type == "vector2")
      return flippedV(c.id, node(c.id + "_mesh", name == "UV1" ? "texcoord1" : "texcoord", Json::object(), "vector2"));
    if (colour && widthOf(c.type) >= 3) return vertexColour(c);
    return schemaError(c.node, "the geomprop of geompropvalue '" + quoteUserText(nameOf(c.node)) + "'",
                       "UV0, st or UV1 (vector2), or Cd, displayColor or color (color3, color4)",
                       "'" + quoteUserText(name) + "' (" + c.type + ")", c.type);
  }

  // --- images ---

  // The nearest fileprefix or colorspace: on the element or its closest ancestor.
  static std::string inherited(pugi::xml_node node, const char* attribute) {
    for (; node; node = node.parent())
      if (pugi::xml_attribute a = node.attribute(attribute)) return a.value();
    return "";
  }

  std::string addressMode(const Context& c, const char* name, const char* fallback) {
    pugi::xml_node input = childInput(c.node, name);
    std::string mode = input ? input.attribute("value").value() : fallback;
    if (mode == "periodic") return "repeat";
    if (mode == "mirror") return "mirror";
    if (mode != "clamp")
      warnAdjusted(input, "address mode '" + quoteUserText(mode) + "' of image '" + quoteUserText(nameOf(c.node)) + "' is read as clamp",
                   "the graph's wrap modes are repeat, clamp and mirror");
    return "clamp";
  }

  std::string textureColorSpace(pugi::xml_node file, const std::string& type) {
    std::string space = inherited(file, "colorspace");
    if (type != "color3" && type != "color4") return "linear";
    if (space == "srgb_texture") return "srgb";
    if (!space.empty() && space != "lin_rec709" && space != "none")  // "none": the bytes as they are
      warnAdjusted(file, "colour space '" + quoteUserText(space) + "' is read as lin_rec709",
                   "the graph reads srgb_texture and lin_rec709; convert the image to one of them");
    return "linear";
  }

  Value image(const Context& c) {
    std::string category = c.node.name();
    if (category == "hextiledimage")
      warnAdjusted(c.node, "hextiledimage '" + quoteUserText(nameOf(c.node)) + "' is read as a plain tiled image",
                   "the graph has no hexagonal tiling; tiling repeats may show");
    return sampleImage(c, textureCoordinate(c, category), c.type);
  }

  // glTF's image nodes: a place2d about the image's top-left corner (glTF's uv origin),
  // the image, then gltf_image's factor.
  Value gltfImage(const Context& c) {
    Value texel = sampleImage(c, placement(c, c.id + "_place", Json::array({0.0, 1.0})), c.type);
    if (!childInput(c.node, "factor")) return texel;
    return node(c.id + "_factor", "multiply", {{"a", texel.input()}, {"b", inEither(c, "factor", 1).input()}}, c.type);
  }

  // gltf_colorimage: image x color x geomcolor; outputs outcolor (rgb) and outa.
  Value gltfColorImage(const Context& c, const std::string& output) {
    if (output != "outcolor" && output != "outa")
      return schemaError(c.node, "the output of gltf_colorimage '" + quoteUserText(nameOf(c.node)) + "'", "outcolor or outa",
                         "'" + quoteUserText(output) + "'", "float");
    auto key = std::make_pair(c.node.internal_object(), std::string("rgba"));
    if (!done_.count(key)) {
      Value texel = sampleImage(c, placement(c, c.id + "_place", Json::array({0.0, 1.0})), "color4");
      Value colour = in(c, "color", "color4", splat(1, 4)), geometry = in(c, "geomcolor", "color4", splat(1, 4));
      Value tinted = node(c.id + "_color", "multiply", {{"a", texel.input()}, {"b", colour.input()}}, "color4");
      done_[key] = node(c.id + "_geomcolor", "multiply", {{"a", tinted.input()}, {"b", geometry.input()}}, "color4");
    }
    const Value& rgba = done_[key];
    return output == "outa" ? swizzle(c.id + "_a", rgba, "w", "float") : swizzle(c.id + "_rgb", rgba, "xyz", "color3");
  }

  // gltf_normalmap: a tangent-space normal map at the placed uv.
  Value gltfNormalMap(const Context& c) {
    Value texel = sampleImage(c, placement(c, c.id + "_place", Json::array({0.0, 1.0})), "vector3");
    Value n = node(c.id, "normal_unpack", {{"rgb", texel.input()}, {"strength", 1.0}}, "vector3");
    n.tangentNormal = true;
    return n;
  }

  // The node's file sampled at `uv` (MaterialX's, v up), as `type`.
  Value sampleImage(const Context& c, const Value& uv, const std::string& type) {
    pugi::xml_node file = childInput(c.node, "file");
    if (!file || !file.attribute("value"))
      return schemaError(c.node, "image '" + quoteUserText(nameOf(c.node)) + "'", "a file input with a value", "none", type);
    auto written = images_(file, inherited(file, "fileprefix") + file.attribute("value").value());
    if (!written) return failedValue(type);
    Json texture{{"file", *written}, {"colorSpace", textureColorSpace(file, type)}};
    std::string u = addressMode(c, "uaddressmode", "periodic"), v = addressMode(c, "vaddressmode", "periodic");
    texture["wrap"] = u == v ? Json(u) : Json::array({u, v});
    texture["filter"] = std::string(childInput(c.node, "filtertype").attribute("value").value()) == "closest" ? "nearest" : "linear";
    std::string name = textureName(texture);
    Value texel = node(c.id + "_texel", "sample", {{"texture", name}, {"uv", flippedV(c.id + "_uv", uv).input()}}, "color4", "rgba");
    std::string base = texel.link.substr(0, texel.link.rfind('.') + 1);
    int width = widthOf(type);
    if (width == 1) return {Json(), base + "r", type};
    if (width == 3) return {Json(), base + "rgb", type};
    if (width == 4) return {Json(), base + "rgba", type};
    return swizzle(c.id + "_rg", texel, "xy", type);
  }

  // One texture per distinct file and sampler.
  std::string textureName(const Json& texture) {
    for (const auto& [name, declared] : textures_.items())
      if (declared == texture) return name;
    std::string name = "image" + std::to_string(textures_.size());
    textures_[name] = texture;
    return name;
  }

  // image: texcoord; tiledimage: texcoord x uvtiling - uvoffset; hextiledimage: texcoord x tiling.
  Value textureCoordinate(const Context& c, const std::string& category) {
    Value uv = childInput(c.node, "texcoord") ? in(c, "texcoord", "vector2", Json()) : defaultTexcoord(c.id + "_texcoord");
    if (category == "image") return uv;
    for (const char* size : {"realworldimagesize", "realworldtilesize"})
      if (childInput(c.node, size))
        warnAdjusted(childInput(c.node, size), std::string(size) + " of '" + quoteUserText(nameOf(c.node)) + "' is not read",
                     "the graph tiles by uvtiling alone; fold the real-world sizes into uvtiling");
    const char* tiling = category == "tiledimage" ? "uvtiling" : "tiling";
    Value scale = in(c, tiling, "vector2", Json::array({1.0, 1.0}));
    Value scaled = node(c.id + "_tiled", "multiply", {{"a", uv.input()}, {"b", scale.input()}}, "vector2");
    if (category != "tiledimage" || !childInput(c.node, "uvoffset")) return scaled;
    Value offset = in(c, "uvoffset", "vector2", Json::array({0.0, 0.0}));
    return node(c.id + "_offset", "subtract", {{"a", scaled.input()}, {"b", offset.input()}}, "vector2");
  }

  // place2d, in MaterialX's order: (uv - pivot) / scale, rotated clockwise by `rotate`
  // degrees, minus offset, plus pivot.
  Value place2d(const Context& c) { return placement(c, c.id, Json::array({0.0, 0.0})); }

  Value placement(const Context& c, const std::string& id, const Json& pivotDefault) {
    Value uv = childInput(c.node, "texcoord") ? in(c, "texcoord", "vector2", Json()) : defaultTexcoord(id + "_texcoord");
    Value pivot = in(c, "pivot", "vector2", pivotDefault), scale = in(c, "scale", "vector2", Json::array({1.0, 1.0}));
    Value offset = in(c, "offset", "vector2", Json::array({0.0, 0.0}));
    auto degrees = literalInput(c, "rotate", 0);
    if (!degrees) return failedValue("vector2");
    Value centred = node(id + "_pivot", "subtract", {{"a", uv.input()}, {"b", pivot.input()}}, "vector2");
    Value placed = node(id + "_scale", "divide", {{"a", centred.input()}, {"b", scale.input()}}, "vector2");
    if (*degrees != 0) {
      double a = *degrees * 3.14159265358979323846 / 180, cs = rounded(std::cos(a)), sn = rounded(std::sin(a));
      Value x = node(id + "_rotx", "dot", {{"a", placed.input()}, {"b", Json::array({cs, sn})}}, "float");
      Value y = node(id + "_roty", "dot", {{"a", placed.input()}, {"b", Json::array({-sn, cs})}}, "float");
      placed = node(id + "_rotate", "combine2", {{"x", x.input()}, {"y", y.input()}}, "vector2");
    }
    Value moved = node(id + "_offset", "subtract", {{"a", placed.input()}, {"b", offset.input()}}, "vector2");
    return node(id, "add", {{"a", moved.input()}, {"b", pivot.input()}}, "vector2");
  }

  Value defaultTexcoord(const std::string& id) { return flippedV(id, node(id + "_mesh", "texcoord", Json::object(), "vector2")); }

  Value normalMap(const Context& c) {
    Value texel = in(c, "in", "vector3", Json::array({0.5, 0.5, 1.0}));
    auto scale = literalInput(c, "scale", 1.0);
    if (!scale) return failedValue("vector3");
    double strength = std::clamp(*scale, -16.0, 16.0);
    if (strength != *scale)
      warnAdjusted(c.node, "the scale of normalmap '" + quoteUserText(nameOf(c.node)) + "' is clamped to [-16, 16]",
                   "normal_unpack takes strengths in that range");
    Value n = node(c.id, "normal_unpack", {{"rgb", texel.input()}, {"strength", strength}}, "vector3");
    n.tangentNormal = true;
    return n;
  }

  // --- noise: the graph's 2D gradient noise, signed as MaterialX's is ---

  Value signedNoise(const std::string& id, const Value& p) {
    Value g = node(id, "gradient_noise", {{"p", p.input()}}, "float");
    return node(id + "_signed", "remap", {{"x", g.input()}, {"outLow", -1.0}, {"outHigh", 1.0}}, "float");
  }

  // 3D noise as the mean of 2D noise on the xy, yz and zx planes (offset apart).
  Value signedNoise3(const std::string& id, const Value& p) {
    const std::pair<const char*, Json> planes[] = {{"xy", Json::array({0.0, 0.0})}, {"yz", Json::array({31.7, 11.3})},
                                                   {"zx", Json::array({7.1, 53.9})}};
    Json sum;
    for (const auto& [channels, offset] : planes) {
      Value plane = swizzle(id + "_" + channels, p, channels, "vector2");
      Value shifted = node(id + "_" + channels + "_at", "add", {{"a", plane.input()}, {"b", offset}}, "vector2");
      Value n = node(id + "_" + channels + "_noise", "gradient_noise", {{"p", shifted.input()}}, "float");
      sum = sum.is_null() ? n.input() : node(id + "_" + channels + "_sum", "add", {{"a", sum}, {"b", n.input()}}, "float").input();
    }
    Value mean = node(id + "_mean", "multiply", {{"a", sum}, {"b", 1.0 / 3}}, "float");
    return node(id + "_signed", "remap", {{"x", mean.input()}, {"outLow", -1.0}, {"outHigh", 1.0}}, "float");
  }

  bool floatOnly(const Context& c) {
    if (c.type == "float") return true;
    schemaError(c.node, "the type of " + std::string(c.node.name()) + " '" + quoteUserText(nameOf(c.node)) + "'", "float", c.type, "float");
    return false;
  }

  // amplitude x noise + pivot
  Value scaledNoise(const Context& c, const Value& noise) {
    Value amplitude = in(c, "amplitude", "float", 1.0), pivot = in(c, "pivot", "float", 0.0);
    Value scaled = node(c.id + "_amplitude", "multiply", {{"a", noise.input()}, {"b", amplitude.input()}}, "float");
    return node(c.id, "add", {{"a", scaled.input()}, {"b", pivot.input()}}, "float");
  }

  Value noise2d(const Context& c) {
    if (!floatOnly(c)) return failedValue("float");
    Value uv = childInput(c.node, "texcoord") ? in(c, "texcoord", "vector2", Json()) : defaultTexcoord(c.id + "_texcoord");
    return scaledNoise(c, signedNoise(c.id + "_noise", uv));
  }

  Value position(const Context& c) {
    if (childInput(c.node, "position")) return in(c, "position", "vector3", Json());
    return node(c.id + "_position", "world_position", Json::object(), "vector3");
  }

  Value noise3d(const Context& c) {
    if (!floatOnly(c)) return failedValue("float");
    return scaledNoise(c, signedNoise3(c.id + "_noise", position(c)));
  }

  // sum over octaves i of diminish^i x noise3d(p x lacunarity^i), x amplitude.
  Value fractal3d(const Context& c) {
    if (!floatOnly(c)) return failedValue("float");
    auto octaves = literalInput(c, "octaves", 3), lacunarity = literalInput(c, "lacunarity", 2), diminish = literalInput(c, "diminish", 0.5);
    if (!octaves || !lacunarity || !diminish) return failedValue("float");
    if (*octaves < 1 || *octaves > 8)
      return schemaError(childInput(c.node, "octaves"), "the octaves of fractal3d '" + quoteUserText(nameOf(c.node)) + "'",
                         "1 to 8", shownNumber(*octaves), "float");
    Value p = position(c);
    Json sum;
    for (int i = 0; i < static_cast<int>(*octaves); ++i) {
      std::string octave = c.id + "_octave" + std::to_string(i);
      Value pi = node(octave + "_p", "multiply", {{"a", p.input()}, {"b", std::pow(*lacunarity, i)}}, "vector3");
      Value term = node(octave, "multiply", {{"a", signedNoise3(octave + "_noise", pi).input()}, {"b", std::pow(*diminish, i)}}, "float");
      sum = sum.is_null() ? term.input() : node(octave + "_sum", "add", {{"a", sum}, {"b", term.input()}}, "float").input();
    }
    Value amplitude = in(c, "amplitude", "float", 1.0);
    return node(c.id, "multiply", {{"a", sum}, {"b", amplitude.input()}}, "float");
  }

  // ifgreater: value1 > value2 ? in1 : in2; ifgreatereq: value1 >= value2 ? in1 : in2.
  Value ifGreater(const Context& c) {
    Value a = in(c, "value1", "float", 1.0), b = in(c, "value2", "float", 0.0);
    Value in1 = own(c, "in1", 0), in2 = own(c, "in2", 0);
    bool orEqual = std::string_view(c.node.name()) == "ifgreatereq";
    Value test = node(c.id + "_test", orEqual ? "less" : "greater", {{"a", a.input()}, {"b", b.input()}}, "boolean");
    return node(c.id, "select", {{"condition", test.input()}, {"ifTrue", (orEqual ? in2 : in1).input()},
                                 {"ifFalse", (orEqual ? in1 : in2).input()}}, c.type);
  }

  // Hue, saturation, value without branches: the max channel and the hue's sextant come
  // from two ordered lerps (the steps pick which channel is larger).
  Value rgbToHsv(const Context& c) {
    Value rgb = in(c, "in", c.type, splat(0, 3));
    auto part = [&](const Value& v, const char* ch) { return swizzle(c.id + "_" + ch, v, ch, "float").input(); };
    Json r = part(rgb, "x"), g = part(rgb, "y"), b = part(rgb, "z");
    Value gb = node(c.id + "_gb", "combine4", {{"x", g}, {"y", b}, {"z", 0.0}, {"w", -1.0 / 3}}, "vector4");
    Value bg = node(c.id + "_bg", "combine4", {{"x", b}, {"y", g}, {"z", -1.0}, {"w", 2.0 / 3}}, "vector4");
    Value gAboveB = node(c.id + "_gAboveB", "step", {{"edge", b}, {"x", g}}, "float");
    Value p = node(c.id + "_p", "lerp", {{"a", bg.input()}, {"b", gb.input()}, {"t", gAboveB.input()}}, "vector4");
    Json px = part(p, "x"), py = part(p, "y"), pz = part(p, "z"), pw = part(p, "w");
    Value low = node(c.id + "_qlow", "combine4", {{"x", px}, {"y", py}, {"z", pw}, {"w", r}}, "vector4");
    Value high = node(c.id + "_qhigh", "combine4", {{"x", r}, {"y", py}, {"z", pz}, {"w", px}}, "vector4");
    Value rAbove = node(c.id + "_rAbove", "step", {{"edge", px}, {"x", r}}, "float");
    Value q = node(c.id + "_q", "lerp", {{"a", low.input()}, {"b", high.input()}, {"t", rAbove.input()}}, "vector4");
    Json qx = part(q, "x"), qy = part(q, "y"), qz = part(q, "z"), qw = part(q, "w");
    Value chroma = node(c.id + "_chroma", "subtract", {{"a", qx}, {"b", node(c.id + "_min", "min", {{"a", qw}, {"b", qy}}, "float").input()}}, "float");
    constexpr double kTiny = 1e-10;  // keeps grey (chroma 0) and black finite
    Value span = node(c.id + "_span", "add", {{"a", node(c.id + "_six", "multiply", {{"a", chroma.input()}, {"b", 6.0}}, "float").input()}, {"b", kTiny}}, "float");
    Value slope = node(c.id + "_slope", "divide", {{"a", node(c.id + "_diff", "subtract", {{"a", qw}, {"b", qy}}, "float").input()}, {"b", span.input()}}, "float");
    Value hue = node(c.id + "_hue", "abs", {{"in", node(c.id + "_hueSum", "add", {{"a", qz}, {"b", slope.input()}}, "float").input()}}, "float");
    Value saturation = node(c.id + "_sat", "divide", {{"a", chroma.input()}, {"b", node(c.id + "_value", "add", {{"a", qx}, {"b", kTiny}}, "float").input()}}, "float");
    return node(c.id, "combine3", {{"x", hue.input()}, {"y", saturation.input()}, {"z", qx}}, c.type);
  }

  // rgb = v x lerp(1, saturate(|frac(h + (1, 2/3, 1/3)) x 6 - 3| - 1), s)
  Value hsvToRgb(const Context& c) {
    Value hsv = in(c, "in", c.type, splat(0, 3));
    Value h = swizzle(c.id + "_h", hsv, "x", "float"), s = swizzle(c.id + "_s", hsv, "y", "float"), v = swizzle(c.id + "_v", hsv, "z", "float");
    Value shifted = node(c.id + "_shift", "add", {{"a", h.input()}, {"b", Json::array({1.0, 2.0 / 3, 1.0 / 3})}}, "vector3");
    Value wrapped = node(c.id + "_frac", "frac", {{"in", shifted.input()}}, "vector3");
    Value ramp = node(c.id + "_ramp", "remap", {{"x", wrapped.input()}, {"outLow", -3.0}, {"outHigh", 3.0}}, "vector3");
    Value tent = node(c.id + "_abs", "abs", {{"in", ramp.input()}}, "vector3");
    Value pure = node(c.id + "_pure", "saturate", {{"in", node(c.id + "_less", "subtract", {{"a", tent.input()}, {"b", 1.0}}, "vector3").input()}}, "vector3");
    Value tinted = node(c.id + "_tint", "lerp", {{"a", 1.0}, {"b", pure.input()}, {"t", s.input()}}, "vector3");
    return node(c.id, "multiply", {{"a", tinted.input()}, {"b", v.input()}}, c.type);
  }

  const Document& doc_;
  const GraphNaming& naming_;
  const ImageFiles& images_;
  std::size_t& nodesLeft_;  // for all materials together
  DiagnosticList& diags_;
  pugi::xml_node shader_;
  const ShadingModel* model_ = nullptr;
  Json nodes_ = Json::array(), textures_ = Json::object(), parameters_ = Json::object();
  std::set<std::string> ids_;
  std::map<std::string, int> nextSuffix_;  // per id base, the suffix to try next
  std::set<std::string> parameterNames_;  // the keys of parameters_, which looks them up one by one
  std::map<std::string, int> nextParameterSuffix_;
  std::map<std::pair<const void*, std::string>, Value> done_;
  std::vector<pugi::xml_node> path_;
  std::set<const void*> failedNodes_;
  std::string alphaMode_ = "opaque";
  double alphaCutoff_ = 0.5;
  bool failed_ = false;
  bool overLimit_ = false;  // a node limit was reached: nothing more is translated
};

}  // namespace

pugi::xml_node surfaceShader(const Document& document, pugi::xml_node material) {
  for (pugi::xml_node input : material.children("input"))
    if (std::string_view(input.attribute("name").value()) == "surfaceshader" && input.attribute("nodename"))
      return document.topLevel(input.attribute("nodename").value());
  return {};
}

std::optional<nlohmann::ordered_json> materialGraph(const Document& document, pugi::xml_node material,
                                                    const GraphNaming& naming, const ImageFiles& images,
                                                    std::size_t& nodesLeft, DiagnosticList& diagnostics) {
  return GraphWriter(document, naming, images, nodesLeft, diagnostics).build(material);
}

}  // namespace wg::mtlx
