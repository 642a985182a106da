// A host we did not design for: Google's Filament (Debian 12's 1.9.25) lighting a
// weathergen surface (docs/engine-api.md, "The surface contract").
//
//   filament-host --eval-weather none|snow|rain
//       prints that weather state as weathergen eval's --weather argument;
//   filament-host MODEL.glb OUT.png [--size WxH]
//       renders the model with gltfio's own materials (the reference);
//   filament-host MODEL.glb OUT.png --material NAME.filamat --reflection NAME.reflect.json
//                 --textures DIR [--weather none|snow|rain] [--size WxH]
//       renders the same geometry with weathergen's material (compile --target filament,
//       then matc) on every primitive, its parameters filled from the reflection alone.
//
// Filament lights both the same way: one sun, constant ambient light from spherical
// harmonics, exposure 1, no post-processing (the PNG is the linear frame, sRGB-encoded).
// Needs an X display (xvfb-run): Debian's OpenGL backend is GLX only.
// Before Filament's headers, whose macros would otherwise rewrite nlohmann's.
#include <nlohmann/json.hpp>

#include <filament/Camera.h>
#include <filament/Engine.h>
#include <filament/IndirectLight.h>
#include <filament/LightManager.h>
#include <filament/Material.h>
#include <filament/MaterialInstance.h>
#include <filament/RenderableManager.h>
#include <filament/Renderer.h>
#include <filament/Scene.h>
#include <filament/SwapChain.h>
#include <filament/Texture.h>
#include <filament/TextureSampler.h>
#include <filament/TransformManager.h>
#include <filament/View.h>
#include <filament/Viewport.h>
#include <gltfio/AssetLoader.h>
#include <gltfio/FilamentAsset.h>
#include <gltfio/MaterialProvider.h>
#include <gltfio/ResourceLoader.h>
#include <math/mat4.h>
#include <utils/EntityManager.h>

#include <stb/stb_image.h>        // implementations live in Debian's libstb.so
#include <stb/stb_image_write.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include <weathergen/weathergen.hpp>

using namespace filament;
using namespace filament::math;
using Json = nlohmann::json;

namespace {

std::vector<std::uint8_t> readFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read " + path);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

struct Options {
  std::string model, output, material, reflection, textures, weather = "none";
  std::uint32_t width = 480, height = 360;
};

Options parse(int argc, char** argv) {
  if (argc < 3) throw std::runtime_error("usage: filament-host MODEL.glb OUT.png [--material F --reflection F --textures DIR --weather none|snow|rain] [--size WxH]");
  Options o;
  o.model = argv[1];
  o.output = argv[2];
  for (int i = 3; i + 1 < argc; i += 2) {
    std::string flag = argv[i], value = argv[i + 1];
    if (flag == "--material") o.material = value;
    else if (flag == "--reflection") o.reflection = value;
    else if (flag == "--textures") o.textures = value;
    else if (flag == "--weather") o.weather = value;
    else if (flag == "--size") std::sscanf(value.c_str(), "%ux%u", &o.width, &o.height);
    else throw std::runtime_error("unknown option " + flag);
  }
  if (o.weather != "none" && o.weather != "snow" && o.weather != "rain") throw std::runtime_error("--weather: none, snow or rain");
  return o;
}

// The weather block's values for each state (docs/weather-model.md's levels): the host
// fills them; a real engine takes them from its weather simulation.
std::map<std::string, float> weatherState(const std::string& weather) {
  std::map<std::string, float> w = {{"temperature", 10.f}, {"sunIntensity", 1.f}};
  // Snow alone, no hoarfrost, so a test can tell where snow lies.
  if (weather == "snow") w = {{"temperature", -6.f}, {"precipitation", 0.6f}, {"snowLevel", 1.f},
                              {"sunIntensity", 0.6f}, {"windIntensity", 0.2f}};
  if (weather == "rain") w = {{"temperature", 12.f}, {"precipitation", 1.f}, {"wetnessLevel", 1.f},
                              {"puddleLevel", 0.8f}, {"sunIntensity", 0.5f}};
  return w;
}

const float3 kSunTowards = normalize(float3{-0.5f, 0.8f, 0.35f});

class Host {
 public:
  explicit Host(const Options& o) : o_(o) {
    engine_ = Engine::create(Engine::Backend::OPENGL);
    if (!engine_) throw std::runtime_error("Engine::create(OPENGL) failed (is DISPLAY set? run under xvfb-run)");
    swapChain_ = engine_->createSwapChain(o.width, o.height);
    renderer_ = engine_->createRenderer();
    scene_ = engine_->createScene();
    view_ = engine_->createView();
    camera_ = engine_->createCamera(utils::EntityManager::get().create());
    camera_->setProjection(35.0, double(o.width) / o.height, 0.1, 100.0);
    camera_->lookAt({2.6, 2.2, 3.4}, {0, 0, 0}, {0, 1, 0});
    camera_->setExposure(1.0f);
    view_->setCamera(camera_);
    view_->setScene(scene_);
    view_->setViewport({0, 0, o.width, o.height});
    view_->setPostProcessingEnabled(false);
    view_->setShadowingEnabled(false);
    renderer_->setClearOptions({.clearColor = {0.45f, 0.5f, 0.58f, 1.0f}, .clear = true});
    sun_ = utils::EntityManager::get().create();
    LightManager::Builder(LightManager::Type::DIRECTIONAL)
        .color({1.0f, 0.97f, 0.92f})
        .intensity(2.2f)
        .direction(-kSunTowards)
        .castShadows(false)
        .build(*engine_, sun_);
    scene_->addEntity(sun_);
    const float3 sh[1] = {{0.35f, 0.38f, 0.45f}};
    ibl_ = IndirectLight::Builder().irradiance(1, sh).intensity(1.0f).build(*engine_);
    scene_->setIndirectLight(ibl_);
  }

