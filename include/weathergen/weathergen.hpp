// weathergen's engine API: compile a material graph held in memory to GLSL, HLSL,
// SPIR-V and reflection JSON.
//
// Self-contained on purpose: only standard types cross this boundary, so engines never
// see the compiler's internals and the API can stay stable while they change.
//  - Diagnostics come back as values; no exception ever leaves compile().
//  - No global state of weathergen's own; glslang's process tables are set up once by
//    initialize(), after which compile() may run on any number of threads at once.
#pragma once
#include <cstdint>
#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace weathergen {

struct Diagnostic {
  std::string code;      // stable id, e.g. "WG2001"; "WG9900" is an internal exception
  std::string severity;  // "error" or "warning"
  std::string file;      // the fileName given to compile()
  std::string pointer;   // RFC 6901 JSON pointer into the graph, "" for the whole document
  std::string message;
  std::string hint;
  int line = 0;  // 1-based; 0 when unknown
  int column = 0;
};

struct Stage {
  std::string language;  // "glsl" or "hlsl"
  std::string stage;     // "vert" or "frag"
  std::string source;
  std::vector<std::uint32_t> spirv;  // empty unless Options::spirv
};

// One surface file's text (Options::surface).
struct Surface {
  std::string language;  // "glsl", "glsles" or "hlsl"
  std::string source;
};

struct Options {
  bool spirv = true;           // compile every stage to validated SPIR-V
  // What an engine that needs less can skip: without hlsl, Result::stages holds the two
  // GLSL stages; without reflection, Result::reflectionJson stays empty.
  bool hlsl = true;
  bool reflection = true;
  bool optimize = false;       // spirv-opt's performance passes
  // Threads that compile the four stages to SPIR-V at once (glslang, spirv-val), the
  // calling thread among them; the result is the same for any count. 1 spawns none, 0
  // or less counts as 1, and no more than one thread a stage is started.
  int threads = 1;
  std::string weatherPreset;   // "" keeps the graph's own preset
  // Quality tier: "low" (seed 000's terms), "medium" (plus sky exposure) or "high" (plus
  // the looks); "" keeps the graph's own, else high. An unknown tier is a diagnostic.
  std::string quality;
  // Weather effects switched on or off over the graph's own, by name ("relief",
  // "specularAntiAliasing"...; docs/weather-model.md); an unknown name is a diagnostic.
  std::map<std::string, bool> effects;
  bool cppHeader = false;      // fill Result::cppHeader (std140 structs with static_asserts)
  // Fill Result::surfaces: the weathered surface without our lighting, for engines that
  // light it themselves (docs/engine-api.md, "The surface contract").
  bool surface = false;
  // A persistent compile cache shared by processes (docs/scaling.md, "The compile
  // cache"): "" compiles every time; else a directory, created if missing, that keeps
  // each compile without diagnostics, keyed by the graph's text, the files it reads and
  // the options. A directory that cannot be written only leaves the cache out. Unlike
  // the CLI, the library has no default: it never writes outside what its program names.
  std::string cacheDirectory;
  // The variant: static switch name -> value (docs/graph-format.md, "Static switches");
  // switches not named keep their default. Unknown names or values are diagnostics.
  std::map<std::string, std::string> switches;
};

struct Result {
  bool ok = false;  // true when the material compiled; diagnostics may still hold warnings
  std::vector<Diagnostic> diagnostics;
  std::string name;         // the material's declared name
  std::string contentHash;  // identifies what the material is, not how its file spells it
  std::string reflectionJson;  // with Options::reflection
  std::vector<Stage> stages;  // glsl vert, glsl frag, hlsl vert, hlsl frag (with Options::hlsl)
  std::string cppHeader;      // only with Options::cppHeader
  std::vector<Surface> surfaces;  // only with Options::surface: glsl, glsles, hlsl
};

// Sets up glslang's process-global state. Call once before compiling from several
// threads; further calls, concurrent ones included, do nothing. Returns false if
// glslang could not be initialised (compile() then reports WG9900).
bool initialize();

// Compiles one graph. fileName names the graph in diagnostics and anchors relative
// texture paths; json is the graph text. Never throws.
Result compile(std::string_view fileName, std::string_view json, const Options& options = {}) noexcept;

// The weather's shared noise texture: the "weatherNoise" entry of the reflection's
// weatherMaps (set 0), which weathered materials sample. RGBA8 texels, row-major, row 0
// first, width * height * 4 bytes; the same bytes on every call and every machine.
// Upload it once as VK_FORMAT_R8G8B8A8_UNORM with one mip level and bind it with a
// sampler that repeats (REPEAT on u and v), filters linearly and has maxLod 0, as the
// CPU evaluator reads it (docs/engine-api.md). Never throws; empty if out of memory.
struct NoiseTexture {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgba8;
};
NoiseTexture weatherNoiseTexture() noexcept;

// weathergen's version, e.g. "0.1.0".
std::string version();

}  // namespace weathergen
