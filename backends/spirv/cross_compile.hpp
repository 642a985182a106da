// More targets from the validated SPIR-V: GLSL ES and Metal Shading Language, both
// produced by SPIRV-Cross, so they inherit every check the SPIR-V already passed.
//
// Resource slots are derived from the SPIR-V descriptor set and binding, never from
// declaration order: within each slot kind (uniform buffer, texture, sampler), the
// resources the module declares are ranked by (set, binding) and numbered from 0. Both
// stages of a material declare the same resources, so a resource has the same slot in
// both, even where one stage does not use it (its slot is then simply left unbound).
// The same material therefore always gets the same slots, and output is byte-deterministic.
#pragma once
#include <string>

#include "backends/spirv/spirv_toolchain.hpp"

namespace wg {

struct CrossResult {
  bool ok = false;
  std::string source;      // the translated shader when ok
  std::string error;       // SPIRV-Cross's message when !ok
  std::string entryPoint;  // function name in `source` ("main" in GLSL ES, "main0" in MSL)
};

// GLSL ES 3.10 (`#version 310 es`): separate texture/sampler pairs become combined
// samplers named <texture>_<sampler> that take their texture's slot; uniform blocks and
// combined samplers get explicit `layout(binding = N)` (GL has no descriptor sets), the
// same N in both stages as GL's program link requires. Floats and ints default to highp.
// Anonymous blocks are named after their type: FrameBlock's instance is frameBlock.
CrossResult spirvToGlslEs(const SpirvWords& words, ShaderStage stage);

// MSL 2.0 for macOS: uniform blocks take [[buffer(N)]], images [[texture(N)]] and
// samplers [[sampler(N)]] with N as described above; the app chooses vertex-buffer
// indices above the uniform buffers'. The entry point is main0: `main` is reserved in Metal.
CrossResult spirvToMsl(const SpirvWords& words, ShaderStage stage);

}  // namespace wg
