// Deterministic synthetic material graphs for scaling benchmarks and tests.
//
// makeSyntheticGraph(n, seed) returns the JSON text of a valid material with exactly
// max(n, kSyntheticGraphMinNodes) nodes (the fixed sources, seeds and reduction need 78). The mix is what hand-written materials use: chains and fan-in of
// add / multiply / lerp / sin / normalize / value_noise (plus swizzle to move between
// widths) over texcoord, world_position and parameters.
//
// Structure, chosen so the pass pipeline keeps almost every node:
//  * every node's first input is a node (the oldest not-yet-consumed value of a
//    fixed-width frontier), so no node is all-constant and constant folding folds nothing;
//  * every node is consumed: the frontier is summed into baseColor / normal /
//    roughness at the end, so dead-node elimination removes nothing;
//  * second operands are random earlier nodes (fan-in), parameters or random literals,
//    so structurally identical nodes (CSE merges) are rare.
// Edges grow linearly with n (at most 3 inputs per node) and the depth is about n / 24.
// Header-only and free of project dependencies so tests can reuse it.
#pragma once
#include <cstdint>
#include <charconv>
#include <initializer_list>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace wg {

namespace synthetic_detail {

// splitmix64: tiny, portable and identical on every standard library.
class Rng {
 public:
  explicit Rng(std::uint64_t seed) : state_(seed) {}
  std::uint64_t next() {
    std::uint64_t z = (state_ += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  int below(int n) { return static_cast<int>(next() % static_cast<std::uint64_t>(n)); }
  float uniform(float lo, float hi) {
    return lo + (hi - lo) * static_cast<float>(next() >> 40) / static_cast<float>(1ull << 24);
  }

 private:
  std::uint64_t state_;
};

// String building by appending (GCC 12's -Wrestrict misfires on "literal" + std::string).
inline void append(std::string& out, std::initializer_list<std::string_view> parts) {
  for (std::string_view part : parts) out.append(part);
}
inline std::string cat(std::initializer_list<std::string_view> parts) {
  std::string out;
  append(out, parts);
  return out;
}

inline std::string number(float x) {
  char buffer[32];  // to_chars: independent of the C locale
  auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, x, std::chars_format::fixed, 4);
  return std::string(buffer, ec == std::errc() ? end : buffer);
}

inline std::string literal(int width, Rng& rng) {
  if (width == 1) return number(rng.uniform(-2.f, 2.f));
  std::string out = "[";
  for (int i = 0; i < width; ++i) append(out, {i ? ", " : "", number(rng.uniform(-2.f, 2.f))});
  return out += "]";
}

class Generator {
 public:
  Generator(int nodeCount, std::uint32_t seed) : target_(nodeCount), rng_(seed) {}

  std::string run() {
    sources();
    // Each body node pops one frontier value and pushes one, so the frontier keeps its
    // width; stop when the closing reduction fills the budget exactly.
    while (true) {
      int slack = target_ - static_cast<int>(width_.size()) - reductionCost();
      if (slack <= 0) break;
      bodyNode(slack == 1);
    }
    reduce();
    return document();
  }

 private:
  static constexpr int kFrontier = 24;
  static constexpr int kFloatParams = 8, kVec2Params = 4, kVec3Params = 4;

  // --- emission -----------------------------------------------------------------------
  int add(const std::string& op, int width, const std::string& inputs) {
    int id = static_cast<int>(width_.size());
    nodes_ += nodes_.empty() ? "\n    " : ",\n    ";
    append(nodes_, {"{\"id\": \"n", std::to_string(id), "\", \"op\": \"", op, "\""});
    if (!inputs.empty()) append(nodes_, {", \"inputs\": {", inputs, "}"});
    nodes_ += "}";
    width_.push_back(width);
    byWidth_[width].push_back(id);
    return id;
  }
  int addParameter(const std::string& param, int width) {
    int id = static_cast<int>(width_.size());
    nodes_ += nodes_.empty() ? "\n    " : ",\n    ";
    append(nodes_, {"{\"id\": \"n", std::to_string(id), "\", \"op\": \"parameter\", \"param\": \"", param, "\"}"});
    width_.push_back(width);
    byWidth_[width].push_back(id);
    params_[width].push_back(id);
    return id;
  }
  static std::string link(int id) { return cat({"\"n", std::to_string(id), ".out\""}); }
  static std::string port(std::string_view name, std::string_view value) { return cat({"\"", name, "\": ", value}); }
  static std::string ports(std::initializer_list<std::pair<std::string_view, std::string>> list) {
    std::string out;
    for (const auto& [name, value] : list) append(out, {out.empty() ? "" : ", ", port(name, value)});
    return out;
  }

