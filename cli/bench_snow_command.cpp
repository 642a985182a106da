// weathergen bench-snow: GPU time of the deformation pass (stamps plus normals, from
// timestamp queries) with 1 to 1024 interactors, the same load on smaller and larger
// maps, the refill pass, and the memory of the map and the print store after a
// 10-minute scripted walk in simulated time. Prints markdown (docs/BENCHMARKS.md).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "cli/bench_options.hpp"
#include "cli/number_text.hpp"
#include "compiler/literal.hpp"
#include "cli/commands.hpp"
#include "cli/diagnostic_output.hpp"
#include "snow/deformation_texel.hpp"
#include "snow/gpu_deformation_map.hpp"
#include "snow/snow_interactors.hpp"

namespace wg {

namespace {

constexpr const char* kUsage = R"(Usage: weathergen bench-snow [--frames N] [--walk-minutes M] [--profile-seconds S]
                            [--store-budget MIB] [--refill-tiles N] [--work-per-frame N]
                            [--device NAME]

Moves N interactors (1, 16, 256, 1024) through the default 1024² deformation map (4 cm
texels); each presses a 0.15 m-radius capsule from its previous to its current position
every frame (60 fps, 1.4 m/s), the worst case: walkers stamp only when a foot lands.
Prints the median GPU time over N frames (default 120, after 10 warm-up frames) of the
stamp and normal dispatches, the same 256 interactors on 512² and 2048² maps, the global
refill pass; then every frame's snow work (recentring, stamps, refill) for S simulated
seconds (default 60) of a player with 16 companions and a vehicle in heavy snowfall, as
median and worst frame; then the same walk for M simulated minutes (default 10) in calm
weather with the window following, and the memory of the map and of the print store
(whose budget --store-budget sets, default 16 MiB). --refill-tiles sets how many tiles
with prints a frame refills at most (default 4), --work-per-frame the profile's budget
of shader invocations a frame (default 8192): stamps beyond it wait for the next frames.
)";

constexpr int kWarmUpFrames = 10;
constexpr double kFrameSeconds = 1.0 / 60.0;
constexpr float kWalkSpeed = 1.4f;    // m/s, a brisk walk
constexpr float kBodyRadius = 0.15f;  // a dragged foot or a small body
const snow::SnowCover kCover{0.3f};
// Refill two quanta per call: every call dispatches.
constexpr double kTwoQuantaPerSecond = 2.0 * snow::kDepthQuantum;
// Heavy snowfall: prints fill at ~5 cm/h (docs/deformable-snow.md), a quantum every 7.2 s.
constexpr double kHeavySnowRefill = 0.05 / 3600.0;
constexpr int kCompanions = 16;
constexpr float kLegLength = 120.f, kLegGap = 30.f;  // the walk's serpentine, metres

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0.0 : (v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]));
}

// Median GPU milliseconds of `frames` frames of `count` movers on a map of `resolution`.
double measureMovers(vk::Context& ctx, std::uint32_t resolution, int count, int frames) {
  snow::WindowSettings settings;
  settings.resolution = resolution;
  snow::GpuDeformationMap map(ctx, settings);
  std::mt19937 random(1234);  // fixed: every run moves the same interactors
  float half = 0.45f * map.window().extent();
  std::uniform_real_distribution<float> position(-half, half), angle(0.f, 6.2831853f);
  std::vector<glm::vec2> at(count), velocity(count);
  for (int i = 0; i < count; ++i) {
    at[i] = {position(random), position(random)};
    float a = angle(random);
    velocity[i] = glm::vec2(std::cos(a), std::sin(a)) * kWalkSpeed;
  }
  std::vector<double> times;
  std::vector<snow::Stamp> stamps(count);
  for (int f = 0; f < kWarmUpFrames + frames; ++f) {
    for (int i = 0; i < count; ++i) {
      glm::vec2 next = at[i] + velocity[i] * float(kFrameSeconds);
      if (std::abs(next.x) > half || std::abs(next.y) > half) velocity[i] = -velocity[i];  // stay inside
      stamps[i] = snow::capsule(at[i], next, kBodyRadius, kCover, kCover.depth);
      at[i] = next;
    }
    double ms = map.apply(stamps);
    if (f >= kWarmUpFrames) times.push_back(ms);
  }
  return median(times);
}

