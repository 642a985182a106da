// weather-inject: inserts the weather subgraph between the material's PBR attributes
// and the output (seed 000: weather functions run after the original shader). The base
// graph is left as it is; only the output bindings move to the weathered values. With
// preset "none" the pass does nothing, so the shader is exactly the unweathered one.
#include <algorithm>
#include <cmath>
#include <iterator>
#include <optional>

#include "compiler/ir_node_builder.hpp"
#include "compiler/pass_pipeline.hpp"
#include "compiler/material_interface.hpp"
#include "nodes/frame_fields.hpp"
#include "nodes/weather_levels.hpp"
#include "nodes/weather_model.hpp"

namespace wg {

namespace {

// Parameters the pass publishes (material block), sorted in with the user's.
struct WeatherParameter {
  std::string_view name;
  std::string_view label;
  float WeatherConfig::*field;  // default from the config, or null for a weight
  int weight;                   // 0-3 for w1-w4, else -1
  float min, max;
};
constexpr std::array<WeatherParameter, 7> kParameters = {{
    {"weather.w1", "Snow weight w1 (sun, eq. 3.1)", nullptr, 0, 0.f, 16.f},
    {"weather.w2", "Snow weight w2 (wind, eq. 3.1)", nullptr, 1, 0.f, 16.f},
    {"weather.w3", "Snow weight w3 (height, eq. 3.1)", nullptr, 2, 0.f, 16.f},
    {"weather.w4", "Snow weight w4 (terrain, eq. 3.1)", nullptr, 3, 0.f, 16.f},
    {"weather.maxSnowHeight", "Max snow height (m, eq. 3.10)", &WeatherConfig::maxSnowHeight, -1, 0.f, 10.f},
    {"weather.minHeight", "Snow line low (m, eq. 3.8)", &WeatherConfig::minHeight, -1, -1e5f, 1e5f},
    {"weather.maxHeight", "Snow line high (m, eq. 3.8)", &WeatherConfig::maxHeight, -1, -1e5f, 1e5f},
}};

// Adds the weather parameters, keeps the list sorted by name (identifiers and
// offsets depend on that order) and renumbers existing parameter nodes.
std::vector<int> addParameters(IrGraph& g) {
  std::vector<ParameterDecl> all = g.parameters;
  for (const auto& p : kParameters) {
    float value = p.weight >= 0 ? g.weather.weights[static_cast<std::size_t>(p.weight)] : g.weather.*(p.field);
    all.push_back({std::string(p.name), ValueType::Float, Value::scalar(value), p.min, p.max, std::string(p.label), ""});
  }
  std::vector<std::size_t> order(all.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return all[a].name < all[b].name; });
  std::vector<int> newIndex(all.size());
  std::vector<ParameterDecl> sorted;
  for (std::size_t i = 0; i < order.size(); ++i) {
    newIndex[order[i]] = static_cast<int>(i);
    sorted.push_back(all[order[i]]);
  }
  for (auto& node : g.nodes)
    if (node.parameter >= 0) node.parameter = newIndex[static_cast<std::size_t>(node.parameter)];
  g.parameters = std::move(sorted);
  std::vector<int> weatherIndex;
  for (std::size_t i = 0; i < kParameters.size(); ++i) weatherIndex.push_back(newIndex[g.parameters.size() - kParameters.size() + i]);
  return weatherIndex;
}

class WeatherInjector {
 public:
  explicit WeatherInjector(IrGraph& g) : g_(g), b_(g, /*weatherNodes=*/true), cfg_(g.weather) {}