  ~Host() {
    if (asset_) {
      scene_->removeEntities(asset_->getEntities(), asset_->getEntityCount());
      loader_->destroyAsset(asset_);
    }
    if (provider_) {
      provider_->destroyMaterials();
      delete provider_;
    }
    if (loader_) gltfio::AssetLoader::destroy(&loader_);
    if (instance_) engine_->destroy(instance_);
    if (material_) engine_->destroy(material_);
    for (Texture* t : textures_) engine_->destroy(t);
    engine_->destroy(ibl_);
    engine_->destroy(sun_);
    engine_->destroyCameraComponent(camera_->getEntity());
    engine_->destroy(view_);
    engine_->destroy(scene_);
    engine_->destroy(renderer_);
    engine_->destroy(swapChain_);
    Engine::destroy(&engine_);
  }

  // The model, fitted into a 2 m cube standing on y = 0... -1 (centred on the origin).
  void loadModel() {
    provider_ = gltfio::createUbershaderLoader(engine_);
    loader_ = gltfio::AssetLoader::create({engine_, provider_, nullptr});
    std::vector<std::uint8_t> bytes = readFile(o_.model);
    asset_ = loader_->createAssetFromBinary(bytes.data(), bytes.size());
    if (!asset_) throw std::runtime_error("gltfio cannot read " + o_.model);
    gltfio::ResourceLoader({engine_, o_.model.c_str(), true, false}).loadResources(asset_);
    asset_->releaseSourceData();
    Aabb box = asset_->getBoundingBox();
    float3 extent = box.extent();
    float scale = 1.0f / std::max(extent.x, std::max(extent.y, extent.z));
    auto& tm = engine_->getTransformManager();
    tm.setTransform(tm.getInstance(asset_->getRoot()), mat4f::scaling(float3(scale)) * mat4f::translation(-box.center()));
    scene_->addEntities(asset_->getEntities(), asset_->getEntityCount());
  }

  // weathergen's material on every primitive, filled from the reflection.
  void useWeathergenMaterial() {
    std::vector<std::uint8_t> package = readFile(o_.material);
    material_ = Material::Builder().package(package.data(), package.size()).build(*engine_);
    if (!material_) throw std::runtime_error("Filament cannot load " + o_.material);
    instance_ = material_->createInstance();
    std::ifstream in(o_.reflection);
    Json reflection = Json::parse(in);
    const Json& surface = reflection.at("surface");
    std::string prefix = surface.at("prefix");
    auto parameterName = [&](std::string identifier) {
      return identifier.rfind(prefix, 0) == 0 ? identifier.substr(prefix.size()) : identifier;
    };
    std::map<std::string, float> weather = weatherState(o_.weather);
    for (const Json& resource : surface.at("resources")) {
      std::string kind = resource.at("kind");
      if (kind == "uniformBlock") {
        for (const Json& member : resource.at("members")) setMember(parameterName(member.at("identifier")), member, reflection, weather);
      } else if (kind == "texture") {
        bindTexture(parameterName(resource.at("identifier")), resource, reflection);
      }
    }
    auto& rm = engine_->getRenderableManager();
    for (std::size_t i = 0; i < asset_->getEntityCount(); ++i) {
      auto renderable = rm.getInstance(asset_->getEntities()[i]);
      if (!renderable) continue;
      for (std::size_t p = 0; p < rm.getPrimitiveCount(renderable); ++p) rm.setMaterialInstanceAt(renderable, p, instance_);
    }
  }

