// A hash of what a material is (its canonical IR, parameters and textures), not of how
// its file spells it: renaming node ids or reordering nodes keeps the hash.
#pragma once
#include <cstdint>
#include <string>
#include <string_view>

#include "compiler/ir.hpp"

namespace wg {

// 64-bit FNV-1a, stable across platforms and runs (std::hash is neither).
class StableHasher {
 public:
  void add(std::string_view bytes);
  // Inline: the IR hash adds several words per node.
  void add(std::uint64_t value) {
    for (int i = 0; i < 8; ++i) {
      state_ ^= (value >> (8 * i)) & 0xFF;
      state_ *= kPrime;
    }
  }
  std::uint64_t value() const { return state_; }
  std::string hex() const;

 private:
  static constexpr std::uint64_t kOffsetBasis = 14695981039346656037ull;
  static constexpr std::uint64_t kPrime = 1099511628211ull;
  std::uint64_t state_ = kOffsetBasis;
};

std::string contentHash(const IrGraph& graph);

}  // namespace wg
