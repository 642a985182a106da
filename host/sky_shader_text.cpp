#include "host/sky_shader_text.hpp"

#include "backends/library_functions.hpp"
#include "backends/shader_syntax.hpp"
#include "nodes/pbr_shading.hpp"

namespace wg {

SkyInputs skyInputs(const FrameState& frame) {
  return {{frame.skyColor[0], frame.skyColor[1], frame.skyColor[2], frame.ambientIntensity},
          {frame.precipitation, frame.windIntensity, 0.f, 0.f}};
}

std::string skyLibraryText(std::string_view block, const std::vector<std::string_view>& functions) {
  const std::string b(block);
  std::string text = "#define frame_skyColor " + b + ".sky.rgb\n#define frame_ambientIntensity " + b +
                     ".sky.w\n#define frame_precipitation " + b + ".weather.x\n#define frame_windIntensity " + b +
                     ".weather.y\n";
  for (const ReachedPiece& piece : reachedLibraryPieces(glslSyntax(), {&kPbrShadingLibrary}, functions))
    text += piece.text;
  return text;
}

}  // namespace wg
