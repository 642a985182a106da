#include "cli/render_to_files.hpp"

#include <cstdio>
#include <filesystem>

#include "cli/commands.hpp"
#include "cli/diagnostic_output.hpp"
#include "runtime/display_image.hpp"
#include "runtime/image/contact_sheet.hpp"
#include "runtime/image/png_file.hpp"
#include "runtime/material_compile_error.hpp"
#include "runtime/timeline_renderer.hpp"

namespace wg {

namespace {

bool reportValidation(const vk::Context& ctx) {
  const auto& messages = ctx.validationMessages();
  if (messages.empty()) return true;
  constexpr std::size_t kShown = 5;  // the first few tell the story; the rest repeat
  for (std::size_t i = 0; i < messages.size() && i < kShown; ++i)
    std::fprintf(stderr, "vulkan validation %s\n", messages[i].c_str());
  std::fprintf(stderr, "weathergen: error: %zu Vulkan validation message(s)\n", messages.size());
  return false;
}

int writePicture(const std::string& path, const Image& picture) {
  if (std::string e = image::writePng(path, picture); !e.empty()) return usageError(e);
  return kExitOk;
}

int renderOneFrame(SceneRenderer& renderer, vk::Context& ctx, const RenderPlan& plan) {
  RenderedFrame frame = renderer.render(plan.request);
  if (!reportValidation(ctx)) return kExitInternal;
  if (int e = writePicture(plan.output, toDisplayImage(frame))) return e;
  if (plan.progress) std::fprintf(stderr, "render: wrote %s (%ux%u)\n", plan.output.c_str(), frame.width, frame.height);
  return kExitOk;
}

int renderTimelineSheet(SceneRenderer& renderer, vk::Context& ctx, const RenderPlan& plan) {
  auto stages = renderTimeline(renderer, *plan.timeline, plan.request, plan.step,
                               [&](std::size_t i, std::size_t n, const std::string& label) {
                                 if (plan.progress) std::fprintf(stderr, "render: [%zu/%zu] %s\n", i, n, label.c_str());
                               });
  if (!reportValidation(ctx)) return kExitInternal;
  const std::string& sceneName = renderer.scene().name;
  std::vector<image::LabelledFrame> frames;
  std::vector<Image> strip;
  for (const auto& stage : stages) {
    Image img = toDisplayImage(stage.frame);
    if (!plan.framesDir.empty()) {
      std::filesystem::create_directories(plan.framesDir);
      std::string path = (std::filesystem::path(plan.framesDir) / (sceneName + "-" + stage.slug + ".png")).string();
      if (int e = writePicture(path, img)) return e;
    }
    frames.push_back({img, stage.lines});
    strip.push_back(std::move(img));
  }
  std::string title = "weathergen  " + sceneName + "  (" + std::string(languageName(plan.request.backend)) + ", " + plan.aov + ")";
  constexpr int kSheetColumns = 3;
  if (int e = writePicture(plan.output, image::contactSheet(title, frames, kSheetColumns))) return e;
  std::filesystem::path stripPath = std::filesystem::path(plan.output).replace_extension(".strip.png");
  if (int e = writePicture(stripPath.string(), image::frameStrip(strip))) return e;
  if (plan.progress) std::fprintf(stderr, "render: wrote %s and %s\n", plan.output.c_str(), stripPath.string().c_str());
  return kExitOk;
}

}  // namespace

RenderedFiles renderToFiles(vk::Context& ctx, scene::Scene scene, const RenderPlan& plan, const std::string& graphsDir) {
  RenderedFiles result;
  try {
    SceneRenderer renderer(ctx, std::move(scene), graphsDir);
    result.exitCode = plan.timeline ? renderTimelineSheet(renderer, ctx, plan) : renderOneFrame(renderer, ctx, plan);
    if (result.exitCode == kExitOk) result.materialInputs = renderer.materialInputFiles();
  } catch (const MaterialCompileError& e) {
    printDiagnostics(e.diagnostics(), false);
    result.exitCode = kExitBadInput;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "weathergen: error: %s\n", e.what());
    result.exitCode = kExitInternal;
  }
  return result;
}

}  // namespace wg