  void run() {
    const WeatherEffects& e = cfg_.effects;
    std::vector<int> params = addParameters(g_);
    for (std::size_t i = 0; i < params.size(); ++i) paramNodes_.push_back(b_.parameter(params[i]));

    position_ = b_.add("world_position", {});
    normal_ = b_.add("world_normal", {});
    exposure_ = e.skyExposure ? b_.add("sky_exposure", {{"position", position_}}) : IrNodeBuilder::constant(1.f);
    diffuse_ = g_.output(PbrField::BaseColor);

    color_ = g_.output(PbrField::BaseColor);
    roughness_ = g_.output(PbrField::Roughness);
    specular_ = g_.output(PbrField::Specular);
    metallic_ = g_.output(PbrField::Metallic);
    tangentNormal_ = g_.output(PbrField::Normal);
    emissive_ = g_.output(PbrField::Emissive);
    weights_ = b_.add("combine4", {{"x", paramNodes_[0]}, {"y", paramNodes_[1]}, {"z", paramNodes_[2]}, {"w", paramNodes_[3]}});
    shape_ = b_.add("combine4", {{"x", paramNodes_[5]}, {"y", paramNodes_[6]}, {"z", IrNodeBuilder::constant(cfg_.inclinationIntensity)}});
    terms_ = predictionTerms();

    // Order of the layers: moss grows on the rock, snow lies on top, rain wets both,
    // water pools in puddles, and frost or ice forms last.
    if (e.moss) addMoss();
    if (e.snow) addSnow();
    if (e.wetness) addWetness();
    if (e.puddles) addPuddles();
    if (e.ice) addIce();
    if (e.hoarfrost) addHoarfrost();
    if (e.foliageDensity) addFoliageDensity();

    g_.output(PbrField::BaseColor) = color_;
    g_.output(PbrField::Roughness) = roughness_;
    g_.output(PbrField::Specular) = specular_;
    g_.output(PbrField::Metallic) = metallic_;
    g_.output(PbrField::Normal) = tangentNormal_;
    g_.output(PbrField::Emissive) = emissive_;
  }

 private:
  Operand lerp(const Operand& a, const Operand& b, const Operand& t) {
    return b_.add("lerp", {{"a", a}, {"b", b}, {"t", t}});
  }
  static Operand k(float x) { return IrNodeBuilder::constant(x); }
  // A constant black emission needs no covering (most materials have none).
  static bool isBlack(const Operand& o) {
    return o.kind == Operand::Kind::Constant && o.constant.v[0] == 0.f && o.constant.v[1] == 0.f && o.constant.v[2] == 0.f;
  }
  static Operand flatNormal() { return IrNodeBuilder::constant(Value::vec3(0.f, 0.f, 1.f)); }

  // Covers the surface with a layer: albedo, roughness and specular move to the
  // layer's, metals become dielectric, and the normal map flattens under it. An opaque
  // layer (snow, moss, ice, frost) hides the emission under it; water does not.
  void cover(const Operand& coverage, const Operand& albedo, float roughness, float specular, float normalFlattening) {
    cover(coverage, albedo, k(roughness), k(specular), normalFlattening);
  }
  // The normal moves towards the layer's own (flat unless given) by normalFlattening.
  void cover(const Operand& coverage, const Operand& albedo, const Operand& roughness, const Operand& specular,
             float normalFlattening, const Operand& layerNormal = flatNormal(), bool opaque = true) {
    color_ = lerp(color_, albedo, coverage);
    roughness_ = lerp(roughness_, roughness, coverage);
    specular_ = lerp(specular_, specular, coverage);
    metallic_ = lerp(metallic_, k(0.f), coverage);
    if (opaque && !isBlack(emissive_)) emissive_ = lerp(emissive_, IrNodeBuilder::constant(Value::vec3(0.f, 0.f, 0.f)), coverage);
    if (normalFlattening > 0.f)
      tangentNormal_ = lerp(tangentNormal_, layerNormal, b_.add("multiply", {{"a", coverage}, {"b", k(normalFlattening)}}));
  }

  // The shared noise lookup at the point (nodes/weather_noise.hpp), made once: snow,
  // moss, ice and hoarfrost read its transition channel (eq. 3.14 shares one NoiseMap),
  // puddles its puddle channel, melting snow its flow channel (the thaw patches).
  Operand noise(std::string_view channel) {
    if (!noise_) noise_ = b_.add("weather_noise", {{"position", position_}});
    return b_.output(*noise_, channel);
  }

  // A layer's own normal: the transition noise as a height field of `amplitude` metres,
  // or flat with the relief effect off.
  Operand relief(float amplitude) {
    if (!cfg_.effects.relief) return flatNormal();
    return b_.add("weather_noise_relief", {{"position", position_}, {"height", noise("transition")}, {"amplitude", k(amplitude)}});
  }

