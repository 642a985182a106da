// The one function that makes every emitted identifier. It sanitises any text to
// [A-Za-z0-9_], never yields a GLSL or HLSL reserved word, a gl_ name, a leading or
// doubled underscore, and resolves collisions deterministically (first come, _2, _3...).
#pragma once
#include <string>
#include <string_view>
#include <unordered_set>

namespace wg {

class IdentifierScope {
 public:
  // Longest identifier made; keeps emitted code readable and far below compiler limits.
  static constexpr std::size_t kMaxLength = 48;

  // A fresh, valid, unique identifier derived from hint (which may be hostile text).
  std::string make(std::string_view hint);
  // Marks a fixed internal name as taken (it must already be valid).
  void reserve(std::string_view name);
  // Room for `count` more names without rehashing (large graphs name every node).
  void expectMore(std::size_t count) { used_.reserve(used_.size() + count); }

  static std::string sanitize(std::string_view hint);
  static bool isReserved(std::string_view name);

 private:
  std::unordered_set<std::string> used_;
};

}  // namespace wg
