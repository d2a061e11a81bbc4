// Per-pixel shading frames: renormalisation of interpolated vectors, the minimal tilt by a map
// normal, the turn by a map tangent, and degenerate inputs. References are vectors worked out by
// hand (rotations about known axes) and orthonormality identities.
#include "core/brdf/shading_frame.h"

#include <cmath>
#include <glm/geometric.hpp>
#include <gtest/gtest.h>

namespace
{
constexpr double kPi = 3.14159265358979323846;

void expectOrthonormal(const aniso::Frame& f)
{
  EXPECT_NEAR(glm::length(f.t), 1.0, 1e-14);
  EXPECT_NEAR(glm::length(f.b), 1.0, 1e-14);
  EXPECT_NEAR(glm::length(f.n), 1.0, 1e-14);
  EXPECT_NEAR(glm::dot(f.t, f.b), 0.0, 1e-14);
  EXPECT_NEAR(glm::dot(f.t, f.n), 0.0, 1e-14);
  EXPECT_NEAR(glm::length(glm::cross(f.n, f.t) - f.b), 0.0, 1e-14); // right-handed, b = n x t
}

void expectNear(const glm::dvec3& a, const glm::dvec3& b, double tolerance)
{
  EXPECT_NEAR(glm::length(a - b), 0.0, tolerance) << a.x << " " << a.y << " " << a.z;
}

// Interpolated vectors of any length, not orthogonal: n keeps the direction of the normal, t is
// the tangent's component orthogonal to n, normalised; no map gives exactly that frame.
TEST(ShadingFrame, RenormalisesInterpolatedVectors)
{
  const glm::dvec3 normal = 3.7 * glm::normalize(glm::dvec3(0.2, -0.3, 1.0));
  const glm::dvec3 tangent = 0.2 * glm::dvec3(1.0, 0.1, 0.4);
  const aniso::Frame f = aniso::perturbedFrame(normal, tangent);
  expectOrthonormal(f);
  expectNear(f.n, glm::normalize(normal), 1e-15);
  const glm::dvec3 n = glm::normalize(normal);
  const glm::dvec3 expectedT = glm::normalize(tangent - glm::dot(tangent, n) * n);
  expectNear(f.t, expectedT, 1e-15);
}

// A map normal tilted by 30 degrees towards +t rotates the frame about b: b is unchanged,
// n = cos30 n0 + sin30 t0 and t = cos30 t0 - sin30 n0 (the smallest rotation).
TEST(ShadingFrame, MapNormalTiltsByTheSmallestRotation)
{
  const glm::dvec3 n0(0.0, 0.0, 1.0);
  const glm::dvec3 t0(0.0, 1.0, 0.0); // base tangent along world +Y, so b0 = n0 x t0 = -X
  const double a = 30.0 * kPi / 180.0;
  const aniso::Frame f =
      aniso::perturbedFrame(2.0 * n0, t0, glm::dvec3(std::sin(a), 0.0, std::cos(a)) * 5.0);
  expectOrthonormal(f);
  expectNear(f.b, glm::dvec3(-1.0, 0.0, 0.0), 1e-15);
  expectNear(f.n, std::cos(a) * n0 + std::sin(a) * t0, 1e-15);
  expectNear(f.t, std::cos(a) * t0 - std::sin(a) * n0, 1e-15);
}

// A map tangent (cos a, sin a) turns t by a within the (tilted) tangent plane; n is unchanged.
TEST(ShadingFrame, MapTangentTurnsWithinTheTangentPlane)
{
  const glm::dvec3 normal = glm::normalize(glm::dvec3(0.3, 0.4, 1.0));
  const glm::dvec3 tangent(1.0, 0.0, 0.0);
  const glm::dvec3 mapNormal = glm::normalize(glm::dvec3(-0.2, 0.1, 1.0));
  const aniso::Frame tilted = aniso::perturbedFrame(normal, tangent, mapNormal);
  for (double degrees : {90.0, 37.0, -120.0, 180.0})
  {
    const double a = degrees * kPi / 180.0;
    const aniso::Frame f = aniso::perturbedFrame(normal, tangent, mapNormal,
                                                 0.3 * glm::dvec2(std::cos(a), std::sin(a)));
    expectOrthonormal(f);
    expectNear(f.n, tilted.n, 1e-15);
    expectNear(f.t, std::cos(a) * tilted.t + std::sin(a) * tilted.b, 1e-14);
  }
}

// The tilted normal is the map normal expressed in the base frame (t0, b0, n0).
TEST(ShadingFrame, MapNormalIsExpressedInTheBaseFrame)
{
  const glm::dvec3 normal = glm::normalize(glm::dvec3(-0.5, 0.2, 0.8));
  const glm::dvec3 tangent(0.0, 1.0, 0.3);
  const aniso::Frame base = aniso::Frame::fromNormalTangent(normal, tangent);
  const glm::dvec3 m = glm::normalize(glm::dvec3(0.4, -0.3, 0.7));
  const aniso::Frame f = aniso::perturbedFrame(normal, tangent, m);
  expectNear(f.n, m.x * base.t + m.y * base.b + m.z * base.n, 1e-15);
}

// Degenerate inputs never produce NaN: zero normal -> default frame; zero or NaN map normal ->
// no tilt; zero map tangent -> tangent kept; tangent parallel to the normal -> some valid frame.
TEST(ShadingFrame, DegenerateInputsStayFinite)
{
  const aniso::Frame def = aniso::perturbedFrame(glm::dvec3(0.0), glm::dvec3(1.0, 0.0, 0.0));
  expectNear(def.n, glm::dvec3(0.0, 0.0, 1.0), 0.0);
  expectNear(def.t, glm::dvec3(1.0, 0.0, 0.0), 0.0);

  const glm::dvec3 normal(0.0, 0.0, 1.0);
  const glm::dvec3 tangent(1.0, 0.0, 0.0);
  const aniso::Frame untilted = aniso::perturbedFrame(normal, tangent, glm::dvec3(0.0));
  expectNear(untilted.n, normal, 1e-15);
  const aniso::Frame nanMap =
      aniso::perturbedFrame(normal, tangent, glm::dvec3(std::nan(""), 0.0, 1.0));
  expectNear(nanMap.n, normal, 1e-15);
  const aniso::Frame kept =
      aniso::perturbedFrame(normal, tangent, glm::dvec3(0.0, 0.0, 1.0), glm::dvec2(0.0));
  expectNear(kept.t, tangent, 1e-15);
  const aniso::Frame parallel = aniso::perturbedFrame(normal, normal);
  expectOrthonormal(parallel);
}

// t / alpha_x and b / alpha_y keep the frame's directions with lengths 1 / alpha.
TEST(ShadingFrame, ScaledTangentsCarryInverseRoughness)
{
  const aniso::Frame f =
      aniso::Frame::fromNormalTangent(glm::dvec3(0.1, 0.2, 1.0), glm::dvec3(1.0, 0.0, 0.0));
  const aniso::ScaledTangents s = aniso::scaledTangents(f, 0.25, 0.5);
  EXPECT_NEAR(glm::length(s.tScaled), 4.0, 1e-14);
  EXPECT_NEAR(glm::length(s.bScaled), 2.0, 1e-14);
  EXPECT_NEAR(glm::dot(s.tScaled, f.t), 4.0, 1e-14);
  EXPECT_NEAR(glm::dot(s.bScaled, f.b), 2.0, 1e-14);
}
} // namespace
