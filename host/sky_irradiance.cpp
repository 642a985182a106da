#include "host/sky_irradiance.hpp"

#include <cmath>
#include <stdexcept>

namespace wg {

namespace {
constexpr double kPi = 3.14159265358979323846;
// The real spherical harmonics are Y_i = K_i p_i; K_i^2 times pi, band by band
// (1/(4 pi); 3/(4 pi); 15/(4 pi), 5/(16 pi), 15/(16 pi)).
constexpr std::array<double, 9> kNormalisationSquaredTimesPi{0.25, 0.75, 0.75, 0.75, 3.75, 3.75, 0.3125, 3.75, 0.9375};
// The clamped cosine's band factors over pi (eq. 8-9: A_0 = pi, A_1 = 2 pi / 3, A_2 = pi / 4).
constexpr std::array<double, 9> kCosineBandOverPi{1.0, 2.0 / 3.0, 2.0 / 3.0, 2.0 / 3.0, 0.25, 0.25, 0.25, 0.25, 0.25};

std::array<double, 9> polynomials(glm::dvec3 n) {
  return {1.0, n.x, n.y, n.z, n.x * n.y, n.y * n.z, 3.0 * n.y * n.y - 1.0, n.x * n.z, n.z * n.z - n.x * n.x};
}

// The solid angle a cube face (at distance 1) subtends between its centre and the point
// (u, v), by the integral of its area element 1 / (1 + u^2 + v^2)^(3/2).
double solidAngleTo(double u, double v) { return std::atan2(u * v, std::sqrt(u * u + v * v + 1.0)); }
}  // namespace

std::vector<SkySample> cubeSkySamples(std::uint32_t faceSize) {
  std::vector<SkySample> samples;
  samples.reserve(6u * faceSize * faceSize);
  const double texel = 2.0 / faceSize;
  for (int axis = 0; axis < 3; ++axis)
    for (double sign : {1.0, -1.0})
      for (std::uint32_t j = 0; j < faceSize; ++j)
        for (std::uint32_t i = 0; i < faceSize; ++i) {
          double u0 = -1.0 + i * texel, v0 = -1.0 + j * texel, u1 = u0 + texel, v1 = v0 + texel;
          glm::dvec3 d(0.0);
          d[axis] = sign;
          d[(axis + 1) % 3] = u0 + 0.5 * texel;
          d[(axis + 2) % 3] = v0 + 0.5 * texel;
          double solidAngle = solidAngleTo(u1, v1) - solidAngleTo(u0, v1) - solidAngleTo(u1, v0) + solidAngleTo(u0, v0);
          samples.push_back({glm::vec3(glm::normalize(d)), static_cast<float>(solidAngle)});
        }
  return samples;
}

SkyIrradiance projectSkyIrradiance(std::span<const SkySample> samples, std::span<const glm::vec3> radiance) {
  if (samples.size() != radiance.size()) throw std::logic_error("sky irradiance: one radiance per sample");
  std::array<glm::dvec3, 9> sums{};
  for (std::size_t s = 0; s < samples.size(); ++s) {
    const std::array<double, 9> p = polynomials(samples[s].direction);
    const glm::dvec3 weighted = glm::dvec3(radiance[s]) * double(samples[s].solidAngle);
    for (std::size_t i = 0; i < 9; ++i) sums[i] += weighted * p[i];
  }
  // c_i = (A_l / pi) K_i^2 integral(L p_i): the projection onto Y_i (eq. 10), its
  // convolution (eq. 8-9) and Y_i's own K_i, divided by pi.
  SkyIrradiance out;
  for (std::size_t i = 0; i < 9; ++i)
    out.coefficients[i] = glm::vec3(sums[i] * (kCosineBandOverPi[i] * kNormalisationSquaredTimesPi[i] / kPi));
  return out;
}

glm::vec3 skyIrradianceAt(const SkyIrradiance& irradiance, glm::vec3 n) {
  const std::array<double, 9> p = polynomials(n);
  glm::dvec3 sum(0.0);
  for (std::size_t i = 0; i < 9; ++i) sum += glm::dvec3(irradiance.coefficients[i]) * p[i];
  return glm::vec3(sum);
}

void writeSkyIrradiance(const SkyIrradiance& irradiance, FrameState& frame) {
  for (std::size_t i = 0; i < 9; ++i) {
    const glm::vec3& c = irradiance.coefficients[i];
    frame.skyIrradiance[i] = {c.r, c.g, c.b, 0.f};
  }
}

}  // namespace wg
