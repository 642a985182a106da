// BM_GlslangCompile/rock_<stage>_<language>: glslang's compile time (compileToSpirv
// only) for the shaders weathergen emits for graphs/rock.json. The source is emitted
// once, outside the timed loop.
#include <benchmark/benchmark.h>

#include "bench/bench_common.hpp"
#include "driver/material_compiler.hpp"

namespace {

void glslangCompile(benchmark::State& state, wg::ShaderLanguage language, wg::ShaderStage stage) {
  const std::string path = (wg::bench::graphsDirectory() / "rock.json").string();
  auto compiled = wg::compileMaterialText(path, wg::bench::readText(path), {.emitSpirv = false});
  if (!compiled.material) {
    state.SkipWithError("graphs/rock.json does not compile");
    return;
  }
  const std::string source = compiled.material->stage(language, stage).source;
  auto check = wg::compileToSpirv(source, language, stage);  // also initialises glslang
  if (!check.ok) {
    state.SkipWithError(("glslang rejects the emitted shader: " + check.log).c_str());
    return;
  }
  for (auto _ : state) {
    auto result = wg::compileToSpirv(source, language, stage);
    benchmark::DoNotOptimize(result);
  }
  state.counters["source_bytes"] = static_cast<double>(source.size());
  state.counters["spirv_instructions"] = static_cast<double>(wg::countInstructions(check.words));
}

using L = wg::ShaderLanguage;
using S = wg::ShaderStage;
BENCHMARK_CAPTURE(glslangCompile, rock_frag_glsl, L::Glsl, S::Fragment)->Name("BM_GlslangCompile/rock_frag_glsl")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(glslangCompile, rock_frag_hlsl, L::Hlsl, S::Fragment)->Name("BM_GlslangCompile/rock_frag_hlsl")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(glslangCompile, rock_vert_glsl, L::Glsl, S::Vertex)->Name("BM_GlslangCompile/rock_vert_glsl")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(glslangCompile, rock_vert_hlsl, L::Hlsl, S::Vertex)->Name("BM_GlslangCompile/rock_vert_hlsl")->Unit(benchmark::kMillisecond);

}  // namespace
