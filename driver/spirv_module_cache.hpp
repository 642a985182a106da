// SPIR-V modules shared by the compiles of one batch. Variants often share a stage: a
// switch that touches only the fragment stage leaves the vertex text as it was. Such a
// text is compiled, validated and offset-checked once, and every material that emits
// it reuses the module. The key is the text less its banner comment, which names the
// material's content hash and never reaches the SPIR-V.
#pragma once
#include <cstddef>
#include <functional>
#include <future>
#include <memory>
#include <mutex>
#include <string>
#include <string_view>
#include <unordered_map>

#include "backends/spirv/spirv_toolchain.hpp"

namespace wg {

// One stage text's module, or why there is none.
struct SpirvModule {
  bool compiled = false;   // glslang accepted the text
  std::string compileLog;  // glslang's messages when it did not
  std::string invalid;     // spirv-val's or the block-offset check's complaint, if any
  SpirvWords words;        // as glslang made them: the translations start from these
  SpirvWords optimized;    // after spirv-opt, when the batch optimises
  std::string optimizedInvalid;  // spirv-val's complaint about `optimized`
};

class SpirvModuleCache {
 public:
  struct Counts {
    std::size_t lookups = 0;   // stages asked for
    std::size_t compiled = 0;  // distinct texts, each compiled once
  };

  // The module of `text` (a stage's source; its banner line is ignored), made by `make`
  // on the first request; a concurrent request for the same text waits for that one.
  // `variant` separates builds of different settings.
  std::shared_ptr<const SpirvModule> get(std::string_view text, std::string_view variant,
                                         const std::function<SpirvModule()>& make);
  Counts counts() const;

 private:
  mutable std::mutex mutex_;
  std::unordered_map<std::string, std::shared_future<std::shared_ptr<const SpirvModule>>> modules_;
  Counts counts_;
};

}  // namespace wg