  void renderTo(const std::string& path) {
    std::vector<std::uint8_t> pixels(std::size_t(o_.width) * o_.height * 4);
    bool done = false, issued = false;
    for (int frame = 0; frame < 200 && !done; ++frame) {
      if (renderer_->beginFrame(swapChain_)) {
        renderer_->render(view_);
        if (!issued && frame >= 2) {  // texture uploads land within a couple of frames
          renderer_->readPixels(0, 0, o_.width, o_.height,
                                backend::PixelBufferDescriptor(pixels.data(), pixels.size(), backend::PixelDataFormat::RGBA,
                                                               backend::PixelDataType::UBYTE,
                                                               [](void*, std::size_t, void* user) { *static_cast<bool*>(user) = true; },
                                                               &done));
          issued = true;
        }
        renderer_->endFrame();
      }
      engine_->flushAndWait();
    }
    if (!done) throw std::runtime_error("readPixels never completed");
    // Rows come back top-down from Debian's 1.9.25 GL backend; the frame is linear.
    for (std::size_t i = 0; i < pixels.size(); ++i) {
      if (i % 4 == 3) continue;
      float v = pixels[i] / 255.0f;
      v = v <= 0.0031308f ? v * 12.92f : 1.055f * std::pow(v, 1.0f / 2.4f) - 0.055f;
      pixels[i] = static_cast<std::uint8_t>(std::lround(std::min(v, 1.0f) * 255.0f));
    }
    if (!stbi_write_png(path.c_str(), int(o_.width), int(o_.height), 4, pixels.data(), int(o_.width) * 4))
      throw std::runtime_error("cannot write " + path);
  }

 private:
  // A block member: the weather's from the state above, the material's default.
  void setMember(const std::string& name, const Json& member, const Json& reflection, const std::map<std::string, float>& weather) {
    if (name.rfind("weather_", 0) == 0) {
      std::string field = name.substr(8);
      if (field == "sunDirection") return instance_->setParameter(name.c_str(), kSunTowards);
      if (field == "windDirection") return instance_->setParameter(name.c_str(), float2{1.0f, 0.0f});
      if (member.at("type") == "vec4") return instance_->setParameter(name.c_str(), float4{0.0f});  // no map regions
      auto value = weather.find(field);
      return instance_->setParameter(name.c_str(), value == weather.end() ? 0.0f : value->second);
    }
    Json value;
    for (const Json& block : reflection.at("blocks"))
      for (const Json& m : block.at("members"))
        if (m.at("identifier") == name) value = m.at("default");
    std::string type = member.at("type");
    if (type == "float") instance_->setParameter(name.c_str(), value.get<float>());
    else if (type == "uint") instance_->setParameter(name.c_str(), value.is_boolean() ? uint32_t(value.get<bool>()) : value.get<uint32_t>());
    else if (type == "vec2") instance_->setParameter(name.c_str(), float2{value[0].get<float>(), value[1].get<float>()});
    else if (type == "vec3") instance_->setParameter(name.c_str(), float3{value[0].get<float>(), value[1].get<float>(), value[2].get<float>()});
    else if (type == "vec4")
      instance_->setParameter(name.c_str(), float4{value[0].get<float>(), value[1].get<float>(), value[2].get<float>(), value[3].get<float>()});
  }

  Texture* makeTexture(std::uint32_t width, std::uint32_t height, Texture::InternalFormat format, const void* texels,
                       std::size_t bytes, Texture::Type type) {
    Texture* texture = Texture::Builder().width(width).height(height).levels(1).sampler(Texture::Sampler::SAMPLER_2D)
                           .format(format).build(*engine_);
    void* copy = std::malloc(bytes);
    std::memcpy(copy, texels, bytes);
    texture->setImage(*engine_, 0, Texture::PixelBufferDescriptor(copy, bytes, Texture::Format::RGBA, type,
                                                                  [](void* b, std::size_t, void*) { std::free(b); }));
    textures_.push_back(texture);
    return texture;
  }

