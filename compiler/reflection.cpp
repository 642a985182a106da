#include "compiler/reflection.hpp"

#include <nlohmann/json.hpp>

#include "compiler/debug_views.hpp"
#include "nodes/shader_stage.hpp"
#include "nodes/texture_sampling.hpp"

namespace wg {

namespace {
using Json = nlohmann::ordered_json;

Json valueJson(const Value& v) {
  if (v.type == ValueType::Bool) return v.asBool();
  if (v.width() == 1) return v.v[0];
  Json a = Json::array();
  for (int i = 0; i < v.width(); ++i) a.push_back(v.v[i]);
  return a;
}

Json blockJson(const UniformBlock& block, const IrGraph* graph) {
  Json members = Json::array();
  for (const auto& m : block.members) {
    Json j = {{"name", m.name}, {"identifier", m.identifier}, {"type", interfaceTypeName(m.type)},
              {"offset", m.offset}, {"size", m.size}};
    if (graph && m.parameter >= 0) {
      const auto& p = graph->parameters[static_cast<std::size_t>(m.parameter)];
      j["valueType"] = typeName(p.type);
      j["default"] = valueJson(p.defaultValue);
      if (p.min) j["min"] = *p.min;
      if (p.max) j["max"] = *p.max;
      if (!p.label.empty()) j["label"] = p.label;
    }
    members.push_back(std::move(j));
  }
  return {{"name", block.name}, {"identifier", block.identifier}, {"set", block.set},
          {"binding", block.binding}, {"size", block.size}, {"members", std::move(members)}};
}

// "wrap" and "filter" appear when both axes (directions) agree, as before per-axis
// settings existed; "wrapU"/"wrapV", "minFilter"/"magFilter" and "colorSpace" always.
void addSamplerJson(Json& texture, const SamplerState& s) {
  if (s.wrapU == s.wrapV) texture["wrap"] = textureWrapName(s.wrapU);
  if (s.minFilter == s.magFilter) texture["filter"] = textureFilterName(s.magFilter);
  texture["wrapU"] = textureWrapName(s.wrapU);
  texture["wrapV"] = textureWrapName(s.wrapV);
  texture["minFilter"] = textureFilterName(s.minFilter);
  texture["magFilter"] = textureFilterName(s.magFilter);
  texture["colorSpace"] = colorSpaceName(s.colorSpace);
}

Json stageVariablesJson(const std::vector<StageVariable>& vars) {
  Json out = Json::array();
  for (const auto& v : vars)
    out.push_back({{"name", v.name}, {"identifier", v.identifier}, {"location", v.location},
                   {"type", interfaceTypeName(v.type)}});
  return out;
}
Json weatherJson(const IrGraph& graph) {
  const WeatherConfig& w = graph.weather;
  Json effects = Json::object();
  if (w.active())
    for (const auto& f : weatherEffectFlags()) effects[std::string(f.name)] = w.effects.*(f.flag);
  return {{"preset", w.preset}, {"effects", std::move(effects)}};
}

Json surfaceStructJson(const SurfaceStruct& st) {
  Json fields = Json::array();
  for (const auto& f : st.fields) fields.push_back({{"name", f.name}, {"type", f.type}});
  return fields;
}

// The host contract (docs/engine-api.md, "The surface contract"): enough to write the
// glue that calls a surface without reading its text.
Json surfaceJson(const SurfaceInterface& s, const std::string& fileStem) {
  Json files = Json::object();
  for (const auto& language : surfaceLanguages()) files[std::string(language.name)] = fileStem + "." + std::string(language.suffix);
  Json structs = Json::object();
  for (const SurfaceStruct* st : {&s.vertexInput, &s.vertexOutput, &s.fragmentInput, &s.fragmentOutput})
    structs[st->name] = surfaceStructJson(*st);
  Json resources = Json::array();
  for (const auto& r : s.resources) {
    Json resource = {{"name", r.name}, {"identifier", r.identifier}, {"kind", surfaceResourceKindName(r.kind)},
                     {"shared", r.shared}, {"set", r.set}, {"binding", r.binding}, {"setMacro", r.setMacro},
                     {"bindingMacro", r.bindingMacro}};
    if (!r.absentMacro.empty()) resource["absentMacro"] = r.absentMacro;
    if (r.kind == SurfaceResourceKind::UniformBlock) {
      const UniformBlock& block = r.shared ? surfaceWeatherBlock() : s.prefixed.material;
      Json members = Json::array();
      for (const auto& m : block.members)
        members.push_back({{"name", m.name}, {"identifier", m.identifier}, {"type", interfaceTypeName(m.type)},
                           {"offset", m.offset}});
      resource["size"] = block.size;
      resource["members"] = std::move(members);
    }
    resources.push_back(std::move(resource));
  }
  return {{"files", std::move(files)},
          {"prefix", s.prefix},
          {"vertex", {{"function", s.vertexFunction}, {"input", s.vertexInput.name}, {"output", s.vertexOutput.name}}},
          {"fragment",
           {{"function", s.fragmentFunction}, {"input", s.fragmentInput.name}, {"output", s.fragmentOutput.name}}},
          {"stageMacros", {{"vertex", kSurfaceVertexOnlyMacro}, {"fragment", kSurfaceFragmentOnlyMacro}}},
          {"hostResourcesMacro", kSurfaceHostResourcesMacro},
          {"structs", std::move(structs)},
          {"resources", std::move(resources)}};
}

}  // namespace

std::string buildReflectionJson(const IrGraph& graph, const MaterialInterface& mi, const SurfaceInterface& surface,
                                const std::string& hash, const std::string& fileStem) {
  Json textures = Json::array();
  for (const auto& b : mi.textures) {
    const TextureDecl& t = graph.textures[static_cast<std::size_t>(b.texture)];
    Json source;
    if (!t.file.empty()) {
      source = {{"kind", "file"}, {"file", t.file}};
    } else {
      source = {{"kind", "procedural"}, {"generator", t.generator}, {"seed", t.seed}, {"size", t.size},
                {"options", Json::parse(t.options.dump())}};
    }
    Json texture = {{"name", b.name}, {"set", b.set}, {"binding", b.textureBinding},
                    {"samplerBinding", b.samplerBinding}, {"textureIdentifier", b.textureIdentifier},
                    {"samplerIdentifier", b.samplerIdentifier}};
    addSamplerJson(texture, t.sampler);
    texture["source"] = std::move(source);
    textures.push_back(std::move(texture));
  }
  Json weatherMaps = Json::array();
  for (const auto& m : mi.weatherMaps)
    weatherMaps.push_back({{"name", m.name}, {"set", m.set}, {"binding", m.textureBinding},
                           {"samplerBinding", m.samplerBinding}, {"textureIdentifier", m.textureIdentifier},
                           {"samplerIdentifier", m.samplerIdentifier}});
  Json debugViews = Json::array();
  for (const auto& view : kDebugViews) debugViews.push_back({{"id", view.id}, {"name", view.name}});
  Json files = Json::object();
  for (ShaderLanguage language : {ShaderLanguage::Glsl, ShaderLanguage::Hlsl})
    for (ShaderStage stage : {ShaderStage::Vertex, ShaderStage::Fragment}) {
      std::string lang(languageName(language));
      std::string st = stage == ShaderStage::Vertex ? "vert" : "frag";
      files[lang + "." + st] = {{"source", fileStem + "." + st + "." + lang},
                                {"spirv", fileStem + "." + lang + "." + st + ".spv"}};
    }
  Json root = {
      {"weathergenVersion", WEATHERGEN_VERSION},
      {"material", graph.name},
      {"contentHash", hash},
      {"weather", weatherJson(graph)},
      {"alphaMode", alphaModeName(graph.alphaMode)},
      {"alphaTested", graph.alphaTested()},
      {"alphaCutoff", graph.alphaCutoff},
      {"doubleSided", graph.doubleSided},
      {"blocks", Json::array({blockJson(*mi.frame, nullptr), blockJson(mi.material, &graph)})},
      {"textures", std::move(textures)},
      {"vertexInputs", stageVariablesJson(mi.vertexInputs)},
      {"varyings", stageVariablesJson(mi.varyings)},
      {"fragmentOutputs", Json::array({{{"name", "color"}, {"location", 0}, {"type", "vec4"}}})},
      {"weatherMaps", std::move(weatherMaps)},
      {"debugViews", std::move(debugViews)},
      {"files", std::move(files)},
      {"surface", surfaceJson(surface, fileStem)},
  };
  return root.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
}

}  // namespace wg