// Median GPU milliseconds of one frame's refill on a map with prints in every tile:
// refillTilesPerFrame tiles and their normals (the whole map before refill was spread).
double measureRefill(vk::Context& ctx, const snow::WindowSettings& settings, int frames) {
  snow::GpuDeformationMap map(ctx, settings);
  std::vector<snow::Stamp> everywhere;
  float tile = map.window().texelSize() * float(map.window().tileTexels()), half = 0.5f * map.window().extent();
  for (float z = -half + 0.5f * tile; z < half; z += tile)
    for (float x = -half + 0.5f * tile; x < half; x += tile)
      everywhere.push_back(snow::capsule({x, z}, {x, z}, 0.2f, kCover, kCover.depth));
  map.apply(everywhere);
  std::vector<double> times;
  for (int f = 0; f < kWarmUpFrames + frames; ++f) {
    double ms = map.refill(kTwoQuantaPerSecond, 1.0);
    if (f >= kWarmUpFrames) times.push_back(ms);
  }
  return median(times);
}

// A serpentine of legs `leg` metres long, `gap` apart, long enough for `length` metres.
std::vector<glm::vec2> serpentine(float length, float leg, float gap, glm::vec2 offset) {
  std::vector<glm::vec2> points{offset};
  glm::vec2 at = offset;
  for (int i = 0; length > 0.f; ++i) {
    at.x += (i % 2 == 0 ? leg : -leg);
    points.push_back(at);
    at.y += gap;
    points.push_back(at);
    length -= leg + gap;
  }
  return points;
}

// The player (whom the window follows), 16 companions on parallel paths and a vehicle,
// on a serpentine long enough for `seconds`.
struct SnowWalk {
  std::vector<snow::Walker> walkers;
  snow::Vehicle car;

  explicit SnowWalk(double seconds) {
    const float length = float(seconds) * kWalkSpeed + kLegLength;
    for (int i = 0; i <= kCompanions; ++i) {
      snow::Walker w;
      // Companions walk beside the player, up to 8 m either side, a little faster or slower.
      float side = i == 0 ? 0.f : float((i + 1) / 2) * (i % 2 ? 1.f : -1.f);
      float speed = kWalkSpeed * (1.f + 0.02f * float(i % 5 - 2));
      w.path = snow::ScriptedPath(serpentine(length, kLegLength, kLegGap, {0.f, side}), speed);
      walkers.push_back(w);
    }
    car.path = snow::ScriptedPath(serpentine(length, kLegLength, kLegGap, {0.f, -10.f}), kWalkSpeed);
  }
  void stamps(double t0, double t1, std::vector<snow::Stamp>& out) const {
    out.clear();
    for (const auto& w : walkers) snow::walkerStamps(w, t0, t1, kCover, out);
    snow::vehicleStamps(car, t0, t1, kCover, out);
  }
  glm::vec2 player(double t) const { return walkers.front().path.pointAt(walkers.front().path.distanceAt(t)); }
};

// The walk for `minutes` of simulated time at 60 frames per second, in calm weather (no
// refill: every print is kept, the store's worst case).
int runSnowWalk(vk::Context& ctx, const snow::WindowSettings& settings, double minutes) {
  const double seconds = minutes * 60.0;
  const std::size_t storeBudget = settings.printStoreBudget;
  snow::GpuDeformationMap map(ctx, settings);
  SnowWalk walk(seconds);
  std::size_t stamps = 0, peakStore = 0;
  std::vector<snow::Stamp> frame;
  const auto frames = static_cast<long>(seconds / kFrameSeconds);
  for (long f = 0; f < frames; ++f) {
    double t0 = double(f - 1) * kFrameSeconds, t1 = double(f) * kFrameSeconds;
    walk.stamps(t0, t1, frame);
    map.follow(walk.player(t1));
    map.apply(frame);
    stamps += frame.size();
    peakStore = std::max(peakStore, map.store().memoryBytes());
  }
  constexpr double kMiB = 1024.0 * 1024.0;
  std::printf("\n%.0f simulated minutes (%ld frames at 60 fps, %zu stamps; %d walkers and a vehicle, %.0f m each):\n\n",
              minutes, frames, stamps, kCompanions + 1, seconds * kWalkSpeed);
  std::printf("| what | memory |\n|---|---|\n");
  std::printf("| deformation map (heights + normals, 1024², 2 x 32 bit) | %.2f MiB |\n", map.mapBytes() / kMiB);
  std::printf("| surface image the snow layer samples (RGBA16F) | %.2f MiB |\n", map.surfaceImage().byteSize() / kMiB);
  std::printf("| print store: %zu tiles of 32² texels, %zu dropped (budget %.2f MiB) | %.2f MiB (peak %.2f MiB) |\n",
              map.store().tileCount(), map.store().tilesDropped(), storeBudget / kMiB, map.store().memoryBytes() / kMiB,
              peakStore / kMiB);
  return kExitOk;
}

