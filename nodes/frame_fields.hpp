// The frame and weather block, defined once: each member's name, type, accepted range,
// doc and place in FrameState. The std140 block (compiler/frame_block.cpp), eval's
// --weather inputs (cli/eval_inputs.cpp) and the renderer's upload
// (host/frame_uniforms.hpp) are all derived from this table.
#pragma once
#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>

#include "nodes/frame_state.hpp"

namespace wg {

// Accepted air temperatures. Outside them an input is almost certainly a unit mistake
// (Fahrenheit, kelvin), so eval and the runtime's validate() reject it.
inline constexpr float kMinTemperatureC = -60.0f;  // below any inhabited-area record low
inline constexpr float kMaxTemperatureC = 60.0f;   // above the hottest recorded air temperature

enum class FrameFieldType : std::uint8_t { Float, Uint, Vec2, Vec3, Vec4, Mat4 };

// Who fills a member. A surface (--target surface) reads only the weather's members,
// from its own WeatherBlock; the host keeps the rest.
enum class FrameFieldOwner : std::uint8_t {
  Host,      // transforms, camera, lights, tone mapping, debug view: the renderer's
  Weather,   // the weather state: eval's --weather, the simulation
  MapPlace,  // where the host lays the shared weather maps in the world
};

struct FrameField {
  std::string_view name;  // the block member; shaders see it as frame_<name>
  FrameFieldType type;
  std::byte* (*member)(FrameState&);  // where FrameState holds it
  float min, max;                     // accepted range of each component
  std::string_view doc;               // unit and meaning
  FrameFieldOwner owner;
};

// In block order, which is the std140 layout order: never reorder or rename.
std::span<const FrameField> frameFields();
const FrameField* findFrameField(std::string_view name);

std::size_t componentCount(FrameFieldType type);  // 16 for Mat4
std::string_view glslTypeName(FrameFieldType type);  // "float", "uint", "vec2", ... "mat4"

// The member's bytes in `frame` (4 per component).
std::span<std::byte> fieldBytes(const FrameField& field, FrameState& frame);
std::span<const std::byte> fieldBytes(const FrameField& field, const FrameState& frame);
// The member's components; only for float-based types (every type but Uint).
std::span<float> fieldFloats(const FrameField& field, FrameState& frame);

}  // namespace wg
