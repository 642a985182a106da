#include "import/material_graph_writer.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "compiler/literal.hpp"

namespace wg::gltf {

namespace {

using Json = nlohmann::ordered_json;

// glTF sampler enums (glTF 2.0, 5.26).
constexpr int kNearest = 9728, kLinear = 9729, kNearestMipmapNearest = 9984, kLinearMipmapNearest = 9985,
              kNearestMipmapLinear = 9986, kLinearMipmapLinear = 9987;
constexpr int kClampToEdge = 33071, kMirroredRepeat = 33648, kRepeat = 10497;

// Extensions whose meaning the graph carries.
bool mappedMaterialExtension(std::string_view name) { return name == "KHR_materials_emissive_strength"; }
bool mappedTextureInfoExtension(std::string_view name) { return name == "KHR_texture_transform"; }

// A texture reference of one material slot, whatever its glTF struct.
struct SlotSource {
  const char* slot;  // texture and node name in the graph: "baseColor", "normal"...
  int texture = -1;
  int texCoord = 0;
  const tinygltf::ExtensionMap* extensions = nullptr;
  bool srgb = false;
  std::string pointer;  // of the textureInfo
};

// The texture coordinate set the file names for a slot: KHR_texture_transform's override, else texCoord.
int declaredSet(const SlotSource& s) {
  auto ext = s.extensions->find("KHR_texture_transform");
  if (ext != s.extensions->end() && ext->second.Has("texCoord")) return ext->second.Get("texCoord").GetNumberAsInt();
  return s.texCoord;
}

double number(const tinygltf::Value& v) { return v.IsNumber() ? v.GetNumberAsDouble() : v.IsInt() ? v.GetNumberAsInt() : 0.0; }

std::array<double, 2> pair(const tinygltf::Value& object, const char* key, std::array<double, 2> fallback) {
  if (!object.Has(key)) return fallback;
  const auto& a = object.Get(key);
  return {number(a.Get(0)), number(a.Get(1))};
}

class GraphBuilder {
 public:
  GraphBuilder(const Asset& asset, int index, const GraphNaming& naming, DiagnosticList& diags)
      : asset_(asset), index_(index), naming_(naming), diags_(diags) {}

  Json build() {
    static const tinygltf::Material kDefault;  // glTF's default material: white, metallic 1, roughness 1
    const tinygltf::Material& m = index_ >= 0 ? asset_.model.materials[index_] : kDefault;
    pointer_ = index_ >= 0 ? "/materials/" + std::to_string(index_) : "";
    graph_["name"] = naming_.name;
    graph_["description"] = description(m);
    warnUnmappedExtensions(m.extensions, mappedMaterialExtension, pointer_);
    std::string baseColor = baseColorNode(m), alpha = node("alpha", "swizzle", {{"in", baseColor}, {"channels", "a"}});
    Json output;
    output["baseColor"] = node("baseColorRgb", "swizzle", {{"in", baseColor}, {"channels", "rgb"}});
    addMetallicRoughness(m, output);
    output["specular"] = 0.5;  // F0 = 0.04, glTF's dielectric reflectance
    addNormal(m, output);
    addOcclusion(m, output);
    addEmissive(m, output);
    addAlpha(m, alpha, output);
    graph_["doubleSided"] = m.doubleSided;
    graph_["weather"] = weather();
    Json ordered;  // a stable, readable key order
    for (const char* key : {"name", "description", "parameters", "textures", "nodes", "output", "alphaMode", "alphaCutoff",
                            "doubleSided", "weather"})
      if (graph_.contains(key)) ordered[key] = graph_[key];
    ordered["output"] = output;
    return ordered;
  }

 private:
  Json weather() const {
    if (naming_.weatherPreset == "none" || naming_.snowDisplacement) return naming_.weatherPreset;
    return Json{{"preset", naming_.weatherPreset}, {"effects", {{"displacement", false}}}};
  }

  std::string description(const tinygltf::Material& m) const {
    std::string model = std::filesystem::path(asset_.file).stem().string();
    if (index_ < 0) return "glTF default material of " + model;
    return "glTF material " + std::to_string(index_) + " '" + m.name + "' of " + model;
  }

  // Adds a node and returns the link to its output.
  std::string node(const std::string& id, const char* op, Json inputs, const char* output = "out") {
    Json n;
    n["id"] = id;
    n["op"] = op;
    if (!inputs.empty()) n["inputs"] = std::move(inputs);
    graph_["nodes"].push_back(std::move(n));
    return id + "." + output;
  }

