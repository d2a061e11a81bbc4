#include "core/reference/pixel_geometry.h"

#include "core/env/parallel.h"
#include "core/error.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/vec4.hpp>
#include <limits>
#include <numeric>

namespace aniso
{
namespace
{
struct Box
{
  glm::dvec3 lo{std::numeric_limits<double>::infinity()};
  glm::dvec3 hi{-std::numeric_limits<double>::infinity()};

  void grow(const glm::dvec3& p)
  {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  void grow(const Box& b)
  {
    lo = glm::min(lo, b.lo);
    hi = glm::max(hi, b.hi);
  }
};

// Bounding-volume hierarchy over the triangles: median split along the longest axis of the
// centroids, leaves of at most kLeafSize triangles. Nodes are stored depth-first, so a node's
// first child follows it and `second` indexes the other.
constexpr int kLeafSize = 4;

struct Node
{
  Box box;
  uint32_t first = 0;  // leaf: first entry in `order`
  uint32_t count = 0;  // leaf: number of triangles; 0 for an inner node
  uint32_t second = 0; // inner node: index of the second child
};

class Bvh
{
public:
  explicit Bvh(const TriangleMesh& mesh) : mesh_(mesh)
  {
    const std::size_t n = mesh.triangles.size();
    order_.resize(n);
    std::iota(order_.begin(), order_.end(), 0u);
    centroids_.resize(n);
    boxes_.resize(n);
    for (std::size_t i = 0; i < n; ++i)
    {
      for (uint32_t corner : mesh.triangles[i])
      {
        boxes_[i].grow(mesh.positions[corner]);
      }
      centroids_[i] = 0.5 * (boxes_[i].lo + boxes_[i].hi);
    }
    nodes_.reserve(2 * n / kLeafSize + 1);
    if (n > 0)
    {
      build(0, static_cast<uint32_t>(n));
    }
  }

  // Nearest hit with t > 0: triangle index and barycentric (u, v) of corners 1 and 2.
  bool intersect(const PixelRay& ray, uint32_t& triangle, double& u, double& v) const
  {
    if (nodes_.empty())
    {
      return false;
    }
    const glm::dvec3 inverse = 1.0 / ray.direction;
    double nearest = std::numeric_limits<double>::infinity();
    bool found = false;
    uint32_t stack[64];
    int top = 0;
    stack[top++] = 0;
    while (top > 0)
    {
      const Node& node = nodes_[stack[--top]];
      if (!hitsBox(node.box, ray, inverse, nearest))
      {
        continue;
      }
      if (node.count > 0)
      {
        for (uint32_t i = node.first; i < node.first + node.count; ++i)
        {
          double t = 0.0;
          double bu = 0.0;
          double bv = 0.0;
          if (hitsTriangle(order_[i], ray, t, bu, bv) && t < nearest)
          {
            nearest = t;
            triangle = order_[i];
            u = bu;
            v = bv;
            found = true;
          }
        }
        continue;
      }
      const uint32_t self = static_cast<uint32_t>(&node - nodes_.data());
      stack[top++] = node.second;
      stack[top++] = self + 1;
    }
    return found;
  }

private:
  uint32_t build(uint32_t first, uint32_t count)
  {
    const uint32_t index = static_cast<uint32_t>(nodes_.size());
    nodes_.emplace_back();
    Box box;
    Box centres;
    for (uint32_t i = first; i < first + count; ++i)
    {
      box.grow(boxes_[order_[i]]);
      centres.grow(centroids_[order_[i]]);
    }
    nodes_[index].box = box;
    const glm::dvec3 extent = centres.hi - centres.lo;
    const int axis =
        extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
    // The depth stays below the traversal stack's 64 entries: median splits halve the count.
    if (count <= kLeafSize || extent[axis] <= 0.0)
    {
      nodes_[index].first = first;
      nodes_[index].count = count;
      return index;
    }
    const uint32_t half = count / 2;
    std::nth_element(
        order_.begin() + first, order_.begin() + first + half, order_.begin() + first + count,
        [&](uint32_t a, uint32_t b) { return centroids_[a][axis] < centroids_[b][axis]; });
    build(first, half);
    const uint32_t second = build(first + half, count - half);
    nodes_[index].second = second;
    return index;
  }

  static bool hitsBox(const Box& box, const PixelRay& ray, const glm::dvec3& inverse, double limit)
  {
    double t0 = 0.0;
    double t1 = limit;
    for (int a = 0; a < 3; ++a)
    {
      double near = (box.lo[a] - ray.origin[a]) * inverse[a];
      double far = (box.hi[a] - ray.origin[a]) * inverse[a];
      if (near > far)
      {
        std::swap(near, far);
      }
      // NaN (0 * inf, a ray in the box's plane) keeps the interval: max/min ignore it.
      t0 = std::max(t0, near);
      t1 = std::min(t1, far);
    }
    return t0 <= t1;
  }

  // Möller-Trumbore, two-sided.
  bool hitsTriangle(uint32_t triangle, const PixelRay& ray, double& t, double& u, double& v) const
  {
    const auto& corners = mesh_.triangles[triangle];
    const glm::dvec3& p0 = mesh_.positions[corners[0]];
    const glm::dvec3 e1 = mesh_.positions[corners[1]] - p0;
    const glm::dvec3 e2 = mesh_.positions[corners[2]] - p0;
    const glm::dvec3 p = glm::cross(ray.direction, e2);
    const double det = glm::dot(e1, p);
    if (det == 0.0)
    {
      return false;
    }
    const double inverseDet = 1.0 / det;
    const glm::dvec3 s = ray.origin - p0;
    u = glm::dot(s, p) * inverseDet;
    if (u < 0.0 || u > 1.0)
    {
      return false;
    }
    const glm::dvec3 q = glm::cross(s, e1);
    v = glm::dot(ray.direction, q) * inverseDet;
    if (v < 0.0 || u + v > 1.0)
    {
      return false;
    }
    t = glm::dot(e2, q) * inverseDet;
    return t > 0.0;
  }

