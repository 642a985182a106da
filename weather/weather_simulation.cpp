#include "weather/weather_simulation.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace wg {
namespace {

// Fresh-snow density fit, Hedstrom & Pomeroy (1998): rho(T) = a + b exp(T / c) kg/m^3.
constexpr double kSnowDensityMin = 67.92;    // kg/m^3, the cold limit
constexpr double kSnowDensityWarm = 51.25;   // kg/m^3 added as T approaches 0 °C
constexpr double kSnowDensityScaleC = 2.59;  // °C
// Tetens saturation vapour pressure over water: e_s(T) = 0.6108 exp(a T / (T + b)) kPa.
// Only ratios are used, so the 0.6108 kPa prefactor cancels.
constexpr double kTetensA = 17.27;
constexpr double kTetensB = 237.3;  // °C
// Temperature a NaN input is replaced with: at the freezing point no thermal rate acts.
constexpr double kNeutralTemperatureC = 0.0;
// Sun melt: the sun's height (sin of its elevation) over which it rises from nothing
// (on the horizon, grazing every face) to full strength, about 6 degrees.
constexpr double kSunMeltElevationRamp = 0.1;

double smoothstep(double e0, double e1, double x) {
  const double t = std::clamp((x - e0) / (e1 - e0), 0.0, 1.0);
  return t * t * (3.0 - 2.0 * t);
}

double clampOr(double x, double lo, double hi, double fallback) {
  return std::isnan(x) ? fallback : std::clamp(x, lo, hi);
}

// Rates: finite and >= 0, anything else is treated as "this process is off".
double rateOrZero(double x) { return std::isfinite(x) && x > 0.0 ? x : 0.0; }

WeatherConditions sanitized(const WeatherConditions& c) {
  WeatherConditions s = c;
  s.temperature = static_cast<float>(
      clampOr(c.temperature, kMinTemperatureC, kMaxTemperatureC, kNeutralTemperatureC));
  s.precipitation = static_cast<float>(clampOr(c.precipitation, 0.0, 1.0, 0.0));
  s.windIntensity = static_cast<float>(clampOr(c.windIntensity, 0.0, 1.0, 0.0));
  return s;
}

// Every WeatherRates field, by kind; the static_assert fails when a field is added to
// the struct but not here.
constexpr std::array kRateFields{&WeatherRates::snowAccumulation,
                                 &WeatherRates::snowMeltPerDegree,
                                 &WeatherRates::rainMeltPerDegree,
                                 &WeatherRates::wetting,
                                 &WeatherRates::wetEvaporation,
                                 &WeatherRates::snowWaterPerFilm,
                                 &WeatherRates::evaporationPerWindMs,
                                 &WeatherRates::referenceWindMs,
                                 &WeatherRates::windSpeedAtFullIntensity,
                                 &WeatherRates::puddleFill,
                                 &WeatherRates::puddleInfiltration,
                                 &WeatherRates::puddleEvaporation,
                                 &WeatherRates::rainMemoryResponse,
                                 &WeatherRates::mossGrowth,
                                 &WeatherRates::mossDrying,
                                 &WeatherRates::freezePerDegree,
                                 &WeatherRates::thawPerDegree};
constexpr std::array kTemperatureFields{&WeatherRates::sunMeltColdC, &WeatherRates::sunMeltFullC,
                                        &WeatherRates::rainAboveC, &WeatherRates::snowBelowC,
                                        &WeatherRates::snowReferenceC,
                                        &WeatherRates::evaporationReferenceC};
static_assert(sizeof(WeatherRates) ==
                  (kRateFields.size() + kTemperatureFields.size()) * sizeof(double),
              "sanitize every WeatherRates field");

WeatherRates sanitized(const WeatherRates& r) {
  const WeatherRates defaults;
  WeatherRates s = r;
  for (auto rate : kRateFields) s.*rate = rateOrZero(r.*rate);
  for (auto temperature : kTemperatureFields) {
    s.*temperature =
        clampOr(r.*temperature, kMinTemperatureC, kMaxTemperatureC, defaults.*temperature);
  }
  return s;
}

double freshSnowDensity(double temperatureC) {
  return kSnowDensityMin + kSnowDensityWarm * std::exp(temperatureC / kSnowDensityScaleC);
}

// e_s(T) / e_s(reference); T and reference are in [-60, 60], far from the pole at -237.3.
double vapourPressureRatio(double temperatureC, double referenceC) {
  auto exponent = [](double t) { return kTetensA * t / (t + kTetensB); };
  return std::exp(exponent(temperatureC) - exponent(referenceC));
}

double snowFractionSanitized(double t, const WeatherRates& r) {
  const double width = r.rainAboveC - r.snowBelowC;
  // A tuned-away band degenerates to the thesis's hard switch (and loses continuity).
  if (!(width > 0.0)) return t <= r.snowBelowC ? 1.0 : 0.0;
  const double x = std::clamp((r.rainAboveC - t) / width, 0.0, 1.0);
  return x * x * (3.0 - 2.0 * x);  // smoothstep: C1, so rates have no kink at the band ends
}

double evaporationFactorSanitized(const WeatherConditions& c, const WeatherRates& r) {
  const double windMs = c.windIntensity * r.windSpeedAtFullIntensity;
  const double wind =
      (1.0 + r.evaporationPerWindMs * windMs) / (1.0 + r.evaporationPerWindMs * r.referenceWindMs);
  const double dryAir = 1.0 - c.precipitation;
  return vapourPressureRatio(c.temperature, r.evaporationReferenceC) * wind * dryAir;
}

WeatherDynamics dynamicsSanitized(const WeatherConditions& c, const WeatherRates& r) {
  const double snowShare = snowFractionSanitized(c.temperature, r);
  const double snowfall = c.precipitation * snowShare;
  const double rainfall = c.precipitation * (1.0 - snowShare);
  // Degrees above / below freezing: continuous in T (a kink, no jump, at 0 °C).
  const double warmth = std::max(0.0, static_cast<double>(c.temperature));
  const double chill = std::max(0.0, -static_cast<double>(c.temperature));
  const double drying = evaporationFactorSanitized(c, r);
  const double coldBoost = freshSnowDensity(r.snowReferenceC) / freshSnowDensity(c.temperature);

  WeatherDynamics d;
  d.snow.gain = r.snowAccumulation * snowfall * coldBoost;
  d.snow.loss = (r.snowMeltPerDegree + r.rainMeltPerDegree * rainfall) * warmth;

  d.wetness.gain = r.wetting * rainfall;
  d.wetness.loss = r.wetEvaporation * drying;
  // Meltwater wets the snow-covered fraction at the rate it is released, but can hold
  // it no wetter than fully wet: capped at the evaporation it has to replace.
  d.wetness.feed = std::min(d.wetness.loss, r.snowWaterPerFilm * d.snow.loss);

  // Exponential approach of the memory to the current rainfall intensity.
  d.rainMemory.gain = r.rainMemoryResponse * rainfall;
  d.rainMemory.loss = r.rainMemoryResponse * (1.0 - rainfall);

  // Moss follows the rain memory (loss and feed share mossGrowth) and dries on top.
  d.moss.feed = r.mossGrowth;
  d.moss.loss = r.mossGrowth + r.mossDrying * drying;

  d.frost.gain = r.freezePerDegree * chill;
  d.frost.loss = r.thawPerDegree * warmth;

  d.puddles.gain = r.puddleFill * rainfall;
  d.puddles.loss = r.puddleInfiltration + r.puddleEvaporation * drying;
  return d;
}

// Integral over [0, h] of e^(-rate (h - s)) ds = (1 - e^(-rate h)) / rate, or h when
// rate is 0; expm1 keeps it exact for tiny rate * h, and it stays finite for huge ones.
double decayIntegral(double rate, double h) {
  return rate > 0.0 ? -std::expm1(-rate * h) / rate : h;
}

// Integral over [0, h] of e^(-a (h - s)) e^(-b s) ds = (e^(-b h) - e^(-a h)) / (a - b):
// symmetric in a, b, and factored around the slower rate so it neither cancels
// catastrophically nor divides by zero when a == b.
double crossIntegral(double a, double b, double h) {
  return std::exp(-std::min(a, b) * h) * decayIntegral(std::abs(a - b), h);
}

// A level moving freely under its own dynamics: x(t) = target + offset e^(-rate t).
struct Trajectory {
  double target = 0.0;
  double offset = 0.0;
  double rate = 0.0;
};

Trajectory trajectoryOf(double x0, const LevelDynamics& d) {
  const double rate = d.gain + d.loss;
  if (!(rate > 0.0)) return {x0, 0.0, 0.0};  // nothing acts: the level holds
  const double target = d.gain / rate;
  return {target, x0 - target, rate};
}

// Exact x(h) for x' = gain (1 - x) - loss x + feed y(t), y following `source`, by
// variation of constants with L = gain + loss:
//   x(h) = x0 e^(-L h) + (gain + feed y_target) decayIntegral(L, h)
//        + feed y_offset crossIntegral(L, source.rate, h).
// Being the exact flow of a linear ODE, it composes: advancing h1 then h2 equals h1 + h2.
double advanceLevel(double x0, const LevelDynamics& d, const Trajectory& source, double h) {
  const double lambda = d.gain + d.loss;
  const double forced = (d.gain + d.feed * source.target) * decayIntegral(lambda, h);
  const double transient = d.feed * source.offset * crossIntegral(lambda, source.rate, h);
  return x0 * std::exp(-lambda * h) + forced + transient;
}

float storeLevel(double x, float previous) {
  // The exact solution stays in [0, 1]; the clamp only absorbs rounding, and the
  // finiteness check only absurd tuned rates (1e300) that overflow.
  return static_cast<float>(
      std::clamp(std::isfinite(x) ? x : static_cast<double>(previous), 0.0, 1.0));
}

float sanitizedLevel(float x) { return static_cast<float>(clampOr(x, 0.0, 1.0, 0.0)); }

}  // namespace

