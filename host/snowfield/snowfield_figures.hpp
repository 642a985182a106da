// The snowfield's movers as simple articulated figures: a walker is a body, two legs
// and two feet, posed so each planted foot stands in the print its footfall pressed
// (snow_interactors.hpp) while the other swings from its last print to its next; the
// vehicle is a body on four wheels that run in its two ruts and turn as it rolls.
// Each part is an object of the scene, placed per frame (RenderRequest::objectModels).
#pragma once
#include <functional>
#include <map>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "host/scene/mesh.hpp"
#include "snow/snow_interactors.hpp"

namespace wg::snow {

// One part: its object name, mesh (in part space) and model matrix.
struct FigurePart {
  std::string name;
  scene::Mesh mesh;
};

// Ground height (m) at world (x, z), and where a pressed foot or wheel rests: that
// height plus the snow left under a print.
struct FigureGround {
  std::function<float(float, float)> height;
  float floor = 0.f;  // m above the ground: the packed snow at the bottom of a print
};

std::vector<FigurePart> walkerParts(const std::string& prefix);
std::vector<FigurePart> vehicleParts(const std::string& prefix, const Vehicle& vehicle);

// Model matrices of every part at `distance` along the mover's path.
void poseWalker(const Walker& walker, const std::string& prefix, float distance, const FigureGround& ground,
                std::map<std::string, glm::mat4>& models);
void poseVehicle(const Vehicle& vehicle, const std::string& prefix, float distance, const FigureGround& ground,
                 std::map<std::string, glm::mat4>& models);

// Where the walker's feet are at `distance` (world, the sole's centre): left, right.
std::pair<glm::vec3, glm::vec3> walkerFeet(const Walker& walker, float distance, const FigureGround& ground);

}  // namespace wg::snow
