// Advances the accumulated weather levels (snow, wetness, moss, frost, puddles) over
// time from temperature, precipitation and wind. See docs/weather-simulation.md for the
// model, where every default below comes from, and why the result is continuous.
#pragma once
#include "weather/weather_state.hpp"

namespace wg {

// Reference quantities the default rates are derived from.
namespace weather_physics {
inline constexpr double kSecondsPerHour = 3600.0;
inline constexpr double kSecondsPerDay = 86400.0;
// e^-3 ≈ 0.05: three e-folding times take an exponential approach 95 % of the way.
inline constexpr double kEFoldsTo95Percent = 3.0;
// Rate (1/s) of an exponential approach that gets 95 % of the way in `hours`.
constexpr double rateTo95PercentIn(double hours) {
  return kEFoldsTo95Percent / (hours * kSecondsPerHour);
}
// Rate (1/s) of an exponential approach that gets 63 % (1 - 1/e) of the way in `hours`.
constexpr double rateWithEFoldingTime(double hours) { return 1.0 / (hours * kSecondsPerHour); }

// precipitation = 1 means this much rain; the AMS calls rain above 7.6 mm/h heavy.
inline constexpr double kHeavyRainMmPerHour = 10.0;
// Water in a full visual snow cover: ~10 cm of fresh snow at ~100 kg/m^3 hides the ground.
inline constexpr double kSnowCoverWaterMm = 10.0;
// Water a soaked (not flooded) surface holds as a film.
inline constexpr double kWetFilmWaterMm = 0.5;
// Degree-day melt factor, mm of water per °C above freezing per day; mid-range of the
// 2-8 mm/(°C·day) measured for snow (Hock 2003, "Temperature index melt modelling").
inline constexpr double kDegreeDayFactorMm = 4.0;
// c_water / L_fusion (4.186 kJ/(kg·K) / 333.55 kJ/kg): kg of snow one kg of rain at
// T °C melts, per °C; the sensible heat rain brings to a snowpack.
inline constexpr double kRainMeltPerDegree = 4.186 / 333.55;
}  // namespace weather_physics

// Every tunable constant of the model, with defaults; engines may override any of them.
// Rates are per simulated second.
struct WeatherRates {
  // --- Precipitation phase -------------------------------------------------------
  // All snow at and below snowBelowC, all rain at and above rainAboveC, a smoothstep
  // blend (sleet) between. The thesis: "if temperature is less than or equal to zero
  // rain becomes snowfall" (3.1), so everything at or below 0 °C is snow; the 1 °C band
  // that keeps every rate a continuous function of temperature lies above 0 °C, where
  // real mixed-phase precipitation is observed (about -1 to +3 °C of air temperature).
  double rainAboveC = 1.0;
  double snowBelowC = 0.0;

  // --- Sun melt (eq. 3.5's SunIntensity, see sunMeltStrength) ----------------------
  // Direct sun warms a sunlit snow surface above the air temperature, so sun-facing
  // slopes lose snow (melt and sublimation) in sub-freezing air too; in deep cold that
  // no longer shows. The melt strength rises from 0 at sunMeltColdC to full at
  // sunMeltFullC (smoothstep) and above.
  double sunMeltColdC = -15.0;
  double sunMeltFullC = 0.0;

  // --- Snow ----------------------------------------------------------------------
  // Heavy snowfall (precipitation 1) at snowReferenceC covers 95 % in 2 h: ~2.5-5 cm/h
  // of snow (NWS "heavy") and ~10 cm hides the ground.
  double snowAccumulation = weather_physics::rateTo95PercentIn(2.0);
  double snowReferenceC = -5.0;  // °C at which snowAccumulation holds
  // Colder snowfall accumulates faster: the same water makes fluffier, deeper snow.
  // Scaled by fresh-snow density rho(snowReferenceC) / rho(T), Hedstrom & Pomeroy
  // (1998): rho(T) = 67.92 + 51.25 exp(T / 2.59) kg/m^3 (not tunable; see the .cpp).
  //
  // Degree-day melt per °C above freezing: 4 mm/(°C·day) of a 10 mm full cover, so
  // at +5 °C a full cover is 95 % gone in ~1.5 days, at +15 °C in ~12 h.
  double snowMeltPerDegree = weather_physics::kDegreeDayFactorMm /
                             weather_physics::kSnowCoverWaterMm / weather_physics::kSecondsPerDay;
  // Extra melt per °C under heavy rain: 10 mm/h of rain carries c_w·T/L_f of melting
  // heat, ~3 mm/(°C·day), so heavy rain nearly doubles the dry melt rate.
  double rainMeltPerDegree = weather_physics::kHeavyRainMmPerHour * 24.0 *
                             weather_physics::kRainMeltPerDegree /
                             weather_physics::kSnowCoverWaterMm / weather_physics::kSecondsPerDay;

  // --- Wetness -------------------------------------------------------------------
  // Heavy rain soaks a surface 95 % in ~10 min (the 0.5 mm film takes 3 min of 10 mm/h
  // rain; absorption into porous materials and run-off slow it).
  double wetting = weather_physics::rateTo95PercentIn(10.0 / 60.0);
  // A 0.5 mm film at ~5 mm/day potential evaporation (20 °C, light breeze, dry air)
  // is gone in ~2.4 h.
  double wetEvaporation = weather_physics::rateTo95PercentIn(2.4);
  // A melting full snow cover releases 20 films' worth of water (10 mm / 0.5 mm):
  // meltwater keeps the snow-covered fraction wet once melt outpaces evaporation.
  double snowWaterPerFilm = weather_physics::kSnowCoverWaterMm / weather_physics::kWetFilmWaterMm;

