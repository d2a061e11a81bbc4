#pragma once
// An orthonormal shading frame: t (n_u direction), b = n x t (n_v direction), n.
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

namespace aniso
{
struct Frame
{
  glm::dvec3 t{1.0, 0.0, 0.0};
  glm::dvec3 b{0.0, 1.0, 0.0};
  glm::dvec3 n{0.0, 0.0, 1.0};

  glm::dvec3 toWorld(const glm::dvec3& local) const { return local.x * t + local.y * b + local.z * n; }
  glm::dvec3 toLocal(const glm::dvec3& world) const
  {
    return {glm::dot(world, t), glm::dot(world, b), glm::dot(world, n)};
  }

  // Frame from a normal and a tangent hint: t is the hint made orthogonal to n (Gram-Schmidt),
  // b = n x t. A hint parallel to n falls back to an arbitrary but deterministic tangent.
  static Frame fromNormalTangent(const glm::dvec3& normal, const glm::dvec3& tangentHint)
  {
    Frame f;
    f.n = glm::normalize(normal);
    glm::dvec3 t = tangentHint - glm::dot(tangentHint, f.n) * f.n;
    double len = glm::length(t);
    if (!(len > 1e-12))
    {
      glm::dvec3 axis = std::abs(f.n.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
      t = axis - glm::dot(axis, f.n) * f.n;
      len = glm::length(t);
    }
    f.t = t / len;
    f.b = glm::cross(f.n, f.t);
    return f;
  }
};
} // namespace aniso
