#include "compiler/sampler_state_loader.hpp"

#include <string>
#include <vector>

#include "compiler/diagnostic.hpp"
#include "compiler/literal.hpp"

namespace wg {

namespace {

class SamplerStateLoader {
 public:
  SamplerStateLoader(const std::string& pointer, const std::string& shown, const JsonDocument& doc, DiagnosticList& diags)
      : pointer_(pointer), shown_(shown), doc_(doc), diags_(diags) {}

  bool ok() const { return ok_; }

  // "repeat" for both axes, or ["repeat", "clamp"] for u and v.
  void wrap(const nlohmann::json& j, SamplerState& state) {
    const std::string at = appendPointer(pointer_, "wrap");
    if (j.is_string()) {
      if (auto w = wrapMode(j, at)) state.wrapU = state.wrapV = *w;
      return;
    }
    if (!j.is_array()) {
      wrongKind(at, "'wrap'", "a wrap mode or an array [u, v] of two", j);
      return;
    }
    if (j.size() != 2) {
      report(DiagCode::WrapModeCount, at, {shown_, std::to_string(j.size()) + (j.size() == 1 ? " mode" : " modes")});
      return;
    }
    auto u = wrapMode(j[0], appendPointer(at, 0));
    auto v = wrapMode(j[1], appendPointer(at, 1));
    if (u) state.wrapU = *u;
    if (v) state.wrapV = *v;
  }

  // "linear" for both directions, or {"min": "linear", "mag": "nearest"}; a direction
  // left out is linear.
  void filter(const nlohmann::json& j, SamplerState& state) {
    const std::string at = appendPointer(pointer_, "filter");
    if (j.is_string()) {
      if (auto f = filterMode(j, at)) state.minFilter = state.magFilter = *f;
      return;
    }
    if (!j.is_object()) {
      wrongKind(at, "'filter'", "a filter or an object {\"min\", \"mag\"}", j);
      return;
    }
    for (const auto& [key, value] : j.items()) {
      const std::string keyAt = appendPointer(at, key);
      if (key != "min" && key != "mag") {
        ok_ = false;
        diags_.report(DiagCode::UnknownField, doc_.locateKey(keyAt), {quoteUserText(key), "a filter object has 'min' and 'mag'"});
        continue;
      }
      if (auto f = filterMode(value, keyAt)) (key == "min" ? state.minFilter : state.magFilter) = *f;
    }
  }

  void colorSpace(const nlohmann::json& j, bool procedural, SamplerState& state) {
    const std::string at = appendPointer(pointer_, "colorSpace");
    auto space = choice(j, at, "colour space", {"srgb", "linear"}, parseColorSpace);
    if (space && procedural && *space == ColorSpace::Srgb)
      report(DiagCode::ProceduralSrgb, at, {shown_});
    else if (space)
      state.colorSpace = *space;
  }

 private:
  std::optional<TextureWrap> wrapMode(const nlohmann::json& j, const std::string& at) {
    return choice(j, at, "wrap mode", {"repeat", "clamp", "mirror"}, parseTextureWrap);
  }
  std::optional<TextureFilter> filterMode(const nlohmann::json& j, const std::string& at) {
    return choice(j, at, "filter", {"linear", "nearest"}, parseTextureFilter);
  }

  // One of a setting's spellings, read by `parse`.
  template <class T>
  std::optional<T> choice(const nlohmann::json& j, const std::string& at, const std::string& noun,
                          const std::vector<std::string_view>& choices, std::optional<T> (*parse)(std::string_view)) {
    if (!j.is_string()) {
      wrongKind(at, "the " + noun, alternatives(choices), j);
      return std::nullopt;
    }
    const std::string text = j.get<std::string>();
    auto value = parse(text);
    if (!value) report(DiagCode::UnknownSamplerValue, at, {shown_, noun, quoteUserText(text), unknownNameHint(text, choices, noun + "s")});
    return value;
  }

  // "a, b or c".
  static std::string alternatives(const std::vector<std::string_view>& choices) {
    std::string text;
    for (std::size_t i = 0; i < choices.size(); ++i)
      text += std::string(i == 0 ? "" : i + 1 == choices.size() ? " or " : ", ") + std::string(choices[i]);
    return text;
  }

  void wrongKind(const std::string& at, std::string_view what, std::string_view expected, const nlohmann::json& j) {
    report(DiagCode::WrongJsonKind, at, {what, expected, describeJsonKind(j)});
  }

  void report(DiagCode code, const std::string& at, std::initializer_list<std::string_view> args) {
    ok_ = false;
    diags_.report(code, doc_.locate(at), args);
  }

  const std::string& pointer_;
  const std::string& shown_;
  const JsonDocument& doc_;
  DiagnosticList& diags_;
  bool ok_ = true;
};

}  // namespace

bool loadSamplerState(const nlohmann::json& texture, const std::string& pointer, const std::string& shownName,
                      bool procedural, const JsonDocument& doc, DiagnosticList& diagnostics, SamplerState& state) {
  SamplerStateLoader loader(pointer, shownName, doc, diagnostics);
  if (auto it = texture.find("wrap"); it != texture.end()) loader.wrap(*it, state);
  if (auto it = texture.find("filter"); it != texture.end()) loader.filter(*it, state);
  if (auto it = texture.find("colorSpace"); it != texture.end()) loader.colorSpace(*it, procedural, state);
  return loader.ok();
}

}  // namespace wg