  // --- Drying environment (wetness, puddles, moss) ----------------------------------
  // Evaporation scales with saturation vapour pressure (Tetens), relative to this
  // temperature, at which the drying times above hold.
  double evaporationReferenceC = 20.0;
  // Penman (1948) wind function f(u) = 1 + 0.54 u (u in m/s at 2 m height).
  double evaporationPerWindMs = 0.54;
  double referenceWindMs = 2.0;  // light breeze: the wind the drying times assume
  // windIntensity 1 is the NWS blizzard threshold, 35 mph = 15.6 m/s.
  double windSpeedAtFullIntensity = 15.6;
  // Relative humidity is taken as rising with precipitation: no evaporation under
  // precipitation 1 (not tunable; evaporation scales with 1 - precipitation).

  // --- Puddles -------------------------------------------------------------------
  // Puddles ~2 cm deep (20 mm of water, run-off from around them included) fill 95 % in
  // 3 h of heavy rain, so a passing 30 min shower leaves them about 40 % full.
  double puddleFill = weather_physics::rateTo95PercentIn(3.0);
  // Sealed ground drains standing water slowly: 95 % in 2 days by seepage alone.
  double puddleInfiltration = weather_physics::rateTo95PercentIn(48.0);
  // 20 mm of water at ~5 mm/day potential evaporation (20 °C, light breeze, dry air):
  // an e-folding time of about a day, 95 % in 3 days.
  double puddleEvaporation = weather_physics::rateTo95PercentIn(72.0);

  // --- Moss ----------------------------------------------------------------------
  // The rain memory follows the rainfall intensity with a 6 h e-folding time: a day of
  // rain saturates it (98 %), a 30 min shower reaches only 8 %.
  double rainMemoryResponse = weather_physics::rateWithEFoldingTime(6.0);
  // Moss is poikilohydric: it rehydrates, swells and greens within hours of sustained
  // wetting. It follows the rain memory with a 4 h e-folding time...
  double mossGrowth = weather_physics::rateWithEFoldingTime(4.0);
  // ...and dries back to brown, inconspicuous cushions over ~2 days (95 %) at 20 °C.
  double mossDrying = weather_physics::rateTo95PercentIn(48.0);

  // --- Frost ---------------------------------------------------------------------
  // Freezing per °C below 0: at -5 °C still water freezes over (95 %) in 6 h; Stefan's
  // law gives ~4 cm of ice by then, enough to look solid. Needs no precipitation.
  double freezePerDegree = weather_physics::rateTo95PercentIn(6.0) / 5.0;
  // Thawing per °C above 0: at +5 °C that ice is 95 % gone in a day (~1-2 mm/h of
  // convective melt; sun and rain, not modelled here, speed it up).
  double thawPerDegree = weather_physics::rateTo95PercentIn(24.0) / 5.0;
};

// One level's linear ODE while the conditions hold:
//   x' = gain * (1 - x) - loss * x + feed * source
// where source is another level (snow for wetness, rainMemory for moss). Every term is
// >= 0 and feed <= loss, which keeps x in [0, 1] for any source in [0, 1].
struct LevelDynamics {
  double gain = 0.0;
  double loss = 0.0;
  double feed = 0.0;
  // Bound on |x'| for every x and source in [0, 1]: no step of h moves the level more
  // than maxRate() * h.
  double maxRate() const { return gain + feed > loss ? gain + feed : loss; }
};

struct WeatherDynamics {
  LevelDynamics snow;
  LevelDynamics wetness;  // fed by snow: meltwater
  LevelDynamics moss;     // fed by rainMemory
  LevelDynamics frost;
  LevelDynamics puddles;
  LevelDynamics rainMemory;
};

// Eq. 3.5's SunIntensity derived from the sun and the temperature: the light's
// brightness, times a ramp from 0 with the sun on the horizon to 1 from about 6 degrees
// up, times the temperature ramp of rates.sunMeltColdC..sunMeltFullC. In [0, 1]; the
// default conditions (full sun overhead, 15 °C) give 1.
float sunMeltStrength(const WeatherConditions& conditions, const WeatherRates& rates = {});
// Fraction of precipitation that falls as snow at this temperature: 1 at and below
// rates.snowBelowC, 0 at and above rates.rainAboveC, smoothstep between.
double snowFraction(double temperatureC, const WeatherRates& rates = {});
// Drying speed relative to the reference (20 °C, light breeze, no precipitation):
// vapour pressure ratio * wind function ratio * (1 - precipitation).
double evaporationFactor(const WeatherConditions& conditions, const WeatherRates& rates = {});
// The coefficients of every level's ODE under these conditions. Inputs are clamped
// into range and non-finite ones replaced, so the result is always finite and >= 0.
WeatherDynamics weatherDynamics(const WeatherConditions& conditions,
                                const WeatherRates& rates = {});

// Advances state.levels and state.time by `seconds` of simulated time, holding
// state.conditions constant over the step. The ODEs are solved exactly, so one step of
// h equals n steps of h/n, and no step size can overshoot. Never produces NaN or a
// level outside [0, 1], whatever the input: non-finite or negative `seconds` do
// nothing, garbage levels are reset into range.
void advanceWeather(WeatherState& state, double seconds, const WeatherRates& rates = {});

// The engine-facing stepper: real frame time in, simulated time out.
struct WeatherSimulation {
  WeatherRates rates;
  // Simulated seconds per real second; 60 makes a real minute an hour of weather.
  double timeScale = 1.0;

  // Advances by realSeconds * timeScale simulated seconds (nothing when that product
  // is negative or not finite).
  void step(WeatherState& state, double realSeconds) const;
};

}  // namespace wg
