// One render of a scene into the output files: a PNG, or for a timeline a labelled
// contact sheet, OUT.strip.png and optionally each frame. Every file is written
// atomically, so a failed render keeps the last good pictures.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "cli/render_plan.hpp"
#include "vulkan/vulkan_context.hpp"

namespace wg {

struct RenderedFiles {
  int exitCode = 0;                        // ExitCode; errors are printed on stderr
  std::vector<std::string> materialInputs;  // SceneRenderer::materialInputFiles, on success
};

// The MSAA samples a frame of this size fits at, up to `samples`, with a note on stderr
// when fewer; 0 after an error saying why it fits at none (host/frame_target_plan.hpp).
unsigned samplesThatFit(const vk::Context& ctx, std::uint32_t width, std::uint32_t height, unsigned samples);

// A Vulkan allocation that still failed is a resource limit: says so, gives kExitBadInput.
int reportOutOfMemory(const vk::OutOfMemory& e);

// A graph that does not compile prints the compiler's diagnostics and gives
// kExitBadInput; validation messages and other failures give kExitInternal.
RenderedFiles renderToFiles(vk::Context& ctx, scene::Scene scene, const RenderPlan& plan, const std::string& graphsDir);

}  // namespace wg