  std::string parameter(const std::string& name, Json value, const char* label, double min, double max) {
    const char* type = !value.is_array() ? "float" : value.size() == 3 ? "vec3" : "vec4";
    graph_["parameters"][name] = Json{{"type", type}, {"default", value}, {"min", min}, {"max", max}, {"label", label}};
    Json n{{"id", name}, {"op", "parameter"}, {"param", name}};
    graph_["nodes"].push_back(std::move(n));
    return name + ".out";
  }

  // Clamps a factor into [min, max], with a warning when the file had it outside; `why`
  // says whose range it is.
  Json factor(const std::vector<double>& values, const char* what, double min, double max,
              const char* why = "glTF 2.0 limits this factor to that range") {
    Json out = Json::array();
    bool clamped = false;
    for (double v : values) {
      double c = std::clamp(v, min, max);
      clamped = clamped || c != v;
      out.push_back(c);
    }
    if (clamped)
      diags_.report(DiagCode::GltfFeatureIgnored, asset_.locate(pointer_),
                    {std::string(what) + " lies outside [" + formatNumber(min) + ", " + formatNumber(max) + "]; it is clamped",
                     why});
    return values.size() == 1 ? out[0] : out;
  }

  static std::string formatNumber(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", v);
    return text;
  }

  std::string baseColorNode(const tinygltf::Material& m) {
    std::string value = parameter("baseColorFactor", factor(m.pbrMetallicRoughness.baseColorFactor, "baseColorFactor", 0, 1),
                                  "Base colour factor", 0, 1);
    const auto& t = m.pbrMetallicRoughness.baseColorTexture;
    if (auto texel = sample({"baseColor", t.index, t.texCoord, &t.extensions, true, pointer_ + "/pbrMetallicRoughness/baseColorTexture"}))
      value = node("baseColorTextured", "multiply", {{"a", value}, {"b", *texel + "rgba"}});
    std::string colour = node("vertexColor", "vertex_color", {});
    return node("baseColor", "multiply", {{"a", value}, {"b", colour}});
  }

  void addMetallicRoughness(const tinygltf::Material& m, Json& output) {
    const auto& pbr = m.pbrMetallicRoughness;
    std::string metallic = parameter("metallicFactor", factor({pbr.metallicFactor}, "metallicFactor", 0, 1), "Metallic factor", 0, 1);
    std::string roughness =
        parameter("roughnessFactor", factor({pbr.roughnessFactor}, "roughnessFactor", 0, 1), "Roughness factor", 0, 1);
    const auto& t = pbr.metallicRoughnessTexture;
    if (auto texel = sample({"metallicRoughness", t.index, t.texCoord, &t.extensions, false,
                             pointer_ + "/pbrMetallicRoughness/metallicRoughnessTexture"})) {
      metallic = node("metallic", "multiply", {{"a", metallic}, {"b", *texel + "b"}});
      roughness = node("roughness", "multiply", {{"a", roughness}, {"b", *texel + "g"}});
    }
    output["metallic"] = metallic;
    output["roughness"] = roughness;
  }

  void addNormal(const tinygltf::Material& m, Json& output) {
    const auto& t = m.normalTexture;
    auto texel = sample({"normal", t.index, t.texCoord, &t.extensions, false, pointer_ + "/normalTexture"});
    if (!texel) return;
    constexpr double kMaxScale = 16;  // normal_unpack's strength; a negative scale flips the slopes, as in glTF
    std::string scale = parameter("normalScale",
                                  factor({t.scale}, "normalTexture.scale", -kMaxScale, kMaxScale, "weathergen's normal_unpack takes scales in that range"),
                                  "Normal scale", -kMaxScale, kMaxScale);
    output["normal"] = node("normal", "normal_unpack", {{"rgb", *texel + "rgb"}, {"strength", scale}});
  }

  void addOcclusion(const tinygltf::Material& m, Json& output) {
    const auto& t = m.occlusionTexture;
    auto texel = sample({"occlusion", t.index, t.texCoord, &t.extensions, false, pointer_ + "/occlusionTexture"});
    if (!texel) return;
    std::string strength =
        parameter("occlusionStrength", factor({t.strength}, "occlusionTexture.strength", 0, 1), "Occlusion strength", 0, 1);
    output["ambientOcclusion"] = node("occlusion", "lerp", {{"a", 1.0}, {"b", *texel + "r"}, {"t", strength}});
  }

