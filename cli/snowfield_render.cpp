#include "cli/snowfield_render.hpp"

#include <cstdio>
#include <filesystem>

#include "cli/commands.hpp"
#include "cli/diagnostic_output.hpp"
#include "cli/picture_files.hpp"
#include "cli/render_to_files.hpp"
#include "cli/run_inputs.hpp"
#include "compiler/literal.hpp"
#include "host/display_image.hpp"
#include "host/image/contact_sheet.hpp"
#include "host/snowfield/snowfield_scene.hpp"

namespace wg {

namespace {

std::filesystem::path stripPath(const SnowfieldRenderOptions& o) {
  return std::filesystem::path(o.output).replace_extension(".strip.png");
}

std::filesystem::path framePath(const SnowfieldRenderOptions& o, std::size_t index) {
  char name[64];
  std::snprintf(name, sizeof name, "snowfield-%02zu.png", index + 1);
  return std::filesystem::path(o.framesDir) / name;
}

// The pictures against the bundled graphs and images the scene reads, known once the
// first frame has compiled them, before any picture is written.
std::string outputsReplaceInputs(const SceneRenderer& renderer, const SnowfieldRenderOptions& o, std::size_t frameCount) {
  RunInputs inputs;
  inputs.add(renderer.materialInputFiles());
  std::vector<PlannedOutput> outputs{{"-o", o.output}, {"-o", stripPath(o)}};
  for (std::size_t i = 0; i < frameCount && !o.framesDir.empty(); ++i) outputs.push_back({"--frames", framePath(o, i)});
  if (std::string e = inputs.checkOutputs(outputs); !e.empty()) return e;
  return checkNoSpecialFiles(outputs);
}

}  // namespace

int renderSnowfield(const SnowfieldRenderOptions& o) {
  std::string error;
  auto ctx = vk::Context::create({o.device, o.validation}, error);
  if (!ctx) return deviceUnavailable(error, o.device);
  const unsigned samples = samplesThatFit(*ctx, o.request.width, o.request.height, o.samples);
  if (samples == 0) return kExitBadInput;
  snow::SnowfieldSettings settings;
  SceneRenderer renderer(*ctx, snow::makeSnowfieldScene(settings), o.graphsDir, static_cast<VkSampleCountFlagBits>(samples));
  snow::SnowfieldAnimation animation(*ctx, settings, o.request.weather);
  renderer.setSnowDeformation(&animation.deformationImage());
  std::vector<image::LabelledFrame> frames;
  std::vector<Image> strip;
  std::vector<PictureFile> pictures;
  auto times = snow::SnowfieldAnimation::keyTimes();
  for (std::size_t i = 0; i < times.size(); ++i) {
    if (o.progress) std::fprintf(stderr, "render: [%zu/%zu] snowfield t = %.0f s\n", i + 1, times.size(), times[i]);
    snow::SnowfieldMoment moment = animation.advanceTo(times[i]);
    RenderRequest request = o.request;
    request.cameraPose = moment.camera;
    request.objectModels = moment.objectModels;
    if (request.debugView == 0) request.afterColourPass = animation.postPasses();  // lit frames only
    RenderedFrame frame = renderer.render(request);
    if (!ctx->validationMessages().empty()) {
      for (const auto& m : ctx->validationMessages()) std::fprintf(stderr, "vulkan validation %s\n", m.c_str());
      std::fprintf(stderr, "weathergen: error: Vulkan validation messages\n");
      return kExitInternal;
    }
    if (i == 0)
      if (std::string e = outputsReplaceInputs(renderer, o, times.size()); !e.empty()) return usageError(e);
    Image img = toDisplayImage(frame);
    if (!o.framesDir.empty()) pictures.push_back({framePath(o, i), img, true});
    frames.push_back({img, moment.caption});
    strip.push_back(std::move(img));
  }
  const std::string title = "weathergen  snowfield: prints that leave the window come back";
  constexpr int kSheetColumns = 3;
  const std::string stripFile = stripPath(o).string();
  pictures.push_back({o.output, image::contactSheet(title, frames, kSheetColumns)});
  pictures.push_back({stripFile, image::frameStrip(strip)});
  if (std::string e = writePicturesTogether(pictures); !e.empty()) return usageError(e);
  if (o.progress) std::fprintf(stderr, "render: wrote %s and %s\n", quoteUserText(o.output, 300).c_str(), quoteUserText(stripFile, 300).c_str());
  return kExitOk;
}

}  // namespace wg
