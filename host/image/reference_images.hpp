// Reference-image tests: a rendered image passes when it is within a tolerance of a
// checked-in PNG. Tolerances live in one JSON file, per image where needed (as in
// Filament's render tests), so loosening one test is a reviewed one-line change.
#pragma once
#include <map>
#include <optional>
#include <string>
#include <string_view>

#include "nodes/texture_image.hpp"
#include "host/image/image_compare.hpp"

namespace wg::image {

inline constexpr std::string_view kToleranceFile = "tests/reference/tolerances.json";
inline constexpr std::string_view kUpdateReferenceCommand = "scripts/update-reference-images.sh";

// Limits on compareImages' maxError and meanError (both in [0, 1]); equal passes.
struct Tolerance {
  double maxError = 0.0;
  double meanError = 0.0;
  bool operator==(const Tolerance&) const = default;
};

struct ToleranceTable {
  Tolerance defaults;
  std::map<std::string, Tolerance> perImage;  // fields an entry omits come from defaults
  // The image's own tolerance, or the defaults.
  Tolerance lookup(const std::string& name) const;
};

// Parses the tolerance file:
//   {"default": {"maxError": 0.25, "meanError": 0.01},
//    "images": {"valley-snowfall-glsl": {"maxError": 0.3, "meanError": 0.03}}}
// "default" needs both fields; an image entry may give just one. Keys starting with
// '_' are comments. Values are numbers in [0, 1]. On failure returns nullopt and sets
// `error` to "file:line:col: /json/pointer: what is wrong".
std::optional<ToleranceTable> parseToleranceTable(const std::string& file, const std::string& text,
                                                  std::string& error);
std::optional<ToleranceTable> loadToleranceTable(const std::string& path, std::string& error);

struct ReferenceCheck {
  bool passed = false;
  ImageDifference difference;  // pixelsOverThreshold counts pixels above tolerance.maxError
  Tolerance tolerance;
  std::string message;  // one line for the test log; names the path and the numbers
};

// Compares `rendered` with the PNG at `referencePath`. A missing or unreadable
// reference, or one of another size, fails with a message naming the command that
// regenerates references (kUpdateReferenceCommand).
ReferenceCheck checkAgainstReference(const Image& rendered, const std::string& referencePath,
                                     const Tolerance& tolerance);

}  // namespace wg::image