// Every frame's snow work in heavy snowfall, recorded as an engine records it (one
// submit a frame within the work budget: recentring, stamps, refill, entered tiles'
// normals), as GPU milliseconds, wall time, and shader invocations (the work itself,
// free of timing noise; on lavapipe the GPU is the CPU).
void measureFrameProfile(vk::Context& ctx, const snow::WindowSettings& settings, double seconds) {
  snow::GpuDeformationMap map(ctx, settings);
  SnowWalk walk(seconds);
  std::vector<snow::Stamp> frame;
  std::vector<double> gpu, wall, work;
  std::size_t mostQueued = 0;
  const auto frames = static_cast<long>(seconds / kFrameSeconds);
  for (long f = 0; f < frames; ++f) {
    double t0 = double(f - 1) * kFrameSeconds, t1 = double(f) * kFrameSeconds;
    walk.stamps(t0, t1, frame);
    std::uint64_t before = map.invocations();
    auto start = std::chrono::steady_clock::now();
    double ms = map.frame({.camera = walk.player(t1),
                           .stamps = frame,
                           .refillMetresPerSecond = kHeavySnowRefill,
                           .seconds = kFrameSeconds});
    double elapsed = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    mostQueued = std::max(mostQueued, map.queuedStamps());
    if (f < kWarmUpFrames) continue;
    gpu.push_back(ms);
    wall.push_back(elapsed);
    work.push_back(double(map.invocations() - before));
  }
  auto row = [](const char* what, std::vector<double> v, const char* format) {
    double mid = median(v);
    auto over = std::count_if(v.begin(), v.end(), [&](double x) { return x > 2.0 * mid; });
    std::sort(v.begin(), v.end());
    double p99 = v.empty() ? 0.0 : v[v.size() * 99 / 100], worst = v.empty() ? 0.0 : v.back();
    std::printf("| %s | ", what);
    for (double x : {mid, p99, worst, mid > 0.0 ? worst / mid : 0.0}) {
      std::printf(format, x);
      std::printf(" | ");
    }
    std::printf("%ld of %zu |\n", long(over), v.size());
  };
  std::printf("\nEvery frame's snow work over %.0f simulated seconds of the walk in heavy snowfall (refill 5 cm/h), "
              "one submit a frame, a budget of %u invocations and at most %u refilled tiles a frame:\n\n",
              seconds, settings.workPerFrame, settings.refillTilesPerFrame);
  std::printf("| per frame | median | 99th percentile | worst | worst / median | frames over 2x median |\n"
              "|---|---|---|---|---|---|\n");
  row("shader invocations (the work)", work, "%.0f");
  row("GPU ms (timestamps)", gpu, "%.4f");
  row("wall ms of the submit and wait", wall, "%.4f");
  std::printf("\nStamps waiting for a later frame: at most %zu.\n", mostQueued);
}

struct BenchSnowOptions {
  std::string device;
  int frames = 120;
  double walkMinutes = 10.0;
  double profileSeconds = 60.0;
  double storeBudgetMiB = double(snow::WindowSettings{}.printStoreBudget) / (1024.0 * 1024.0);
  double refillTiles = snow::WindowSettings{}.refillTilesPerFrame;
  double workPerFrame = snow::WindowSettings{}.workPerFrame;
  bool help = false;
};

// "" or the usage message; `out` is positive and at most `most`.
std::string setPositive(const std::string& v, const char* option, double most, double& out) {
  out = parseNumberText(v).value_or(0.0);
  if (!(out > 0.0) || !(out <= most)) {
    char text[96];
    std::snprintf(text, sizeof text, "%s takes a positive number up to %g", option, most);
    return text;
  }
  return "";
}