float sunMeltStrength(const WeatherConditions& conditions, const WeatherRates& rates) {
  const WeatherConditions c = sanitized(conditions);
  const WeatherRates r = sanitized(rates);
  const auto& d = c.sunDirection;
  const double length = std::sqrt(double(d[0]) * d[0] + double(d[1]) * d[1] + double(d[2]) * d[2]);
  if (!(length > 0.0) || !std::isfinite(length)) return 0.f;
  const double elevation = smoothstep(0.0, kSunMeltElevationRamp, double(d[1]) / length);
  const double warmth = r.sunMeltFullC > r.sunMeltColdC
                            ? smoothstep(r.sunMeltColdC, r.sunMeltFullC, c.temperature)
                            : (c.temperature >= r.sunMeltFullC ? 1.0 : 0.0);
  const double light = clampOr(c.sunIntensity, 0.0, 1.0, 0.0);
  return static_cast<float>(light * elevation * warmth);
}

double snowFraction(double temperatureC, const WeatherRates& rates) {
  return snowFractionSanitized(
      clampOr(temperatureC, kMinTemperatureC, kMaxTemperatureC, kNeutralTemperatureC),
      sanitized(rates));
}

double evaporationFactor(const WeatherConditions& conditions, const WeatherRates& rates) {
  return evaporationFactorSanitized(sanitized(conditions), sanitized(rates));
}

