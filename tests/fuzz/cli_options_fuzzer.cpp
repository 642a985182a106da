// libFuzzer target: arbitrary bytes as NUL-separated command-line arguments for the
// CLI's option parsers (cli_options_case.hpp).
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>
#include <string_view>

#include "tests/fuzz/cli_options_case.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string broken = wg::fuzz::checkCliOptionsInput(std::string_view(reinterpret_cast<const char*>(data), size));
  if (!broken.empty()) {
    std::fprintf(stderr, "broken property: %s\n", broken.c_str());
    __builtin_trap();
  }
  return 0;
}