  const TriangleMesh& mesh_;
  std::vector<uint32_t> order_;
  std::vector<glm::dvec3> centroids_;
  std::vector<Box> boxes_;
  std::vector<Node> nodes_;
};

void validateMesh(const TriangleMesh& mesh)
{
  const std::size_t points = mesh.positions.size();
  if (mesh.normals.size() != points || mesh.tangents.size() != points)
  {
    throw errorAbout("mesh", "normals and tangents must have one entry per point");
  }
  if (!mesh.triangleMaterials.empty() && mesh.triangleMaterials.size() != mesh.triangles.size())
  {
    throw errorAbout("mesh", "triangle materials must have one entry per triangle");
  }
  for (const auto& triangle : mesh.triangles)
  {
    for (uint32_t corner : triangle)
    {
      if (corner >= points)
      {
        throw errorAbout("mesh", "a triangle names point " + std::to_string(corner) + " of " +
                                     std::to_string(points));
      }
    }
  }
}

// The same choice of a perpendicular as the shader's anisoAnyPerpendicular and the core's
// Frame::fromNormalTangent.
glm::dvec3 anyPerpendicular(const glm::dvec3& n)
{
  const glm::dvec3 axis =
      std::abs(n.x) < 0.9 ? glm::dvec3(1.0, 0.0, 0.0) : glm::dvec3(0.0, 1.0, 0.0);
  return glm::normalize(axis - glm::dot(axis, n) * n);
}
} // namespace

void appendTriangles(TriangleMesh& scene, const TriangleMesh& part, int material,
                     const glm::dvec3& centre, double scale)
{
  validateMesh(part);
  if (scene.triangleMaterials.size() != scene.triangles.size())
  {
    scene.triangleMaterials.resize(scene.triangles.size(), 0);
  }
  const auto offset = static_cast<uint32_t>(scene.positions.size());
  for (const glm::dvec3& p : part.positions)
  {
    scene.positions.push_back((p - centre) / scale);
  }
  scene.normals.insert(scene.normals.end(), part.normals.begin(), part.normals.end());
  scene.tangents.insert(scene.tangents.end(), part.tangents.begin(), part.tangents.end());
  for (const auto& t : part.triangles)
  {
    scene.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
    scene.triangleMaterials.push_back(material);
  }
}

PixelRay pixelRay(const glm::dmat4& clipToWorld, int x, int y, int width, int height)
{
  const double ndcX = (x + 0.5) / width * 2.0 - 1.0;
  const double ndcY = 1.0 - (y + 0.5) / height * 2.0;
  const glm::dvec4 nearH = clipToWorld * glm::dvec4(ndcX, ndcY, -1.0, 1.0);
  const glm::dvec4 farH = clipToWorld * glm::dvec4(ndcX, ndcY, 1.0, 1.0);
  const glm::dvec3 nearPoint = glm::dvec3(nearH) / nearH.w;
  const glm::dvec3 farPoint = glm::dvec3(farH) / farH.w;
  return {nearPoint, glm::normalize(farPoint - nearPoint)};
}

std::vector<PixelSample> castPixels(const TriangleMesh& mesh, const glm::dmat4& clipToWorld,
                                    int width, int height)
{
  validateMesh(mesh);
  const Bvh bvh(mesh);
  std::vector<PixelSample> pixels(std::size_t(width) * std::size_t(height));
  parallelFor(
      height,
      [&](int y)
      {
        for (int x = 0; x < width; ++x)
        {
          const PixelRay ray = pixelRay(clipToWorld, x, y, width, height);
          uint32_t triangle = 0;
          double u = 0.0;
          double v = 0.0;
          if (!bvh.intersect(ray, triangle, u, v))
          {
            continue;
          }
          const auto& c = mesh.triangles[triangle];
          const double w = 1.0 - u - v;
          PixelSample& s = pixels[std::size_t(y) * width + x];
          s.hit = true;
          s.position =
              w * mesh.positions[c[0]] + u * mesh.positions[c[1]] + v * mesh.positions[c[2]];
          s.view = -ray.direction;
          s.material = mesh.triangleMaterials.empty() ? 0 : mesh.triangleMaterials[triangle];
          // Counter-clockwise triangles face the viewer when their geometric normal does.
          const glm::dvec3 face = glm::cross(mesh.positions[c[1]] - mesh.positions[c[0]],
                                             mesh.positions[c[2]] - mesh.positions[c[0]]);
          glm::dvec3 n = w * mesh.normals[c[0]] + u * mesh.normals[c[1]] + v * mesh.normals[c[2]];
          n = glm::dot(n, n) > 1e-24 ? glm::normalize(n) : glm::normalize(face);
          if (glm::dot(face, ray.direction) > 0.0)
          {
            n = -n;
          }
          const glm::dvec3 t =
              w * mesh.tangents[c[0]] + u * mesh.tangents[c[1]] + v * mesh.tangents[c[2]];
          const glm::dvec3 projected = t - glm::dot(t, n) * n;
          s.normal = n;
          s.tangent = glm::dot(projected, projected) > 1e-12 ? glm::normalize(projected)
                                                             : anyPerpendicular(n);
        }
      },
      4);
  return pixels;
}
} // namespace aniso
