#include "compiler/reflection.hpp"

#include "compiler/debug_views.hpp"
#include "compiler/indented_json_writer.hpp"
#include "nodes/shader_stage.hpp"
#include "nodes/texture_sampling.hpp"

namespace wg {

namespace {

// An array with one object per item, whose members `writeMembers` writes.
template <typename Items, typename WriteMembers>
void writeObjectArray(IndentedJsonWriter& w, const Items& items, WriteMembers writeMembers) {
  w.beginArray();
  for (const auto& item : items) {
    w.beginObject();
    writeMembers(item);
    w.endObject();
  }
  w.endArray();
}

void writeValue(IndentedJsonWriter& w, const Value& v) {
  if (v.type == ValueType::Bool) return w.boolean(v.asBool());
  if (v.width() == 1) return w.number(v.v[0]);
  w.beginArray();
  for (int i = 0; i < v.width(); ++i) w.number(v.v[i]);
  w.endArray();
}

void writeParameter(IndentedJsonWriter& w, const ParameterDecl& p) {
  w.key("valueType").text(typeName(p.type));
  writeValue(w.key("default"), p.defaultValue);
  if (p.min) w.key("min").number(*p.min);
  if (p.max) w.key("max").number(*p.max);
  if (!p.label.empty()) w.key("label").text(p.label);
}

void writeBlock(IndentedJsonWriter& w, const UniformBlock& block, const IrGraph* graph) {
  w.beginObject();
  w.key("name").text(block.name);
  w.key("identifier").text(block.identifier);
  w.key("set").integer(block.set);
  w.key("binding").integer(block.binding);
  w.key("size").integer(block.size);
  w.key("members").beginArray();
  for (const auto& m : block.members) {
    w.beginObject();
    w.key("name").text(m.name);
    w.key("identifier").text(m.identifier);
    w.key("type").text(interfaceTypeName(m.type));
    w.key("offset").integer(m.offset);
    w.key("size").integer(m.size);
    if (graph && m.parameter >= 0) writeParameter(w, graph->parameters[static_cast<std::size_t>(m.parameter)]);
    w.endObject();
  }
  w.endArray();
  w.endObject();
}

// "wrap" and "filter" appear when both axes (directions) agree, as before per-axis
// settings existed; "wrapU"/"wrapV", "minFilter"/"magFilter" and "colorSpace" always.
void writeSampler(IndentedJsonWriter& w, const SamplerState& s) {
  if (s.wrapU == s.wrapV) w.key("wrap").text(textureWrapName(s.wrapU));
  if (s.minFilter == s.magFilter) w.key("filter").text(textureFilterName(s.magFilter));
  w.key("wrapU").text(textureWrapName(s.wrapU));
  w.key("wrapV").text(textureWrapName(s.wrapV));
  w.key("minFilter").text(textureFilterName(s.minFilter));
  w.key("magFilter").text(textureFilterName(s.magFilter));
  w.key("colorSpace").text(colorSpaceName(s.colorSpace));
}

void writeStageVariables(IndentedJsonWriter& w, const std::vector<StageVariable>& vars) {
  writeObjectArray(w, vars, [&](const StageVariable& v) {
    w.key("name").text(v.name);
    w.key("identifier").text(v.identifier);
    w.key("location").integer(v.location);
    w.key("type").text(interfaceTypeName(v.type));
  });
}

void writeWeather(IndentedJsonWriter& w, const IrGraph& graph) {
  const WeatherConfig& weather = graph.weather;
  w.beginObject();
  w.key("preset").text(weather.preset);
  if (weather.active() && weather.steep) {
    w.key("steep").beginObject();
    w.key("preset").text(weather.steep->preset);
    w.key("slope").beginArray();
    w.number(weather.steep->fromDegrees);
    w.number(weather.steep->toDegrees);
    w.endArray();
    w.endObject();
  }
  w.key("effects").beginObject();
  if (weather.active())
    for (const auto& f : weatherEffectFlags()) w.key(f.name).boolean(weather.effects.*(f.flag));
  w.endObject();
  w.endObject();
}

void writeTextureSource(IndentedJsonWriter& w, const TextureDecl& t) {
  w.beginObject();
  if (!t.file.empty()) {
    w.key("kind").text("file");
    w.key("file").text(t.file);
  } else {
    w.key("kind").text("procedural");
    w.key("generator").text(t.generator);
    w.key("seed").integer(t.seed);
    w.key("size").integer(t.size);
    w.key("options").json(t.options);
  }
  w.endObject();
}

// Where a texture and its sampler are bound, for material textures and weather maps alike.
void writeBinding(IndentedJsonWriter& w, const TextureBinding& b) {
  w.key("name").text(b.name);
  w.key("set").integer(b.set);
  w.key("binding").integer(b.textureBinding);
  w.key("samplerBinding").integer(b.samplerBinding);
  w.key("dimension").text(b.cube ? "cube" : "2d");
  w.key("textureIdentifier").text(b.textureIdentifier);
  w.key("samplerIdentifier").text(b.samplerIdentifier);
}

void writeTextures(IndentedJsonWriter& w, const IrGraph& graph, const MaterialInterface& mi) {
  writeObjectArray(w, mi.textures, [&](const auto& b) {
    const TextureDecl& t = graph.textures[static_cast<std::size_t>(b.texture)];
    writeBinding(w, b);
    writeSampler(w, t.sampler);
    writeTextureSource(w.key("source"), t);
  });
}

void writeWeatherMaps(IndentedJsonWriter& w, const MaterialInterface& mi) {
  writeObjectArray(w, mi.weatherMaps, [&](const auto& m) { writeBinding(w, m); });
}

void writeDebugViews(IndentedJsonWriter& w) {
  writeObjectArray(w, kDebugViews, [&](const auto& view) {
    w.key("id").integer(view.id);
    w.key("name").text(view.name);
  });
}

void writeFiles(IndentedJsonWriter& w, const std::string& fileStem) {
  w.beginObject();
  for (ShaderLanguage language : {ShaderLanguage::Glsl, ShaderLanguage::Hlsl})
    for (ShaderStage stage : {ShaderStage::Vertex, ShaderStage::Fragment}) {
      std::string lang(languageName(language));
      std::string st = stage == ShaderStage::Vertex ? "vert" : "frag";
      w.key(lang + "." + st).beginObject();
      w.key("source").text(fileStem + "." + st + "." + lang);
      w.key("spirv").text(fileStem + "." + lang + "." + st + ".spv");
      w.endObject();
    }
  w.endObject();
}

void writeSurfaceStruct(IndentedJsonWriter& w, const SurfaceStruct& st) {
  writeObjectArray(w, st.fields, [&](const auto& f) {
    w.key("name").text(f.name);
    w.key("type").text(f.type);
  });
}

void writeSurfaceResource(IndentedJsonWriter& w, const SurfaceInterface& s, const SurfaceResource& r) {
  w.beginObject();
  w.key("name").text(r.name);
  w.key("identifier").text(r.identifier);
  w.key("kind").text(surfaceResourceKindName(r.kind));
  w.key("shared").boolean(r.shared);
  w.key("set").integer(r.set);
  w.key("binding").integer(r.binding);
  w.key("setMacro").text(r.setMacro);
  w.key("bindingMacro").text(r.bindingMacro);
  if (!r.absentMacro.empty()) w.key("absentMacro").text(r.absentMacro);
  if (r.kind == SurfaceResourceKind::UniformBlock) {
    const UniformBlock& block = r.shared ? surfaceWeatherBlock() : s.prefixed.material;
    w.key("size").integer(block.size);
    w.key("members").beginArray();
    for (const auto& m : block.members) {
      w.beginObject();
      w.key("name").text(m.name);
      w.key("identifier").text(m.identifier);
      w.key("type").text(interfaceTypeName(m.type));
      w.key("offset").integer(m.offset);
      w.endObject();
    }
    w.endArray();
  }
  w.endObject();
}

// One entry point of the surface: its function and structs' names.
void writeSurfaceFunction(IndentedJsonWriter& w, const std::string& function, const SurfaceStruct& input,
                          const SurfaceStruct& output) {
  w.beginObject();
  w.key("function").text(function);
  w.key("input").text(input.name);
  w.key("output").text(output.name);
  w.endObject();
}

// The host contract (docs/engine-api.md, "The surface contract"): enough to write the
// glue that calls a surface without reading its text.
void writeSurface(IndentedJsonWriter& w, const SurfaceInterface& s, const std::string& fileStem) {
  w.beginObject();
  w.key("files").beginObject();
  for (const auto& language : surfaceLanguages())
    w.key(language.name).text(fileStem + "." + std::string(language.suffix));
  w.endObject();
  w.key("prefix").text(s.prefix);
  writeSurfaceFunction(w.key("vertex"), s.vertexFunction, s.vertexInput, s.vertexOutput);
  writeSurfaceFunction(w.key("fragment"), s.fragmentFunction, s.fragmentInput, s.fragmentOutput);
  w.key("stageMacros").beginObject();
  w.key("vertex").text(kSurfaceVertexOnlyMacro);
  w.key("fragment").text(kSurfaceFragmentOnlyMacro);
  w.endObject();
  w.key("hostResourcesMacro").text(kSurfaceHostResourcesMacro);
  w.key("structs").beginObject();
  for (const SurfaceStruct* st : {&s.vertexInput, &s.vertexOutput, &s.fragmentInput, &s.fragmentOutput})
    writeSurfaceStruct(w.key(st->name), *st);
  w.endObject();
  w.key("resources").beginArray();
  for (const auto& r : s.resources) writeSurfaceResource(w, s, r);
  w.endArray();
  w.endObject();
}

}  // namespace

std::string buildReflectionJson(const IrGraph& graph, const MaterialInterface& mi, const SurfaceInterface& surface,
                                const std::string& hash, const std::string& fileStem) {
  IndentedJsonWriter w;
  w.beginObject();
  w.key("weathergenVersion").text(WEATHERGEN_VERSION);
  w.key("material").text(graph.name);
  w.key("contentHash").text(hash);
  writeWeather(w.key("weather"), graph);
  w.key("alphaMode").text(alphaModeName(graph.alphaMode));
  w.key("alphaTested").boolean(graph.alphaTested());
  w.key("alphaCutoff").number(graph.alphaCutoff);
  w.key("doubleSided").boolean(graph.doubleSided);
  w.key("blocks").beginArray();
  writeBlock(w, *mi.frame, nullptr);
  writeBlock(w, mi.material, &graph);
  w.endArray();
  writeTextures(w.key("textures"), graph, mi);
  writeStageVariables(w.key("vertexInputs"), mi.vertexInputs);
  writeStageVariables(w.key("varyings"), mi.varyings);
  w.key("fragmentOutputs").beginArray();
  w.beginObject();
  w.key("name").text("color");
  w.key("location").integer(0);
  w.key("type").text("vec4");
  w.endObject();
  w.endArray();
  writeWeatherMaps(w.key("weatherMaps"), mi);
  writeDebugViews(w.key("debugViews"));
  writeFiles(w.key("files"), fileStem);
  writeSurface(w.key("surface"), surface, fileStem);
  w.endObject();
  return w.finish();
}

}  // namespace wg
