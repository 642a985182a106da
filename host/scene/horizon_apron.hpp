// The ground beyond a scene's height field, out to the horizon: without it every view
// from above shows the square's tilted edge against the sky. Drawn with the terrain's
// material (so weather covers it too), it lies outside the scene's bounds, which the
// shadow and sky-exposure maps cover; distance haze hides where it ends.
#pragma once
#include "host/scene/mesh.hpp"
#include "host/scene/shapes.hpp"

namespace wg::scene {

// The distance haze (Scene::hazeDistance) of the scenes and stages with an apron: a
// clear winter day, 1 - 1/e at 1.5 km (Koschmieder: about 6 km visibility), so a
// subject 150 m away keeps 90 % of its contrast.
inline constexpr float kHorizonHazeDistance = 1500.f;

struct HorizonApronSettings {
  float reach = 1500.f;  // metres from the centre: past the far plane of any view the CLI allows
  int rings = 14;        // bands from the field's edge out to `reach`, each wider by the same factor
  float uvTiling = 8.f;  // as the field's: uv = world xz / uvTiling, seamless at the edge
};

// Rings of vertices around `field`, a heightFieldTerrain of `verticesPerSide`^2
// vertices centred on the origin. The first ring is the field's border (its positions,
// normals and uv, so no crack or shading seam shows); each further ring is the border
// scaled out from the centre, its heights the border's smoothed along the ring (river
// channels and road cuts fill in with distance) plus `relief` faded in over the first
// rings.
Mesh horizonApron(const Mesh& field, int verticesPerSide, const HeightFn& relief, const HorizonApronSettings& settings = {});

}  // namespace wg::scene