  void addEmissive(const tinygltf::Material& m, Json& output) {
    const auto& t = m.emissiveTexture;
    auto strengthExt = m.extensions.find("KHR_materials_emissive_strength");
    bool black = std::all_of(m.emissiveFactor.begin(), m.emissiveFactor.end(), [](double v) { return v == 0.0; });
    if (black && t.index < 0) return;
    std::string value = parameter("emissiveFactor", factor(m.emissiveFactor, "emissiveFactor", 0, 1), "Emissive factor", 0, 1);
    if (auto texel = sample({"emissive", t.index, t.texCoord, &t.extensions, true, pointer_ + "/emissiveTexture"}))
      value = node("emissiveTextured", "multiply", {{"a", value}, {"b", *texel + "rgb"}});
    if (strengthExt != m.extensions.end() && strengthExt->second.Has("emissiveStrength")) {
      constexpr double kMaxStrength = 1e6;
      double s = number(strengthExt->second.Get("emissiveStrength"));
      std::string strength = parameter("emissiveStrength", factor({s}, "emissiveStrength", 0, kMaxStrength), "Emissive strength", 0,
                                       kMaxStrength);
      value = node("emissive", "multiply", {{"a", value}, {"b", strength}});
    }
    output["emissive"] = value;
  }

  void addAlpha(const tinygltf::Material& m, const std::string& alpha, Json& output) {
    std::string mode = m.alphaMode == "MASK" ? "mask" : m.alphaMode == "BLEND" ? "blend" : "opaque";
    if (m.alphaMode != "OPAQUE" && m.alphaMode != "MASK" && m.alphaMode != "BLEND")
      diags_.report(DiagCode::GltfSchema, asset_.locate(pointer_ + "/alphaMode"),
                    {pointer_ + "/alphaMode", "\"OPAQUE\", \"MASK\" or \"BLEND\"", "'" + quoteUserText(m.alphaMode) + "'"});
    graph_["alphaMode"] = mode;
    if (mode == "opaque") return;
    output["opacity"] = alpha;
    if (mode == "mask")
      graph_["alphaCutoff"] = factor({m.alphaCutoff}, "alphaCutoff", 0, 1, "weathergen's alphaCutoff is in that range; above 1 only fully opaque texels remain");
  }

  // The sample node of a slot ("baseColorTexel."), or nullopt when it has no texture.
  std::optional<std::string> sample(const SlotSource& s) {
    if (s.texture < 0) return std::nullopt;
    const auto& texture = asset_.model.textures[s.texture];
    std::string texPointer = "/textures/" + std::to_string(s.texture);
    warnUnmappedExtensions(*s.extensions, mappedTextureInfoExtension, s.pointer);
    warnUnmappedExtensions(texture.extensions, [](std::string_view) { return false; }, texPointer);
    if (texture.source < 0) {
      diags_.report(DiagCode::GltfFeatureIgnored, asset_.locate(texPointer),
                    {"texture " + std::to_string(s.texture) + " has no PNG or JPEG source; the " + s.slot + " slot uses its factor alone",
                     "give the texture a 'source' image"});
      return std::nullopt;
    }
    Json declaration{{"file", naming_.imageFiles[texture.source]}, {"colorSpace", s.srgb ? "srgb" : "linear"}};
    addSampler(declaration, texture.sampler);
    graph_["textures"][s.slot] = declaration;
    std::string id = std::string(s.slot) + "Texel";
    node(id, "sample", {{"texture", s.slot}, {"uv", texCoord(s)}}, "rgba");
    return id + ".";
  }

  void addSampler(Json& declaration, int index) {
    if (index < 0) return;  // glTF: repeat, filters up to the renderer
    const auto& s = asset_.model.samplers[index];
    std::string at = "/samplers/" + std::to_string(index);
    std::string wrapU = wrapName(s.wrapS, at + "/wrapS"), wrapV = wrapName(s.wrapT, at + "/wrapT");
    declaration["wrap"] = wrapU == wrapV ? Json(wrapU) : Json::array({wrapU, wrapV});
    std::string min = filterName(s.minFilter, at + "/minFilter"), mag = filterName(s.magFilter, at + "/magFilter");
    declaration["filter"] = min == mag ? Json(min) : Json{{"min", min}, {"mag", mag}};
  }

  std::string wrapName(int value, const std::string& at) {
    if (value == kRepeat) return "repeat";
    if (value == kClampToEdge) return "clamp";
    if (value == kMirroredRepeat) return "mirror";
    diags_.report(DiagCode::GltfSchema, asset_.locate(at), {at, "10497, 33071 or 33648", std::to_string(value)});
    return "repeat";
  }

  // The base filter of a glTF filter; mip selection follows the renderer's mip chain.
  std::string filterName(int value, const std::string& at) {
    if (value == -1 || value == kLinear || value == kLinearMipmapNearest || value == kLinearMipmapLinear) return "linear";
    if (value == kNearest || value == kNearestMipmapNearest || value == kNearestMipmapLinear) return "nearest";
    diags_.report(DiagCode::GltfSchema, asset_.locate(at), {at, "a glTF filter (9728, 9729 or 9984-9987)", std::to_string(value)});
    return "linear";
  }

