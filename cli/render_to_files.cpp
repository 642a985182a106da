#include "cli/render_to_files.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>

#include "cli/commands.hpp"
#include "cli/diagnostic_output.hpp"
#include "cli/picture_files.hpp"
#include "compiler/literal.hpp"
#include "host/display_image.hpp"
#include "host/frame_target_plan.hpp"
#include "host/image/contact_sheet.hpp"
#include "host/image/png_file.hpp"
#include "host/material_compile_error.hpp"
#include "host/timeline_renderer.hpp"

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

// The outputs against every file the render read, its materials' libraries and images
// too: those are known once the first frame has compiled them, before anything is written.
std::string outputsReplaceInputs(const SceneRenderer& renderer, const RenderPlan& plan,
                                 const std::vector<std::string>& stageSlugs = {}) {
  RunInputs inputs = plan.inputs;
  inputs.add(renderer.materialInputFiles());
  const auto outputs = plannedOutputs(plan, renderer.scene().name, stageSlugs);
  if (std::string e = inputs.checkOutputs(outputs); !e.empty()) return e;
  return checkNoSpecialFiles(outputs);
}

int renderOneFrame(SceneRenderer& renderer, vk::Context& ctx, const RenderPlan& plan) {
  RenderedFrame frame = renderer.render(plan.request);
  if (!reportValidation(ctx)) return kExitInternal;
  if (std::string e = outputsReplaceInputs(renderer, plan); !e.empty()) return usageError(e);
  if (int e = writePicture(plan.output, toDisplayImage(frame))) return e;
  if (plan.progress) std::fprintf(stderr, "render: wrote %s (%ux%u)\n", quoteUserText(plan.output, 300).c_str(), frame.width, frame.height);
  return kExitOk;
}

constexpr int kSheetColumns = 3;

std::string sheetTitle(const SceneRenderer& renderer, const RenderPlan& plan) {
  return "weathergen  " + renderer.scene().name + "  (" + std::string(languageName(plan.request.backend)) + ", " +
         plan.aov + ")";
}

// The contact sheet and the strip are sized from the plan, before any stage renders: a
// timeline with too many stages fails at once instead of after rendering them all.
std::string checkSheetSize(const std::vector<TimelineFrame>& stages, const std::string& title, const RenderPlan& plan) {
  const int width = static_cast<int>(plan.request.width), height = static_cast<int>(plan.request.height);
  std::vector<image::SheetCell> cells;
  for (const auto& stage : stages) cells.push_back({width, height, stage.lines});
  const image::ContactSheetLayout sheet = image::layoutContactSheet(title, cells, kSheetColumns);
  const long long stripWidth = static_cast<long long>(stages.size()) * (width + image::kStripGap) - image::kStripGap;
  const long long largest = std::max({static_cast<long long>(sheet.width), static_cast<long long>(sheet.height), stripWidth});
  if (largest <= image::kMaxPngDimension) return "";
  return "timeline '" + quoteUserText(plan.timelinePath) + "' has " + std::to_string(stages.size()) + " stages; at " +
         std::to_string(width) + "x" + std::to_string(height) + " its contact sheet would be " + std::to_string(sheet.width) + "x" +
         std::to_string(sheet.height) + " and its strip " + std::to_string(stripWidth) +
         " pixels wide, over the limit of " + std::to_string(image::kMaxPngDimension) +
         " on a side; give the timeline fewer stages (keyframes sharing a label are one stage) or render with a smaller --size";
}

int renderTimelineSheet(SceneRenderer& renderer, vk::Context& ctx, const RenderPlan& plan) {
  auto stages = planTimeline(*plan.timeline, plan.request, plan.step);
  const std::string title = sheetTitle(renderer, plan);
  if (std::string e = checkSheetSize(stages, title, plan); !e.empty()) return usageError(e);
  renderTimelineFrames(renderer, stages, plan.request, [&](std::size_t i, std::size_t n, const std::string& label) {
    if (plan.progress) std::fprintf(stderr, "render: [%zu/%zu] %s\n", i, n, quoteUserText(label).c_str());
  });
  if (!reportValidation(ctx)) return kExitInternal;
  std::vector<std::string> slugs;
  for (const auto& stage : stages) slugs.push_back(stage.slug);
  if (std::string e = outputsReplaceInputs(renderer, plan, slugs); !e.empty()) return usageError(e);
  const std::string& sceneName = renderer.scene().name;
  std::vector<image::LabelledFrame> frames;
  std::vector<Image> strip;
  std::vector<PictureFile> pictures;
  for (const auto& stage : stages) {
    Image img = toDisplayImage(stage.frame);
    if (!plan.framesDir.empty()) pictures.push_back({framePath(plan, sceneName, stage.slug), img, true});
    frames.push_back({img, stage.lines});
    strip.push_back(std::move(img));
  }
  const std::string stripFile = stripPath(plan).string();
  pictures.push_back({plan.output, image::contactSheet(title, frames, kSheetColumns)});
  pictures.push_back({stripFile, image::frameStrip(strip)});
  if (std::string e = writePicturesTogether(pictures); !e.empty()) return usageError(e);
  if (plan.progress) std::fprintf(stderr, "render: wrote %s and %s\n", quoteUserText(plan.output, 300).c_str(), quoteUserText(stripFile, 300).c_str());
  return kExitOk;
}

}  // namespace

int reportOutOfMemory(const vk::OutOfMemory& e) {
  std::fprintf(stderr, "weathergen: error: the device ran out of memory (%s); render with a smaller --size or --samples 1\n",
               e.what());
  return kExitBadInput;
}

unsigned samplesThatFit(const vk::Context& ctx, std::uint32_t width, std::uint32_t height, unsigned samples) {
  const FrameTargetPlan targets = planFrameTargets(width, height, samples, frameLimits(ctx));
  if (targets.samples == 0) std::fprintf(stderr, "weathergen: error: %s\n", targets.note.c_str());
  else if (!targets.note.empty()) std::fprintf(stderr, "weathergen: note: %s\n", targets.note.c_str());
  return targets.samples;
}

RenderedFiles renderToFiles(vk::Context& ctx, scene::Scene scene, const RenderPlan& plan, const std::string& graphsDir) {
  RenderedFiles result;
  const unsigned samples = samplesThatFit(ctx, plan.request.width, plan.request.height, plan.samples);
  if (samples == 0) return {kExitBadInput, {}};
  try {
    SceneRenderer renderer(ctx, std::move(scene), graphsDir, static_cast<VkSampleCountFlagBits>(samples));
    result.exitCode = plan.timeline ? renderTimelineSheet(renderer, ctx, plan) : renderOneFrame(renderer, ctx, plan);
    if (result.exitCode == kExitOk) result.materialInputs = renderer.materialInputFiles();
  } catch (const MaterialCompileError& e) {
    printDiagnostics(inModelTerms(e.diagnostics(), plan.modelOrigins), false);
    result.exitCode = kExitBadInput;
  } catch (const vk::OutOfMemory& e) {
    result.exitCode = reportOutOfMemory(e);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "weathergen: error: %s\n", quoteUserText(e.what(), 1000).c_str());
    result.exitCode = kExitInternal;
  }
  return result;
}

}  // namespace wg
