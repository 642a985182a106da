#include "import/mtlx_shading_models.hpp"

namespace wg::mtlx {

namespace {

const std::vector<ShadingModel>& shadingModels() {
  static const std::vector<ShadingModel> kModels = {
      {"standard_surface", "base_color", "base", "metalness", "specular_roughness", "emission_color", "emission", "opacity",
       "normal", "", "specular", "specular_IOR",
       {{"base", "1"}, {"base_color", "0.8, 0.8, 0.8"}, {"metalness", "0"}, {"specular_roughness", "0.2"},
        {"emission", "0"}, {"emission_color", "1, 1, 1"}, {"opacity", "1, 1, 1"}, {"specular", "1"}, {"specular_IOR", "1.5"}},
       {{"diffuse_roughness", "", "0"}, {"specular_color", "", "1, 1, 1"}, {"specular_anisotropy", "", "0"},
        {"specular_rotation", "specular_anisotropy", "0"}, {"transmission", "", "0"}, {"transmission_", "transmission", ""},
        {"subsurface", "", "0"}, {"subsurface_", "subsurface", ""}, {"sheen", "", "0"}, {"sheen_", "sheen", ""},
        {"coat", "", "0"}, {"coat_", "coat", ""}, {"thin_film_thickness", "", "0"}, {"thin_film_", "thin_film_thickness", ""},
        {"thin_walled", "", "false"}, {"tangent", "", ""}}},
      {"open_pbr_surface", "base_color", "base_weight", "base_metalness", "specular_roughness", "emission_color",
       "emission_luminance", "geometry_opacity", "geometry_normal", "", "specular_weight", "specular_ior",
       {{"base_weight", "1"}, {"base_color", "0.8, 0.8, 0.8"}, {"base_metalness", "0"}, {"specular_roughness", "0.3"},
        {"emission_luminance", "0"}, {"emission_color", "1, 1, 1"}, {"geometry_opacity", "1"}, {"specular_weight", "1"},
        {"specular_ior", "1.5"}},
       {{"base_diffuse_roughness", "", "0"}, {"specular_color", "", "1, 1, 1"}, {"specular_roughness_anisotropy", "", "0"},
        {"specular_ior_level", "", "0.5"}, {"transmission_weight", "", "0"}, {"transmission_", "transmission_weight", ""},
        {"subsurface_weight", "", "0"}, {"subsurface_", "subsurface_weight", ""}, {"fuzz_weight", "", "0"},
        {"fuzz_", "fuzz_weight", ""}, {"coat_weight", "", "0"}, {"coat_", "coat_weight", ""},
        {"thin_film_weight", "", "0"}, {"thin_film_", "thin_film_weight", ""}, {"geometry_thin_walled", "", "false"},
        {"geometry_tangent", "", ""}, {"geometry_coat_", "coat_weight", ""}}},
      {"gltf_pbr", "base_color", "", "metallic", "roughness", "emissive", "emissive_strength", "alpha", "normal", "occlusion",
       "specular", "ior",
       {{"base_color", "1, 1, 1"}, {"metallic", "1"}, {"roughness", "1"}, {"emissive", "0, 0, 0"}, {"emissive_strength", "1"},
        {"alpha", "1"}, {"occlusion", "1"}, {"specular", "1"}, {"ior", "1.5"}},
       {{"specular_color", "", "1, 1, 1"}, {"transmission", "", "0"}, {"thickness", "transmission", "0"}, {"attenuation_", "transmission", ""},
        {"sheen_color", "", "0, 0, 0"}, {"sheen_roughness", "sheen_color", ""}, {"clearcoat", "", "0"},
        {"clearcoat_", "clearcoat", ""}, {"iridescence", "", "0"}, {"iridescence_", "iridescence", ""},
        {"dispersion", "", "0"}, {"anisotropy_strength", "", "0"}, {"anisotropy_rotation", "anisotropy_strength", ""},
        {"tangent", "", ""}}},
      {"UsdPreviewSurface", "diffuseColor", "", "metallic", "roughness", "emissiveColor", "", "opacity", "normal", "occlusion",
       "", "ior",
       {{"diffuseColor", "0.18, 0.18, 0.18"}, {"metallic", "0"}, {"roughness", "0.5"}, {"emissiveColor", "0, 0, 0"},
        {"opacity", "1"}, {"occlusion", "1"}, {"ior", "1.5"}, {"normal", "0, 0, 1"}},
       {{"useSpecularWorkflow", "", "0"}, {"specularColor", "useSpecularWorkflow", ""}, {"clearcoat", "", "0"},
        {"clearcoatRoughness", "clearcoat", ""}, {"displacement", "", "0"}}},
  };
  return kModels;
}

}  // namespace

const ShadingModel* shadingModel(std::string_view category) {
  for (const auto& m : shadingModels())
    if (category == m.category) return &m;
  return nullptr;
}

}  // namespace wg::mtlx