  // --- graph shape ----------------------------------------------------------------------
  void sources() {
    texcoord_ = add("texcoord", 2, "");
    position_ = add("world_position", 3, "");
    for (int i = 0; i < kFloatParams; ++i) addParameter(cat({"f", std::to_string(i)}), 1);
    for (int i = 0; i < kVec2Params; ++i) addParameter(cat({"v2_", std::to_string(i)}), 2);
    for (int i = 0; i < kVec3Params; ++i) addParameter(cat({"v3_", std::to_string(i)}), 3);
    // Seed the frontier with distinct, non-constant values of every width.
    for (int i = 0; i < kFrontier; ++i) {
      int kind = i % 3;
      int base = kind == 0 ? texcoord_ : kind == 1 ? position_ : params_[1][static_cast<std::size_t>(i / 3)];
      frontier_.push_back(add(i % 2 ? "multiply" : "add", width_[base],
                              ports({{"a", link(base)}, {"b", literal(width_[base], rng_)}})));
    }
  }

  // A second operand of width `w` (or a float, which any generic port accepts).
  std::string operand(int w) {
    int roll = rng_.below(10);
    if (roll < 4) {  // fan-in from an earlier node of the same width, or a float
      int pickWidth = (w != 1 && rng_.below(3) == 0) ? 1 : w;
      const auto& pool = byWidth_[pickWidth];
      if (!pool.empty()) return link(pool[static_cast<std::size_t>(rng_.below(static_cast<int>(pool.size())))]);
    }
    if (roll < 7) {
      const auto& pool = params_[rng_.below(2) ? 1 : w];
      return link(pool[static_cast<std::size_t>(rng_.below(static_cast<int>(pool.size())))]);
    }
    return literal(rng_.below(2) ? 1 : w, rng_);
  }

  // keepCost: the new node must not change the reduction cost (same vec2-ness as input).
  void bodyNode(bool keepCost) {
    int a = frontier_.front();
    frontier_.erase(frontier_.begin());
    int w = width_[a];
    int result;
    int roll = keepCost ? 0 : rng_.below(100);
    if (roll < 30) {  // add
      const char* op = rng_.below(2) ? "add" : "subtract";  // drawn before the operand: fixed order
      result = add(op, w, ports({{"a", link(a)}, {"b", operand(w)}}));
    } else if (roll < 55) {  // multiply
      result = add("multiply", w, ports({{"a", link(a)}, {"b", operand(w)}}));
    } else if (roll < 67) {  // lerp
      std::string t = rng_.below(2) ? operand(1) : number(rng_.uniform(0.f, 1.f));
      result = add("lerp", w, ports({{"a", link(a)}, {"b", operand(w)}, {"t", t}}));
    } else if (roll < 77) {  // sin
      result = add("sin", w, port("in", link(a)));
    } else if (roll < 85 && w > 1) {  // normalize
      result = add("normalize", w, port("in", link(a)));
    } else if (w == 2) {  // value_noise: vec2 -> float
      result = add("value_noise", 1, ports({{"p", link(a)}, {"scale", number(rng_.uniform(0.5f, 16.f))}}));
    } else if (w == 3) {  // drop to vec2 for noise
      static const char* const kSwizzles[] = {"xy", "xz", "yz", "zx"};
      result = add("swizzle", 2, ports({{"in", link(a)}, {"channels", cat({"\"", kSwizzles[rng_.below(4)], "\""})}}));
    } else {  // float: widen by mixing with a coordinate
      int coord = rng_.below(2) ? texcoord_ : position_;
      result = add("multiply", width_[coord], ports({{"a", link(a)}, {"b", link(coord)}}));
    }
    frontier_.push_back(result);
  }

