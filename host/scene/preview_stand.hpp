// The preview stand of `render --material`: one material on a sphere, a rock, a 45
// degree ramp and a cube tilted onto an edge on a post, stood on a ground plane next to
// a small roof, so up-facing, sloped, vertical and overhanging (down-facing) surfaces,
// sun and shade, open and sheltered ground all show at once.
#pragma once
#include <string>
#include <string_view>
#include <vector>

#include "host/scene/scene.hpp"

namespace wg::scene {

// The objects drawn with the previewed material.
std::vector<std::string_view> previewStandSubjects();  // "sphere", "rock", "ramp", "cube"

// `graph` is a SceneObject::graph value (a bundled stem or a graph file path). The
// ground is the bundled "terrain" graph, the roof, its posts and the cube's post the
// bundled "rock". The scene is stageAround's (cameras front, sun-side, shade-side,
// close-up) with the ground at y = 0 and two ground probes: "under-roof" (expect
// "sheltered") and "open-ground" (expect "open").
Scene previewStand(const std::string& graph, std::string name = "stand");

}  // namespace wg::scene
