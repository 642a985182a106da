#include "host/snowfield/snowfield_figures.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

#include "host/scene/shapes.hpp"

namespace wg::snow {

namespace {
constexpr float kPi = 3.14159265f;
// An adult: hips 0.9 m above the soles, a 0.55 m torso, a 0.11 m head.
constexpr float kHipHeight = 0.9f, kTorsoTop = 1.45f, kHeadRadius = 0.11f;
constexpr float kLegWidth = 0.11f, kStepLift = 0.12f;  // how high a swinging foot rises
constexpr float kWheelRadius = 0.35f;
constexpr float kAxleOffset = 1.3f;  // front and rear axles from the vehicle's centre
constexpr int kWheelSegments = 16;

const char* kLegs[2] = {"LeftLeg", "RightLeg"};
const char* kFeet[2] = {"LeftFoot", "RightFoot"};

float yawOf(glm::vec2 heading) { return std::atan2(heading.x, heading.y); }  // +z forward

glm::mat4 standing(glm::vec3 at, glm::vec2 heading) {
  return glm::rotate(glm::translate(glm::mat4(1.f), at), yawOf(heading), glm::vec3(0.f, 1.f, 0.f));
}

glm::vec2 leftOf(glm::vec2 heading) { return {-heading.y, heading.x}; }

// A cylinder along x, centred on the origin.
scene::Mesh wheel(float radius, float width) {
  scene::Mesh m;
  float half = 0.5f * width;
  for (int i = 0; i < kWheelSegments; ++i) {
    float a0 = 2.f * kPi * float(i) / kWheelSegments, a1 = 2.f * kPi * float(i + 1) / kWheelSegments;
    glm::vec3 r0(0.f, std::cos(a0), std::sin(a0)), r1(0.f, std::cos(a1), std::sin(a1));
    float u0 = float(i) / kWheelSegments, u1 = float(i + 1) / kWheelSegments;
    std::uint32_t a = scene::addVertex(m, glm::vec3(-half, 0.f, 0.f) + r0 * radius, r0, {u0, 0.f});
    std::uint32_t b = scene::addVertex(m, glm::vec3(half, 0.f, 0.f) + r0 * radius, r0, {u0, 1.f});
    std::uint32_t c = scene::addVertex(m, glm::vec3(half, 0.f, 0.f) + r1 * radius, r1, {u1, 1.f});
    std::uint32_t d = scene::addVertex(m, glm::vec3(-half, 0.f, 0.f) + r1 * radius, r1, {u1, 0.f});
    scene::addQuadFacing(m, a, b, c, d, 0.5f * (r0 + r1));
    for (float side : {-1.f, 1.f}) {
      glm::vec3 n(side, 0.f, 0.f);
      std::uint32_t centre = scene::addVertex(m, glm::vec3(side * half, 0.f, 0.f), n, {0.5f, 0.5f});
      std::uint32_t p = scene::addVertex(m, glm::vec3(side * half, 0.f, 0.f) + r0 * radius, n, glm::vec2(r0.y, r0.z) * 0.5f + 0.5f);
      std::uint32_t q = scene::addVertex(m, glm::vec3(side * half, 0.f, 0.f) + r1 * radius, n, glm::vec2(r1.y, r1.z) * 0.5f + 0.5f);
      scene::addTriangleFacing(m, centre, p, q, n);
    }
  }
  scene::computeTangents(m);
  return m;
}

// Rotates -y onto `direction` (unit).
glm::mat4 downTo(glm::vec3 direction) {
  glm::vec3 down(0.f, -1.f, 0.f), axis = glm::cross(down, direction);
  float s = glm::length(axis), c = glm::dot(down, direction);
  if (s < 1e-6f) return c > 0.f ? glm::mat4(1.f) : glm::rotate(glm::mat4(1.f), kPi, glm::vec3(1.f, 0.f, 0.f));
  return glm::rotate(glm::mat4(1.f), std::atan2(s, c), axis / s);
}
}  // namespace

std::vector<FigurePart> walkerParts(const std::string& prefix) {
  scene::Mesh body = scene::box({-0.18f, kHipHeight, -0.1f}, {0.18f, kTorsoTop, 0.1f});
  scene::append(body, scene::sphere(kHeadRadius), glm::translate(glm::mat4(1.f), {0.f, kTorsoTop + 0.03f + kHeadRadius, 0.f}));
  for (float side : {-1.f, 1.f})  // arms hanging at the sides
    scene::append(body, scene::box({-0.04f, -0.6f, -0.04f}, {0.04f, 0.f, 0.04f}),
                  glm::translate(glm::mat4(1.f), {side * 0.23f, kTorsoTop - 0.03f, 0.f}));
  std::vector<FigurePart> parts{{prefix, std::move(body)}};
  for (int i = 0; i < 2; ++i) {
    // Unit length along -y from the hip; the pose scales it to reach the foot.
    parts.push_back({prefix + kLegs[i], scene::box({-0.5f * kLegWidth, -1.f, -0.5f * kLegWidth}, {0.5f * kLegWidth, 0.f, 0.5f * kLegWidth})});
    // A boot as long and wide as the footprint (snow_stamp.hpp's FootShape), sole at y = 0.
    parts.push_back({prefix + kFeet[i], scene::box({-0.05f, 0.f, -0.14f}, {0.05f, 0.08f, 0.14f})});
  }
  return parts;
}

std::vector<FigurePart> vehicleParts(const std::string& prefix, const Vehicle& v) {
  std::vector<FigurePart> parts;
  // The body sits between the wheels, above them, narrower than the track plus a tyre.
  float half = 0.5f * v.track + 0.5f * v.wheelWidth;
  scene::Mesh body = scene::box({-half + v.wheelWidth, kWheelRadius, -2.1f}, {half - v.wheelWidth, 1.45f, 2.1f});
  scene::append(body, scene::box({-half, 2.f * kWheelRadius, -2.1f}, {half, 1.f, 2.1f}));  // fenders over the wheels
  parts.push_back({prefix, std::move(body)});
  for (int i = 0; i < 4; ++i) parts.push_back({prefix + "Wheel" + std::to_string(i), wheel(kWheelRadius, v.wheelWidth)});
  return parts;
}

std::pair<glm::vec3, glm::vec3> walkerFeet(const Walker& w, float s, const FigureGround& ground) {
  auto planted = [&](int k) {
    glm::vec2 at = k >= 0 ? footfall(w, k) : w.path.pointAt(0.f) + leftOf(w.path.headingAt(0.f)) * (w.footSpacing * (k == -1 ? -0.5f : 0.5f));
    return glm::vec3(at.x, ground.height(at.x, at.y) + ground.floor, at.y);
  };
  int k = std::max(int(std::floor(s / w.stepLength)), 0);
  int last = int(std::floor(w.path.length() / w.stepLength));
  glm::vec3 feet[2];
  if (k >= last) {  // at the end of the path both feet stand in their last prints
    feet[last % 2] = planted(last);
    feet[(last + 1) % 2] = planted(last - 1);
  } else {
    float u = s / w.stepLength - float(k);
    feet[k % 2] = planted(k);  // even footfalls are left feet
    glm::vec3 from = planted(k - 1), to = planted(k + 1);
    glm::vec3 swing = glm::mix(from, to, u);
    swing.y += kStepLift * std::sin(kPi * u);
    feet[(k + 1) % 2] = swing;
  }
  return {feet[0], feet[1]};
}

void poseWalker(const Walker& w, const std::string& prefix, float s, const FigureGround& ground,
                std::map<std::string, glm::mat4>& models) {
  glm::vec2 at = w.path.pointAt(s), heading = w.path.headingAt(s);
  auto [left, right] = walkerFeet(w, s, ground);
  // The body rides above the feet's mean height.
  glm::vec3 base(at.x, 0.5f * (left.y + right.y), at.y);
  models[prefix] = standing(base, heading);
  const glm::vec3 feet[2] = {left, right};
  for (int i = 0; i < 2; ++i) {
    float side = i == 0 ? 0.5f : -0.5f;
    glm::vec2 hipAt = at + leftOf(heading) * (side * w.footSpacing);
    glm::vec3 hip(hipAt.x, base.y + kHipHeight, hipAt.y);
    glm::vec3 ankle = feet[i] + glm::vec3(0.f, 0.06f, 0.f);
    glm::vec3 reach = ankle - hip;
    float length = glm::length(reach);
    models[prefix + kLegs[i]] = glm::translate(glm::mat4(1.f), hip) * downTo(reach / length) *
                                glm::scale(glm::mat4(1.f), glm::vec3(1.f, length, 1.f));
    models[prefix + kFeet[i]] = standing(feet[i], heading);
  }
}

void poseVehicle(const Vehicle& v, const std::string& prefix, float s, const FigureGround& ground,
                 std::map<std::string, glm::mat4>& models) {
  glm::vec2 at = v.path.pointAt(s), heading = v.path.headingAt(s);
  float roll = s / kWheelRadius;  // rolling without slip
  float sum = 0.f;
  for (int i = 0; i < 4; ++i) {
    float side = (i % 2 == 0) ? 0.5f : -0.5f, axle = (i < 2) ? kAxleOffset : -kAxleOffset;
    glm::vec2 p = at + leftOf(heading) * (side * v.track) + heading * axle;
    float bottom = ground.height(p.x, p.y) + ground.floor;
    sum += bottom;
    models[prefix + "Wheel" + std::to_string(i)] = standing({p.x, bottom + kWheelRadius, p.y}, heading) *
                                                   glm::rotate(glm::mat4(1.f), roll, glm::vec3(1.f, 0.f, 0.f));
  }
  models[prefix] = standing({at.x, 0.25f * sum, at.y}, heading);
}

}  // namespace wg::snow
