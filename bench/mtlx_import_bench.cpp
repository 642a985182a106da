// MaterialX import (docs/materialx-import.md), on the MaterialX project's StandardSurface
// examples (../shared/materialx beside the checkout; skipped when absent):
//   BM_ImportMaterialX/StandardSurface: every document read, checked and turned into
//     graphs, short of writing files, with stand-in images through the search path;
//   BM_CodegenMaterialX/<document>: BM_Codegen's path (no SPIR-V, no reflection) on the
//     graphs a document imports to.
#include <benchmark/benchmark.h>
#include <unistd.h>

#include <algorithm>

#include <filesystem>
#include <fstream>
#include <regex>
#include <set>

#include "bench/bench_common.hpp"
#include "driver/material_compiler.hpp"
#include "import/mtlx_import.hpp"

namespace {

namespace fs = std::filesystem;

const fs::path kFolder = fs::path(WG_SOURCE_DIR) / ".." / "shared" / "materialx" / "StandardSurface";

std::vector<fs::path> documents() {
  std::vector<fs::path> found;
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(kFolder, ec))
    if (e.path().extension() == ".mtlx") found.push_back(e.path());
  std::sort(found.begin(), found.end());
  return found;
}

// A folder of stand-ins (the placeholder PNG) for every image the documents name.
class StandIns {
 public:
  StandIns() : dir_(fs::temp_directory_path() / ("wg-mtlx-bench-" + std::to_string(::getpid()))) {
    fs::create_directories(dir_);
    std::regex file(R"re(type="filename" value="([^"]+)")re");
    for (const auto& doc : documents()) {
      std::string text = wg::bench::readText(doc.string());
      for (std::sregex_iterator it(text.begin(), text.end(), file), end; it != end; ++it)
        std::ofstream(dir_ / (*it)[1].str(), std::ios::binary) << wg::mtlx::placeholderPng();
    }
  }
  ~StandIns() { fs::remove_all(dir_); }
  const fs::path& dir() const { return dir_; }

 private:
  fs::path dir_;
};

std::optional<wg::mtlx::ImportedDocument> importOne(const fs::path& doc, const fs::path& images) {
  wg::DiagnosticList diagnostics;
  auto document = wg::mtlx::loadDocument(doc.string(), {images.string()}, diagnostics);
  return document ? wg::mtlx::importDocument(*document, {}, diagnostics) : std::nullopt;
}

void importFolder(benchmark::State& state) {
  StandIns standIns;
  auto docs = documents();
  if (docs.empty()) {
    state.SkipWithError(("no MaterialX examples at " + kFolder.string()).c_str());
    return;
  }
  std::size_t materials = 0;
  for (auto _ : state) {
    materials = 0;
    for (const auto& doc : docs) {
      auto imported = importOne(doc, standIns.dir());
      if (!imported) {
        state.SkipWithError(("does not import: " + doc.string()).c_str());
        return;
      }
      materials += imported->materialGraphs.size();
    }
  }
  state.counters["documents"] = static_cast<double>(docs.size());
  state.counters["materials"] = static_cast<double>(materials);
}

void codegenDocument(benchmark::State& state, const fs::path& doc) {
  StandIns standIns;
  auto imported = importOne(doc, standIns.dir());
  if (!imported) {
    state.SkipWithError(("does not import: " + doc.string()).c_str());
    return;
  }
  fs::path out = standIns.dir() / "out";
  fs::create_directories(out);
  for (const auto& f : imported->files) std::ofstream(out / f.name, std::ios::binary) << f.bytes;
  wg::CompileOptions options{.emitSpirv = false, .emitReflection = false};
  std::vector<std::pair<std::string, std::string>> graphs;
  for (const auto& g : imported->materialGraphs) graphs.emplace_back((out / g).string(), wg::bench::readText((out / g).string()));
  for (const auto& [path, text] : graphs)
    if (!wg::compileMaterialText(path, text, options).material) {
      state.SkipWithError(("does not compile: " + path).c_str());
      return;
    }
  for (auto _ : state)
    for (const auto& [path, text] : graphs) benchmark::DoNotOptimize(wg::compileMaterialText(path, text, options));
  state.counters["materials"] = static_cast<double>(graphs.size());
}

const bool registered = [] {
  benchmark::RegisterBenchmark("BM_ImportMaterialX/StandardSurface", importFolder)->Unit(benchmark::kMillisecond);
  for (const auto& doc : documents())
    if (doc.stem().string().find("_look_") == std::string::npos)  // looks re-import other documents' materials
      benchmark::RegisterBenchmark(("BM_CodegenMaterialX/" + doc.stem().string()).c_str(), codegenDocument, doc)
          ->Unit(benchmark::kMicrosecond);
  return true;
}();

}  // namespace
