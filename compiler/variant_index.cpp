#include "compiler/variant_index.hpp"

#include <nlohmann/json.hpp>
#include <set>

#include "compiler/json_text.hpp"

namespace wg {

std::string buildVariantIndexJson(const std::string& material, const std::vector<SwitchDecl>& switches,
                                  const std::vector<VariantEntry>& variants) {
  using Json = nlohmann::ordered_json;
  Json declared = Json::object();
  for (const auto& s : switches) declared[s.name] = {{"values", s.values}, {"default", s.defaultValue}};
  Json list = Json::array();
  std::set<std::string> shaders;
  for (const auto& v : variants) {
    Json values = Json::object();
    for (const auto& [name, value] : v.switches) values[name] = value;
    list.push_back({{"name", variantName(v.switches)},
                    {"switches", std::move(values)},
                    {"contentHash", v.contentHash},
                    {"reflection", v.fileStem + ".reflect.json"}});
    shaders.insert(v.contentHash);
  }
  Json root = {{"weathergenVersion", WEATHERGEN_VERSION},
               {"material", material},
               {"switches", std::move(declared)},
               {"variantCount", variants.size()},
               {"shaderSetCount", shaders.size()},
               {"variants", std::move(list)}};
  return jsonText(root, 2) + "\n";
}

}  // namespace wg