WeatherDynamics weatherDynamics(const WeatherConditions& conditions, const WeatherRates& rates) {
  return dynamicsSanitized(sanitized(conditions), sanitized(rates));
}

void advanceWeather(WeatherState& state, double seconds, const WeatherRates& rates) {
  WeatherLevels& l = state.levels;
  for (float WeatherLevels::*level : kLevelMembers) l.*level = sanitizedLevel(l.*level);
  l.rainMemory = sanitizedLevel(l.rainMemory);
  if (!std::isfinite(state.time)) state.time = 0.0;
  if (!std::isfinite(seconds) || seconds <= 0.0) return;

  const WeatherDynamics d = weatherDynamics(state.conditions, rates);
  const Trajectory none;  // feed is 0 for the free levels; any source would do
  // Sources first, from their start-of-step values: their trajectory over the step is
  // what drives the fed level.
  const Trajectory snow = trajectoryOf(l.snow, d.snow);
  const Trajectory rainMemory = trajectoryOf(l.rainMemory, d.rainMemory);

  const WeatherLevels before = l;
  l.snow = storeLevel(advanceLevel(before.snow, d.snow, none, seconds), before.snow);
  l.wetness = storeLevel(advanceLevel(before.wetness, d.wetness, snow, seconds), before.wetness);
  l.rainMemory =
      storeLevel(advanceLevel(before.rainMemory, d.rainMemory, none, seconds), before.rainMemory);
  l.moss = storeLevel(advanceLevel(before.moss, d.moss, rainMemory, seconds), before.moss);
  l.frost = storeLevel(advanceLevel(before.frost, d.frost, none, seconds), before.frost);
  l.puddles = storeLevel(advanceLevel(before.puddles, d.puddles, none, seconds), before.puddles);

  const double end = state.time + seconds;
  if (std::isfinite(end)) state.time = end;
}

void WeatherSimulation::step(WeatherState& state, double realSeconds) const {
  const double scale = std::isfinite(timeScale) && timeScale > 0.0 ? timeScale : 0.0;
  advanceWeather(state, realSeconds * scale, rates);
}

}  // namespace wg
