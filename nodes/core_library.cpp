#include "nodes/core_library.hpp"

namespace wg {

// A zero vector stays zero instead of becoming NaN (degenerate normals, V + L = 0).
const ShaderLibrary kCoreLibrary = {
    "core",
    R"(vec3 wg_safe_normalize(const vec3 v) { return v * inversesqrt(max(dot(v, v), 1e-12)); }
)",
    {}};

}  // namespace wg