  // Nodes reduce() will add: one per frontier value (the add into a sum), one more per
  // vec2 (value_noise to a float first), then saturate, normalize, roughness noise + saturate.
  int reductionCost() const {
    int cost = static_cast<int>(frontier_.size()) + 4;
    for (int id : frontier_)
      if (width_[id] == 2) ++cost;
    return cost;
  }

  void reduce() {
    int sums[2] = {position_, position_};  // start from a vec3 so each sum is a vec3
    for (std::size_t i = 0; i < frontier_.size(); ++i) {
      int v = frontier_[i];
      if (width_[v] == 2) v = add("value_noise", 1, ports({{"p", link(v)}, {"scale", number(rng_.uniform(0.5f, 16.f))}}));
      int& sum = sums[i % 2];
      sum = add("add", 3, ports({{"a", link(sum)}, {"b", link(v)}}));
    }
    baseColor_ = add("saturate", 3, port("in", link(sums[0])));
    normal_ = add("normalize", 3, port("in", link(sums[1])));
    int noise = add("value_noise", 1, ports({{"p", link(texcoord_)}, {"scale", link(params_[1][0])}}));
    roughness_ = add("saturate", 1, port("in", link(noise)));
  }

  std::string document() const {
    std::string out = cat({"{\n  \"name\": \"synthetic_", std::to_string(target_), "\",\n  \"parameters\": {"});
    bool first = true;
    auto param = [&](const std::string& name, std::string_view type, const std::string& dflt) {
      out += first ? "\n    " : ",\n    ";
      first = false;
      append(out, {"\"", name, "\": {\"type\": \"", type, "\", \"default\": ", dflt, "}"});
    };
    for (int i = 0; i < kFloatParams; ++i) param(cat({"f", std::to_string(i)}), "float", number(0.1f + 0.1f * static_cast<float>(i)));
    for (int i = 0; i < kVec2Params; ++i) param(cat({"v2_", std::to_string(i)}), "vec2", "[0.5, 0.25]");
    for (int i = 0; i < kVec3Params; ++i) param(cat({"v3_", std::to_string(i)}), "vec3", "[0.5, 0.25, 0.125]");
    append(out, {"\n  },\n  \"nodes\": [", nodes_, "\n  ],\n  \"output\": {\n"});
    append(out, {"    \"baseColor\": ", link(baseColor_), ",\n"});
    append(out, {"    \"normal\": ", link(normal_), ",\n"});
    append(out, {"    \"roughness\": ", link(roughness_), "\n  }\n}\n"});
    return out;
  }

  int target_;
  Rng rng_;
  std::string nodes_;
  std::vector<int> width_;                 // per node: 1, 2 or 3 components
  std::vector<int> byWidth_[4], params_[4];  // node ids by width; parameter nodes by width
  std::vector<int> frontier_;              // produced, not yet consumed; oldest first
  int texcoord_ = 0, position_ = 0, baseColor_ = 0, normal_ = 0, roughness_ = 0;
};

}  // namespace synthetic_detail

// Smallest graph the generator makes: 2 geometry sources, 16 parameters, 24 frontier
// seeds, and the reduction of that frontier (24 adds, 8 noises, 4 output nodes).
inline constexpr int kSyntheticGraphMinNodes = 78;

// JSON text of a valid material with exactly max(nodeCount, kSyntheticGraphMinNodes)
// nodes; the same arguments give the same text on every platform.
inline std::string makeSyntheticGraph(int nodeCount, std::uint32_t seed) {
  return synthetic_detail::Generator(nodeCount, seed).run();
}

}  // namespace wg
