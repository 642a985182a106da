// BM_ImportGltf/<model>: `weathergen import` short of writing files: read and check
// the glTF (container, JSON, schema, references, buffers, images' headers), read every
// primitive's geometry, and build one material graph per material. Real files from
// Debian's assimp-testmodels; skipped when the package is not installed.
#include <benchmark/benchmark.h>

#include <filesystem>

#include "import/gltf_asset.hpp"
#include "import/model_geometry.hpp"
#include "import/model_import.hpp"

namespace {

const std::filesystem::path kModels = "/usr/share/assimp/models/glTF2";

void importGltf(benchmark::State& state, const std::string& relative) {
  std::string path = (kModels / relative).string();
  if (!std::filesystem::exists(path)) {
    state.SkipWithError(("not installed: " + path + " (apt-get install assimp-testmodels)").c_str());
    return;
  }
  std::size_t materials = 0;
  for (auto _ : state) {
    wg::DiagnosticList diagnostics;
    auto asset = wg::gltf::loadAsset(path, diagnostics);
    auto geometry = asset ? wg::gltf::readModelGeometry(*asset, diagnostics) : std::nullopt;
    auto imported = geometry ? wg::gltf::importModel(*asset, *geometry, {}, diagnostics) : std::nullopt;
    if (!imported) {
      state.SkipWithError(("does not import: " + path).c_str());
      return;
    }
    materials = imported->materialGraphs.size();
    benchmark::DoNotOptimize(imported);
  }
  state.counters["materials"] = static_cast<double>(materials);
}

const bool registered = [] {
  for (const char* model : {"2CylinderEngine-glTF-Binary/2CylinderEngine.glb", "BoxTextured-glTF-Binary/BoxTextured.glb",
                            "ClearCoat-glTF/ClearCoatTest.gltf"})
    benchmark::RegisterBenchmark(("BM_ImportGltf/" + std::filesystem::path(model).stem().string()).c_str(), importGltf,
                                 std::string(model))
        ->Unit(benchmark::kMillisecond);
  return true;
}();

}  // namespace