  // The uv a slot samples at: its texture coordinate set, through KHR_texture_transform.
  std::string texCoord(const SlotSource& s) {
    auto ext = s.extensions->find("KHR_texture_transform");
    const tinygltf::Value* transform = ext != s.extensions->end() ? &ext->second : nullptr;
    int set = declaredSet(s);
    if (set > 1) {
      diags_.report(DiagCode::GltfFeatureIgnored, asset_.locate(s.pointer),
                    {"the " + std::string(s.slot) + " texture reads texCoord " + std::to_string(set) + "; only sets 0 and 1 are read, so set 0 is used",
                     "move the texture to TEXCOORD_0 or TEXCOORD_1"});
      set = 0;
    }
    std::string uv = set == 0 ? "uv0" : "uv1";
    if (!uvNodes_[set]) node(uv, set == 0 ? "texcoord" : "texcoord1", {}), uvNodes_[set] = true;
    uv += ".out";
    if (!transform) return uv;
    return transformed(uv, *transform, s.slot);
  }

  // KHR_texture_transform: uv' = offset + R(rotation) (scale * uv). R turns uv
  // counter-clockwise in uv space as the extension's text and its sample model
  // (TextureTransformTest) mean; that is the transpose of the README's GLSL listing
  // (glTF issue 1563), and what other viewers do.
  std::string transformed(const std::string& uv, const tinygltf::Value& t, const std::string& slot) {
    auto offset = pair(t, "offset", {0, 0}), scale = pair(t, "scale", {1, 1});
    double rotation = t.Has("rotation") ? number(t.Get("rotation")) : 0.0;
    std::string p = slot + "Uv";
    std::string scaled = node(p + "Scaled", "multiply", {{"a", uv}, {"b", {scale[0], scale[1]}}});
    std::string rotated = scaled;
    if (rotation != 0.0) {
      double c = std::cos(rotation), s = std::sin(rotation);
      std::string u = node(p + "U", "dot", {{"a", scaled}, {"b", {c, s}}});
      std::string v = node(p + "V", "dot", {{"a", scaled}, {"b", {-s, c}}});
      rotated = node(p + "Rotated", "combine2", {{"x", u}, {"y", v}});
    }
    return node(p, "add", {{"a", rotated}, {"b", {offset[0], offset[1]}}});
  }

  template <typename Mapped>
  void warnUnmappedExtensions(const tinygltf::ExtensionMap& extensions, Mapped mapped, const std::string& pointer) {
    std::string who = index_ >= 0 ? std::to_string(index_) + " ('" + quoteUserText(asset_.model.materials[index_].name) + "')" : "default";
    for (const auto& [name, value] : extensions)
      if (!mapped(name))
        diags_.report(DiagCode::GltfExtensionIgnored, asset_.locate(appendPointer(pointer + "/extensions", name)),
                      {who, quoteUserText(name)});
  }

  const Asset& asset_;
  int index_;
  const GraphNaming& naming_;
  DiagnosticList& diags_;
  std::string pointer_;
  Json graph_;
  bool uvNodes_[2] = {false, false};
};

// The set a slot samples: 0 or 1, sets above 1 falling back to 0 as the graph does;
// -1 when the slot samples nothing (no texture, or a texture without an image).
int setOf(const tinygltf::Model& model, const SlotSource& s) {
  if (s.texture < 0 || model.textures[s.texture].source < 0) return -1;
  int set = declaredSet(s);
  return set > 1 ? 0 : set;
}

}  // namespace

nlohmann::ordered_json materialGraph(const Asset& asset, int index, const GraphNaming& naming, DiagnosticList& diagnostics) {
  return GraphBuilder(asset, index, naming, diagnostics).build();
}

unsigned texCoordSetsUsed(const tinygltf::Model& model, int index) {
  if (index < 0) return 0;
  const auto& m = model.materials[index];
  const auto& pbr = m.pbrMetallicRoughness;
  const SlotSource slots[] = {
      {"", pbr.baseColorTexture.index, pbr.baseColorTexture.texCoord, &pbr.baseColorTexture.extensions},
      {"", pbr.metallicRoughnessTexture.index, pbr.metallicRoughnessTexture.texCoord, &pbr.metallicRoughnessTexture.extensions},
      {"", m.normalTexture.index, m.normalTexture.texCoord, &m.normalTexture.extensions},
      {"", m.occlusionTexture.index, m.occlusionTexture.texCoord, &m.occlusionTexture.extensions},
      {"", m.emissiveTexture.index, m.emissiveTexture.texCoord, &m.emissiveTexture.extensions}};
  unsigned sets = 0;
  for (const auto& s : slots)
    if (int set = setOf(model, s); set >= 0) sets |= 1u << set;
  return sets;
}

}  // namespace wg::gltf