// "" or the usage message; `out` is a whole number from 1 to `most`.
std::string setWholeNumber(const std::string& v, const char* option, double most, double& out) {
  std::string error = setPositive(v, option, most, out);
  return error.empty() && out != std::floor(out) ? std::string(option) + " takes a whole number" : error;
}

OptionTable benchSnowOptionTable(BenchSnowOptions& o) {
  return {.options = {
      {"--frames", "", "N", "frames measured per load (default 120)",
       [&o](const std::string& v) { return setFrameCount(v, o.frames); }},
      {"--walk-minutes", "", "M", "simulated minutes of the walk (default 10)",
       [&o](const std::string& v) { return setPositive(v, "--walk-minutes", 1e4, o.walkMinutes); }},
      {"--profile-seconds", "", "S", "simulated seconds of the per-frame profile (default 60)",
       [&o](const std::string& v) { return setPositive(v, "--profile-seconds", 3600.0, o.profileSeconds); }},
      {"--store-budget", "", "MIB", "print store budget in MiB (default 16)",
       [&o](const std::string& v) { return setPositive(v, "--store-budget", 1e6, o.storeBudgetMiB); }},
      {"--refill-tiles", "", "N", "tiles refilled per frame at most (default 4)",
       [&o](const std::string& v) { return setWholeNumber(v, "--refill-tiles", 1024, o.refillTiles); }},
      {"--work-per-frame", "", "N", "shader invocations a frame's snow work may take (default 8192)",
       [&o](const std::string& v) { return setWholeNumber(v, "--work-per-frame", 1 << 24, o.workPerFrame); }},
      {"--device", "", "NAME", "Vulkan device, as render takes it", storeValue(o.device)},
      {"--help", "-h", "", "this help", storeFlag(o.help), true},
  }};
}

// The movers on the default map, then 256 of them on smaller and larger maps.
void measureMoverTable(vk::Context& ctx, int frames) {
  std::printf("| interactors | map | stamps/frame | GPU ms/frame | ms per interactor | vs 1 interactor |\n"
              "|---|---|---|---|---|---|\n");
  double one = 0.0;
  for (int count : {1, 16, 256, 1024}) {
    double ms = measureMovers(ctx, 1024, count, frames);
    if (count == 1) one = ms;
    std::printf("| %d | 1024² | %d | %.4f | %.5f | %.2fx |\n", count, count, ms, ms / count, one > 0 ? ms / one : 0.0);
    std::fflush(stdout);
  }
  for (std::uint32_t resolution : {512u, 2048u}) {
    double ms = measureMovers(ctx, resolution, 256, frames);
    std::printf("| 256 | %u² | 256 | %.4f | %.5f | %.2fx |\n", resolution, ms, ms / 256, one > 0 ? ms / one : 0.0);
    std::fflush(stdout);
  }
}

}  // namespace

int runBenchSnowCommand(int argc, char** argv) {
  BenchSnowOptions o;
  if (auto exit = parseBenchOptions(benchSnowOptionTable(o), argc, argv, o.help, kUsage)) return *exit;
  std::string error;
  auto ctx = vk::Context::create({o.device, false}, error);
  if (!ctx) return deviceUnavailable(error, o.device);
  std::printf("Device: %s. Median of %d frames (after %d warm-up), stamps + normals, GPU timestamps.\n\n",
              ctx->deviceName().c_str(), o.frames, kWarmUpFrames);
  measureMoverTable(*ctx, o.frames);
  snow::WindowSettings settings;
  settings.printStoreBudget = std::size_t(o.storeBudgetMiB * 1024.0 * 1024.0);
  settings.refillTilesPerFrame = std::uint32_t(o.refillTiles);
  settings.workPerFrame = std::uint32_t(o.workPerFrame);
  std::printf("\nRefill on a map with prints in every tile (%u tiles a frame and their normals): %.4f ms\n",
              settings.refillTilesPerFrame, measureRefill(*ctx, settings, o.frames));
  measureFrameProfile(*ctx, settings, o.profileSeconds);
  return runSnowWalk(*ctx, settings, o.walkMinutes);
}

}  // namespace wg