  // Eq. 3.6's flow where the wind term is on (the vertex-rate pass moves it per vertex);
  // with the term off it is never read.
  Operand windFlow() {
    const bool steepWind = cfg_.steep && cfg_.steep->terms[3] > 0.5f;
    if (cfg_.terms[3] <= 0.5f && !steepWind) return k(0.f);
    if (!windFlow_) windFlow_ = b_.add("weather_wind_flow", {{"position", position_}});
    return *windFlow_;
  }

  static Operand termsConstant(const std::array<float, 4>& t) { return IrNodeBuilder::constant(Value::vec4(t[0], t[1], t[2], t[3])); }

  // How steep the point is for the slope blend: 0 below its first angle, 1 above its
  // second, by the geometric normal's up component.
  Operand steepness() {
    if (!steepness_) {
      const SteepBlend& blend = *cfg_.steep;
      const float degrees = 3.14159265f / 180.f;
      Operand up = b_.output(b_.add("split", {{"in", normal_}}), "y");
      Operand flat = b_.add("smoothstep", {{"edge0", k(std::cos(blend.toDegrees * degrees))},
                                          {"edge1", k(std::cos(blend.fromDegrees * degrees))}, {"x", up}});
      steepness_ = b_.add("one_minus", {{"in", flat}});
    }
    return *steepness_;
  }

  // Eq. 3.1's term switches: the preset's, or with a slope blend the flat preset's
  // moving to the steep one's.
  Operand predictionTerms() {
    if (!cfg_.steep) return termsConstant(cfg_.terms);
    return lerp(termsConstant(cfg_.terms), termsConstant(cfg_.steep->terms), steepness());
  }

  // How much of an effect a point has under a slope blend: all of it where both
  // presets have it, else it fades in towards the side whose preset has it (moss).
  std::optional<Operand> slopeFade(bool WeatherEffects::*effect) {
    if (!cfg_.steep) return std::nullopt;
    const bool flat = weatherPreset(cfg_.preset)->effects.*effect, steep = weatherPreset(cfg_.steep->preset)->effects.*effect;
    if (flat == steep) return std::nullopt;
    return steep ? steepness() : b_.add("one_minus", {{"in", steepness()}});
  }
  Operand faded(bool WeatherEffects::*effect, Operand value) {
    if (auto fade = slopeFade(effect)) return b_.add("multiply", {{"a", value}, {"b", *fade}});
    return value;
  }

  Operand terrainTerm() {
    // Eq. 3.11-3.13: slope of the shared height map under the object.
    Operand uv = b_.add("terrain_coord", {{"position", position_}});
    Operand h0 = b_.add("terrain_height", {{"uv", uv}});
    Operand hu = b_.add("terrain_height", {{"uv", b_.add("add", {{"a", uv}, {"b", IrNodeBuilder::constant(Value::vec2(0.05f, 0.f))}})}});
    Operand hv = b_.add("terrain_height", {{"uv", b_.add("add", {{"a", uv}, {"b", IrNodeBuilder::constant(Value::vec2(0.f, 0.05f))}})}});
    Operand slope = b_.add("weather_terrain_slope",
                           {{"h0", h0}, {"hShiftU", hu}, {"hShiftV", hv}, {"intensity", k(cfg_.terrainSlopeIntensity)}});
    Operand tangentZ = b_.output(b_.add("split", {{"in", g_.output(PbrField::Normal)}}), "z");
    return b_.add("weather_terrain_orientation", {{"slope", slope}, {"normal", normal_}, {"tangentNormalZ", tangentZ},
                                                  {"intensity", k(cfg_.terrainIntensity)}});
  }

