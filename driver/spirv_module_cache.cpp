#include "driver/spirv_module_cache.hpp"

#include "backends/reference_host.hpp"

namespace wg {

namespace {
// The text without its banner line: the banner differs between materials that
// otherwise emit the same stage.
std::string withoutBanner(std::string_view text) {
  std::size_t begin = text.find(kStageBannerPrefix);
  if (begin == std::string_view::npos || (begin > 0 && text[begin - 1] != '\n')) return std::string(text);
  std::size_t end = text.find('\n', begin);
  std::string out(text.substr(0, begin));
  if (end != std::string_view::npos) out += text.substr(end + 1);
  return out;
}
}  // namespace

std::shared_ptr<const SpirvModule> SpirvModuleCache::get(std::string_view text, std::string_view variant,
                                                         const std::function<SpirvModule()>& make) {
  std::string key(variant);
  key += '\n';
  key += withoutBanner(text);
  std::promise<std::shared_ptr<const SpirvModule>> promise;
  std::shared_future<std::shared_ptr<const SpirvModule>> future;
  bool first = false;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    ++counts_.lookups;
    auto [it, inserted] = modules_.try_emplace(std::move(key));
    if (inserted) {
      it->second = promise.get_future().share();
      ++counts_.compiled;
      first = true;
    }
    future = it->second;
  }
  if (first) {
    try {
      promise.set_value(std::make_shared<const SpirvModule>(make()));
    } catch (...) {
      promise.set_exception(std::current_exception());
    }
  }
  return future.get();
}

SpirvModuleCache::Counts SpirvModuleCache::counts() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return counts_;
}

}  // namespace wg
