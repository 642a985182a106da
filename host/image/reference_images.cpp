#include "host/image/reference_images.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

#include "compiler/diagnostic.hpp"
#include "compiler/json_document.hpp"
#include "host/image/png_file.hpp"

namespace wg::image {

namespace {

using nlohmann::json;

constexpr const char* kDefaultKey = "default";
constexpr const char* kImagesKey = "images";
constexpr const char* kMaxErrorKey = "maxError";
constexpr const char* kMeanErrorKey = "meanError";
constexpr char kCommentPrefix = '_';  // "_comment" etc.: JSON has no comments
constexpr double kMinTolerance = 0.0;
constexpr double kMaxTolerance = 1.0;  // errors are fractions of full scale

std::string formatNumber(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.4g", value);
  return buffer;
}

// Validates the parsed document; the first problem found stops the parse.
class ToleranceParser {
 public:
  explicit ToleranceParser(const JsonDocument& document) : document_(document) {}

  std::optional<ToleranceTable> parse() {
    const json& root = document_.root();
    if (!expectObject(root, "")) return std::nullopt;
    if (!checkKeys(root, "", {kDefaultKey, kImagesKey})) return std::nullopt;
    const std::string defaultPointer = appendPointer("", kDefaultKey);
    if (!root.contains(kDefaultKey)) return fail("", "missing field 'default'");
    ToleranceTable table;
    if (!parseTolerance(root.at(kDefaultKey), defaultPointer, nullptr, table.defaults)) return std::nullopt;
    if (!root.contains(kImagesKey)) return table;
    const json& images = root.at(kImagesKey);
    const std::string imagesPointer = appendPointer("", kImagesKey);
    if (!expectObject(images, imagesPointer)) return std::nullopt;
    for (const auto& [name, entry] : images.items()) {
      if (isComment(name)) continue;
      const std::string pointer = appendPointer(imagesPointer, name);
      if (name.empty()) return fail(pointer, "image names must not be empty");
      Tolerance tolerance;
      if (!parseTolerance(entry, pointer, &table.defaults, tolerance)) return std::nullopt;
      table.perImage.emplace(name, tolerance);
    }
    return table;
  }

  const std::string& error() const { return error_; }

 private:
  const JsonDocument& document_;
  std::string error_;

  static bool isComment(const std::string& key) { return !key.empty() && key.front() == kCommentPrefix; }

  std::nullopt_t fail(const std::string& pointer, const std::string& message) {
    const SourceLocation where = document_.locate(pointer);
    error_ = document_.file() + ":" + std::to_string(where.line) + ":" + std::to_string(where.column) +
             ": " + (pointer.empty() ? std::string("(document root)") : pointer) + ": " + message;
    return std::nullopt;
  }

  bool expectObject(const json& value, const std::string& pointer) {
    if (value.is_object()) return true;
    fail(pointer, std::string("expected an object, got ") + value.type_name());
    return false;
  }

  bool checkKeys(const json& object, const std::string& pointer, const std::vector<std::string_view>& known) {
    for (const auto& [key, value] : object.items()) {
      if (isComment(key) || std::find(known.begin(), known.end(), key) != known.end()) continue;
      std::string message = "unknown field '" + key + "'";
      if (std::string hint = suggestClosest(key, known); !hint.empty()) message += "; " + hint;
      fail(appendPointer(pointer, key), message);
      return false;
    }
    return true;
  }

  // Reads one field into `out`; absent is fine when there is an inherited value.
  bool parseField(const json& object, const std::string& pointer, const char* key, const double* inherited,
                  double& out) {
    const std::string fieldPointer = appendPointer(pointer, key);
    if (!object.contains(key)) {
      if (inherited) {
        out = *inherited;
        return true;
      }
      fail(pointer, "missing field '" + std::string(key) + "'");
      return false;
    }
    const json& value = object.at(key);
    const bool inRange = value.is_number() && std::isfinite(value.get<double>()) &&
                         value.get<double>() >= kMinTolerance && value.get<double>() <= kMaxTolerance;
    if (!inRange) {
      fail(fieldPointer, "expected a number in [0, 1], got " + value.dump());
      return false;
    }
    out = value.get<double>();
    return true;
  }