  void addSnow() {
    Operand detailNormal = b_.add("tangent_to_world", {{"normal", g_.output(PbrField::Normal)}});
    Operand terrain = cfg_.effects.terrainOrientation ? terrainTerm() : k(0.f);
    Operand coverage = b_.add("weather_snow_coverage", {{"normal", normal_}, {"detailNormal", detailNormal},
                                                        {"position", position_}, {"diffuse", diffuse_}, {"terrain", terrain},
                                                        {"windFlow", windFlow()}, {"exposure", exposure_},
                                                        {"weights", weights_}, {"shape", shape_}, {"terms", terms_},
                                                        {"noise", noise("transition")}, {"patchNoise", noise("flow")},
                                                        {"antiAliasing", k(cfg_.effects.specularAntiAliasing ? 1.f : 0.f)}});
    // Snow's own lit micro-relief replaces the surface's detail under it.
    Operand layerNormal = relief(weather::kSnowReliefAmplitude);
    cover(coverage, b_.add("weather_snow_albedo", {{"diffuse", diffuse_}}), k(weather::kSnowRoughness), k(0.5f), 0.7f, layerNormal);
    g_.coverage(CoverageTerm::Snow) = coverage;
    if (cfg_.effects.displacement) {
      Operand offset = b_.add("weather_snow_offset", {{"normal", normal_}, {"position", position_}, {"windFlow", windFlow()},
                                                      {"exposure", exposure_}, {"weights", weights_}, {"shape", shape_},
                                                      {"terms", terms_},
                                                      {"maxSnowHeight", paramNodes_[4]}, {"noise", noise("transition")}});
      g_.output(PbrField::WorldPositionOffset) =
          b_.add("add", {{"a", g_.output(PbrField::WorldPositionOffset)}, {"b", offset}});
    }
  }

  void addMoss() {
    Operand coverage = b_.add("weather_moss_coverage", {{"normal", normal_}, {"position", position_}, {"diffuse", diffuse_},
                                                        {"weights", weights_}, {"shape", shape_},
                                                        {"noise", noise("transition")}});
    coverage = faded(&WeatherEffects::moss, coverage);
    cover(coverage, b_.add("weather_moss_albedo", {{"diffuse", diffuse_}}), weather::kMossRoughness, 0.5f, 0.f);
    g_.coverage(CoverageTerm::Moss) = coverage;
  }

  // Eq. 3.20's frost map: 0 on the banks, 1 mid-stream, from the river's v coordinate.
  Operand frostMap() {
    Operand v = b_.output(b_.add("split", {{"in", b_.add("texcoord", {})}}), "y");
    Operand across = b_.add("abs", {{"in", b_.add("subtract", {{"a", b_.add("multiply", {{"a", v}, {"b", k(2.f)}})}, {"b", k(1.f)}})}});
    return b_.add("one_minus", {{"in", across}});
  }

  void addWetness() {
    Operand p = b_.add("weather_wetness", {{"exposure", exposure_}});
    // Section 5.1.2: wetness applies to every object; on a water surface (the river) only
    // its banks get wet, the water itself stays water.
    if (cfg_.effects.ice)
      p = b_.add("multiply", {{"a", p}, {"b", b_.add("one_minus", {{"in", b_.add("smoothstep", {{"edge0", k(0.f)}, {"edge1", k(kWetBank)}, {"x", frostMap()}})}})}});
    color_ = b_.add("weather_wet_diffuse", {{"diffuse", color_}, {"p", p}, {"metallic", metallic_}});
    roughness_ = b_.add("weather_wet_roughness", {{"roughness", roughness_}, {"p", p}, {"metallic", metallic_}});
    if (cfg_.effects.specularAntiAliasing)
      roughness_ = b_.add("weather_specular_aa", {{"roughness", roughness_}, {"normal", tangentNormal_}});
    if (cfg_.effects.ripple)
      tangentNormal_ = b_.add("weather_wet_normal", {{"normal", tangentNormal_}, {"position", position_}, {"p", p}});
    g_.coverage(CoverageTerm::Wet) = p;
  }

  void addPuddles() {
    // Flooded: water's F0 0.02 and a near-mirror surface over a darkened base.
    Operand coverage = b_.add("weather_puddle_coverage", {{"normal", normal_}, {"noise", noise("puddle")}, {"exposure", exposure_}});
    Operand darkened = b_.add("multiply", {{"a", color_}, {"b", k(kPuddleDarkening)}});
    // Below 0 C the puddle is ice: ice's albedo (Table 4.1), roughness and F0.
    Operand frozen = b_.add("weather_puddle_ice", {});
    Operand albedo = lerp(darkened, b_.add("weather_ice_albedo", {{"diffuse", diffuse_}}), frozen);
    cover(coverage, albedo, lerp(k(weather::kPuddleRoughness), k(weather::kIceRoughness), frozen),
          lerp(k(weather::kWaterSpecular), k(weather::kIceSpecular), frozen), 1.f, flatNormal(), /*opaque=*/false);
    g_.coverage(CoverageTerm::Puddle) = coverage;
    if (!cfg_.effects.ice) g_.coverage(CoverageTerm::Ice) = b_.add("multiply", {{"a", coverage}, {"b", frozen}});
  }