  // A weather map: the noise from weathergen's API; the others at their documented
  // fallback (the host has none), as 1x1 float textures.
  void bindTexture(const std::string& name, const Json& resource, const Json& reflection) {
    TextureSampler linearRepeat(TextureSampler::MinFilter::LINEAR, TextureSampler::MagFilter::LINEAR,
                                TextureSampler::WrapMode::REPEAT);
    if (resource.at("shared")) {
      std::string map = resource.at("name");
      if (map == "weatherNoise") {
        weathergen::NoiseTexture noise = weathergen::weatherNoiseTexture();
        Texture* t = makeTexture(noise.width, noise.height, Texture::InternalFormat::RGBA8, noise.rgba8.data(),
                                 noise.rgba8.size(), Texture::Type::UBYTE);
        return instance_->setParameter(name.c_str(), t, linearRepeat);
      }
      float fallback[4] = {0.f, 0.f, 0.f, 0.f};
      if (map == "skyExposure") std::fill(fallback, fallback + 4, -1.0e6f);
      if (map == "snowDeformation") fallback[2] = 1.f;
      Texture* t = makeTexture(1, 1, Texture::InternalFormat::RGBA32F, fallback, sizeof fallback, Texture::Type::FLOAT);
      return instance_->setParameter(name.c_str(), t, linearRepeat);
    }
    for (const Json& texture : reflection.at("textures")) {
      if (texture.at("textureIdentifier") != name) continue;
      const Json& source = texture.at("source");
      if (source.at("kind") != "file") throw std::runtime_error("texture '" + name + "': this host reads image files only");
      std::string path = (std::filesystem::path(o_.textures) / source.at("file").get<std::string>()).string();
      int w = 0, h = 0, channels = 0;
      stbi_uc* texels = stbi_load(path.c_str(), &w, &h, &channels, 4);
      if (!texels) throw std::runtime_error("cannot read image " + path);
      bool srgb = texture.at("colorSpace") == "srgb";
      Texture* t = makeTexture(w, h, srgb ? Texture::InternalFormat::SRGB8_A8 : Texture::InternalFormat::RGBA8, texels,
                               std::size_t(w) * h * 4, Texture::Type::UBYTE);
      stbi_image_free(texels);
      auto wrap = [](const Json& mode) {
        return mode == "clamp" ? TextureSampler::WrapMode::CLAMP_TO_EDGE
               : mode == "mirror" ? TextureSampler::WrapMode::MIRRORED_REPEAT : TextureSampler::WrapMode::REPEAT;
      };
      TextureSampler sampler(texture.at("minFilter") == "nearest" ? TextureSampler::MinFilter::NEAREST
                                                                  : TextureSampler::MinFilter::LINEAR,
                             texture.at("magFilter") == "nearest" ? TextureSampler::MagFilter::NEAREST
                                                                  : TextureSampler::MagFilter::LINEAR);
      sampler.setWrapModeS(wrap(texture.at("wrapU")));
      sampler.setWrapModeT(wrap(texture.at("wrapV")));
      return instance_->setParameter(name.c_str(), t, sampler);
    }
    throw std::runtime_error("texture '" + name + "' is not in the reflection's textures");
  }

  const Options& o_;
  Engine* engine_ = nullptr;
  SwapChain* swapChain_ = nullptr;
  Renderer* renderer_ = nullptr;
  Scene* scene_ = nullptr;
  View* view_ = nullptr;
  Camera* camera_ = nullptr;
  utils::Entity sun_;
  IndirectLight* ibl_ = nullptr;
  gltfio::MaterialProvider* provider_ = nullptr;
  gltfio::AssetLoader* loader_ = nullptr;
  gltfio::FilamentAsset* asset_ = nullptr;
  Material* material_ = nullptr;
  MaterialInstance* instance_ = nullptr;
  std::vector<Texture*> textures_;
};

}  // namespace

// The same state as weathergen eval's --weather argument, so a test can ask the CPU
// evaluator what the host's frame should show.
void printWeatherArgument(const std::string& weather) {
  std::string text = "sunDirection=" + std::to_string(kSunTowards.x) + ":" + std::to_string(kSunTowards.y) + ":" +
                     std::to_string(kSunTowards.z) + ",windDirection=1:0,sunMelt=0,terrainHeightScale=0";
  for (const char* field : {"temperature", "precipitation", "snowLevel", "frostLevel", "wetnessLevel", "puddleLevel",
                            "sunIntensity", "windIntensity"}) {
    auto state = weatherState(weather);
    auto value = state.find(field);
    text += std::string(",") + field + "=" + std::to_string(value == state.end() ? 0.0f : value->second);
  }
  std::printf("%s\n", text.c_str());
}

int main(int argc, char** argv) {
  try {
    if (argc == 3 && std::string(argv[1]) == "--eval-weather") {
      printWeatherArgument(argv[2]);
      return 0;
    }
    Options o = parse(argc, argv);
    Host host(o);
    host.loadModel();
    if (!o.material.empty()) host.useWeathergenMaterial();
    host.renderTo(o.output);
    std::printf("filament-host: wrote %s\n", o.output.c_str());
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "filament-host: %s\n", e.what());
    return 1;
  }
}