  bool parseTolerance(const json& value, const std::string& pointer, const Tolerance* inherited, Tolerance& out) {
    return expectObject(value, pointer) && checkKeys(value, pointer, {kMaxErrorKey, kMeanErrorKey}) &&
           parseField(value, pointer, kMaxErrorKey, inherited ? &inherited->maxError : nullptr, out.maxError) &&
           parseField(value, pointer, kMeanErrorKey, inherited ? &inherited->meanError : nullptr, out.meanError);
  }
};

std::string regenerateHint() {
  return "if the new rendering is intended, run " + std::string(kUpdateReferenceCommand) +
         " and review the changed images";
}

std::string sizeText(const Image& image) {
  return std::to_string(image.width) + "x" + std::to_string(image.height);
}

}  // namespace

Tolerance ToleranceTable::lookup(const std::string& name) const {
  auto it = perImage.find(name);
  return it == perImage.end() ? defaults : it->second;
}

std::optional<ToleranceTable> parseToleranceTable(const std::string& file, const std::string& text,
                                                  std::string& error) {
  DiagnosticList diagnostics;
  std::optional<JsonDocument> document = parseJsonDocument(file, text, diagnostics);
  if (!document) {
    // Malformed JSON, a duplicate key or a size limit: there is no pointer to blame
    // beyond what the diagnostic locates.
    const Diagnostic& d = diagnostics.items().front();
    error = file + ":" + std::to_string(d.location.line) + ":" + std::to_string(d.location.column) + ": " +
            (d.location.pointer.empty() ? std::string() : d.location.pointer + ": ") + d.message;
    return std::nullopt;
  }
  ToleranceParser parser(*document);
  std::optional<ToleranceTable> table = parser.parse();
  if (!table) error = parser.error();
  return table;
}

std::optional<ToleranceTable> loadToleranceTable(const std::string& path, std::string& error) {
  std::ifstream in(path, std::ios::binary);
  if (!in || std::filesystem::is_directory(path)) {
    error = path + ": cannot read the tolerance file";
    return std::nullopt;
  }
  std::ostringstream text;
  text << in.rdbuf();
  return parseToleranceTable(path, text.str(), error);
}

ReferenceCheck checkAgainstReference(const Image& rendered, const std::string& referencePath,
                                     const Tolerance& tolerance) {
  ReferenceCheck check;
  check.tolerance = tolerance;
  if (!rendered.valid()) {
    check.message = "the rendered image is empty; nothing to compare with " + referencePath;
    return check;
  }
  std::error_code ignored;
  if (!std::filesystem::exists(referencePath, ignored)) {
    check.message = "reference image " + referencePath + " does not exist; create it with " +
                    std::string(kUpdateReferenceCommand) + " and review it before committing";
    return check;
  }
  std::string readError;
  std::optional<Image> reference = readPng(referencePath, readError);
  if (!reference) {
    check.message = "cannot read reference image: " + readError + "; regenerate it with " +
                    std::string(kUpdateReferenceCommand);
    return check;
  }
  check.difference = compareImages(rendered, *reference, tolerance.maxError);
  if (check.difference.sizeMismatch) {
    check.message = "rendered image is " + sizeText(rendered) + " but reference " + referencePath + " is " +
                    sizeText(*reference) + "; " + regenerateHint();
    return check;
  }
  const bool maxOk = check.difference.maxError <= tolerance.maxError;
  const bool meanOk = check.difference.meanError <= tolerance.meanError;
  check.passed = maxOk && meanOk;
  check.message = referencePath + ": max error " + formatNumber(check.difference.maxError) +
                  (maxOk ? " <= " : " > ") + formatNumber(tolerance.maxError) + " (" +
                  std::to_string(check.difference.pixelsOverThreshold) + " pixels over), mean error " +
                  formatNumber(check.difference.meanError) + (meanOk ? " <= " : " > ") +
                  formatNumber(tolerance.meanError);
  if (!check.passed) check.message += "; " + regenerateHint();
  return check;
}

}  // namespace wg::image