  void addIce() {
    Operand coverage = b_.add("weather_frost_coverage", {{"frostMap", frostMap()}, {"noise", noise("transition")}});
    // Ice keeps the frozen surface's bends (its normal map) as cracks and bubbles, and 40 %
    // of its relief; the rest is ice's own slight undulation.
    Operand albedo = b_.add("weather_ice_albedo", {{"diffuse", diffuse_}, {"normal", tangentNormal_}});
    Operand layerNormal = relief(weather::kIceReliefAmplitude);
    cover(coverage, albedo, k(weather::kIceRoughness), k(weather::kIceSpecular), kIceFlattening, layerNormal);
    g_.coverage(CoverageTerm::Frost) = coverage;
    g_.coverage(CoverageTerm::Ice) = coverage;
  }

  void addHoarfrost() {
    Operand coverage = b_.add("weather_hoarfrost_coverage", {{"noise", noise("transition")}, {"exposure", exposure_}});
    Operand partial = b_.add("multiply", {{"a", coverage}, {"b", k(kHoarfrostOpacity)}});
    cover(partial, b_.add("weather_snow_albedo", {{"diffuse", diffuse_}}), weather::kFrostRoughness, 0.5f, 0.f);
    g_.coverage(CoverageTerm::Frost) = coverage;
  }

  void addFoliageDensity() {
    // Section 5.1.1: foliage density falls as snow rises; alpha testing thins the cards.
    Operand snow = b_.output(b_.add("weather_levels", {}), "snow");
    Operand sheltered = b_.add("multiply", {{"a", snow}, {"b", exposure_}});
    Operand density = b_.add("saturate", {{"in", b_.add("subtract", {{"a", k(1.f)}, {"b", b_.add("multiply", {{"a", sheltered}, {"b", k(cfg_.foliageThinning)}})}})}});
    g_.output(PbrField::Opacity) = b_.add("multiply", {{"a", g_.output(PbrField::Opacity)}, {"b", density}});
    if (!g_.alphaModeDeclared) g_.alphaMode = AlphaMode::Mask;  // a declared mode (blend) stays
    g_.coverage(CoverageTerm::Density) = density;
  }

  // Puddle water darkens what it floods (Lagarde: porous surfaces under water).
  static constexpr float kPuddleDarkening = 0.55f;
  // How far ice's normal moves from the frozen surface's towards its own relief.
  static constexpr float kIceFlattening = 0.6f;
  // Hoarfrost is a thin, partial crystal layer, never full snow cover.
  static constexpr float kHoarfrostOpacity = 0.6f;
  // On a water surface, the outer tenth of the frost map on each side (F < 0.2, 1 m of a
  // 10 m river) is bank that gets wet; the rest is water.
  static constexpr float kWetBank = 0.2f;

  IrGraph& g_;
  IrNodeBuilder b_;
  const WeatherConfig& cfg_;
  std::vector<Operand> paramNodes_;
  Operand position_, normal_, exposure_, diffuse_, color_, roughness_, specular_, metallic_, tangentNormal_, emissive_;
  Operand weights_, shape_, terms_;
  std::optional<Operand> steepness_;
  std::optional<Operand> noise_, windFlow_;
};

// Every weather level's uniform: while all are 0 the weather nodes leave the material as it was.
const std::vector<std::string>& weatherLevelUniforms() {
  static const std::vector<std::string> kUniforms = [] {
    std::vector<std::string> uniforms;
    for (const WeatherLevel& level : kWeatherLevels) uniforms.push_back(frameMemberIdentifier(*findFrameField(level.frameField)));
    return uniforms;
  }();
  return kUniforms;
}

}  // namespace

void injectWeather(IrGraph& graph) {
  if (!graph.weather.active()) return;
  graph.unweathered = graph.outputs;
  graph.weatherGuard.assign(weatherLevelUniforms().begin(), weatherLevelUniforms().end());
  WeatherInjector(graph).run();
}

}  // namespace wg
