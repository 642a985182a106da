// Under AddressSanitizer, keeps the Vulkan driver and the validation layer mapped after
// the loader dlclose()s them. LeakSanitizer runs at exit; without this, their one-off
// allocations show as "<unknown module>" and tests/sanitizers/lsan.supp cannot name
// them. Normal builds are unaffected.
#if defined(__SANITIZE_ADDRESS__)
#include <dlfcn.h>

#include <initializer_list>

namespace {
[[maybe_unused]] const bool kDriversResident = [] {
  for (const char* library : {"libvulkan_lvp.so", "libVkLayer_khronos_validation.so"})
    dlopen(library, RTLD_NOW | RTLD_NODELETE);  // a missing library is fine: nothing to keep
  return true;
}();
}  // namespace
#endif
