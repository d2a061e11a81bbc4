#include "bench/flange_mesh.h"

#include <array>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <map>
#include <vector>
#include <vtkCellArray.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

namespace aniso::bench
{
namespace
{
// Dimensions (outer radius 1).
constexpr double kOuter = 1.0;
constexpr double kThickness = 0.18;
constexpr double kRimChamfer = 0.03;
constexpr double kHub = 0.42;
constexpr double kHubTop = 0.55;
constexpr double kHubChamfer = 0.03;
constexpr double kFillet = 0.06;
constexpr double kBore = 0.25;
constexpr double kHolePitch = 0.72;
constexpr double kHole = 0.07;

// Resolution.
constexpr int kSectors = 6;                 // one bolt hole per sector
constexpr int kArc = 32;                    // segments per sector arc
constexpr int kAround = kSectors * kArc;    // segments of every turned face
constexpr int kSide = 12;                   // segments along a sector's radial sides
constexpr int kLoop = 2 * kArc + 2 * kSide; // points around a hole and around its sector
constexpr int kLayers = 10;                 // rings between a hole and its sector's boundary
constexpr int kFilletSegments = 8;

// Every point is computed from integer indices by these functions only, so a point shared by
// two faces comes out bitwise equal from both and is merged.
glm::dvec3 onCircle(double radius, int step, double z)
{
  const double angle = 2.0 * M_PI * (step % kAround) / kAround;
  return {radius * std::cos(angle), radius * std::sin(angle), z};
}

double sideRadius(double inner, double outer, int i)
{
  return i == kSide ? outer : inner + (outer - inner) * i / kSide;
}

class Builder
{
public:
  vtkIdType point(const glm::dvec3& p)
  {
    const std::array<double, 3> key{p.x, p.y, p.z};
    const auto found = ids_.find(key);
    if (found != ids_.end())
    {
      return found->second;
    }
    const vtkIdType id = points_->InsertNextPoint(p.x, p.y, p.z);
    ids_.emplace(key, id);
    return id;
  }

  // Two triangles, wound so that their normal agrees with OUTWARD.
  void quad(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c, const glm::dvec3& d,
            const glm::dvec3& outward)
  {
    triangle(a, b, c, outward);
    triangle(a, c, d, outward);
  }

  vtkSmartPointer<vtkPolyData> finish()
  {
    auto poly = vtkSmartPointer<vtkPolyData>::New();
    poly->SetPoints(points_);
    poly->SetPolys(triangles_);
    return poly;
  }

private:
  void triangle(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c,
                const glm::dvec3& outward)
  {
    const glm::dvec3 normal = glm::cross(b - a, c - a);
    if (glm::dot(normal, normal) == 0.0)
    {
      return; // a degenerate corner of the grid
    }
    vtkIdType ids[3] = {point(a), point(b), point(c)};
    if (glm::dot(normal, outward) < 0.0)
    {
      std::swap(ids[1], ids[2]);
    }
    triangles_->InsertNextCell(3, ids);
  }

  std::map<std::array<double, 3>, vtkIdType> ids_;
  vtkSmartPointer<vtkPoints> points_ = vtkSmartPointer<vtkPoints>::New();
  vtkSmartPointer<vtkCellArray> triangles_ = vtkSmartPointer<vtkCellArray>::New();
};

// A profile (r, z) traversed with the solid on its left, turned about Z.
void revolve(const std::vector<glm::dvec2>& profile, Builder& builder)
{
  for (std::size_t i = 0; i + 1 < profile.size(); ++i)
  {
    const glm::dvec2 d = profile[i + 1] - profile[i];
    const glm::dvec2 outward2 = glm::normalize(glm::dvec2(d.y, -d.x));
    for (int j = 0; j < kAround; ++j)
    {
      const double middle = 2.0 * M_PI * (j + 0.5) / kAround;
      const glm::dvec3 outward(outward2.x * std::cos(middle), outward2.x * std::sin(middle),
                               outward2.y);
      builder.quad(onCircle(profile[i].x, j, profile[i].y),
                   onCircle(profile[i + 1].x, j, profile[i + 1].y),
                   onCircle(profile[i + 1].x, j + 1, profile[i + 1].y),
                   onCircle(profile[i].x, j + 1, profile[i].y), outward);
    }
  }
}

// The boundary of sector k of a flat annulus (inner, outer) at height z, counter-clockwise seen
// from +Z: up its first radial side, along the outer arc, down the second side, back along the
// inner arc.
std::vector<glm::dvec3> sectorLoop(int k, double inner, double outer, double z)
{
  std::vector<glm::dvec3> loop;
  loop.reserve(kLoop);
  const int first = k * kArc;
  const int last = first + kArc;
  for (int i = 0; i < kSide; ++i)
  {
    loop.push_back(onCircle(sideRadius(inner, outer, i), first, z));
  }
  for (int a = 0; a < kArc; ++a)
  {
    loop.push_back(onCircle(outer, first + a, z));
  }
  for (int i = kSide; i > 0; --i)
  {
    loop.push_back(onCircle(sideRadius(inner, outer, i), last, z));
  }
  for (int a = kArc; a > 0; --a)
  {
    loop.push_back(onCircle(inner, first + a, z));
  }
  return loop;
}

glm::dvec3 holeCentre(int k, double z)
{
  return onCircle(kHolePitch, k * kArc + kArc / 2, z);
}

// Points around hole k, one per point of its sector's loop, at the loop point's azimuth seen
// from the hole centre (taken from the top face's loop, so both faces share the hole's points).
std::vector<glm::dvec3> holeLoop(int k, double z)
{
  const std::vector<glm::dvec3> reference =
      sectorLoop(k, kHub + kFillet, kOuter - kRimChamfer, kThickness);
  const glm::dvec3 centre = holeCentre(k, z);
  std::vector<glm::dvec3> hole;
  hole.reserve(reference.size());
  for (const glm::dvec3& p : reference)
  {
    const double azimuth = std::atan2(p.y - centre.y, p.x - centre.x);
    hole.push_back(centre + kHole * glm::dvec3(std::cos(azimuth), std::sin(azimuth), 0.0));
  }
  return hole;
}

// A flat annulus with one hole per sector: rings interpolated from each hole to its sector's
// boundary (an O-grid), the last ring being the boundary itself.
void holedAnnulus(double inner, double outer, double z, const glm::dvec3& outward, Builder& builder)
{
  for (int k = 0; k < kSectors; ++k)
  {
    const std::vector<glm::dvec3> boundary = sectorLoop(k, inner, outer, z);
    const std::vector<glm::dvec3> hole = holeLoop(k, z);
    auto ring = [&](int layer, int m)
    {
      const std::size_t i = static_cast<std::size_t>(m % kLoop);
      if (layer == kLayers)
      {
        return boundary[i];
      }
      const double t = double(layer) / kLayers;
      return hole[i] + t * (boundary[i] - hole[i]);
    };
    for (int layer = 0; layer < kLayers; ++layer)
    {
      for (int m = 0; m < kLoop; ++m)
      {
        builder.quad(ring(layer, m), ring(layer + 1, m), ring(layer + 1, m + 1), ring(layer, m + 1),
                     outward);
      }
    }
  }
}

void holeWalls(Builder& builder)
{
  for (int k = 0; k < kSectors; ++k)
  {
    const std::vector<glm::dvec3> bottom = holeLoop(k, 0.0);
    const std::vector<glm::dvec3> top = holeLoop(k, kThickness);
    const glm::dvec3 centre = holeCentre(k, 0.0);
    for (int m = 0; m < kLoop; ++m)
    {
      const std::size_t a = static_cast<std::size_t>(m);
      const std::size_t b = static_cast<std::size_t>((m + 1) % kLoop);
      // The solid lies outside the hole: its surface faces the hole's axis.
      const glm::dvec3 middle = 0.5 * (bottom[a] + bottom[b]);
      const glm::dvec3 outward = glm::dvec3(centre.x - middle.x, centre.y - middle.y, 0.0);
      builder.quad(bottom[a], bottom[b], top[b], top[a], outward);
    }
  }
}
} // namespace

vtkSmartPointer<vtkPolyData> makeFlange()
{
  Builder builder;
  revolve({{kOuter, 0.0}, {kOuter, kThickness - kRimChamfer}, {kOuter - kRimChamfer, kThickness}},
          builder);
  std::vector<glm::dvec2> hub;
  for (int i = 0; i <= kFilletSegments; ++i)
  {
    // Concave fillet between the flange's top face and the hub, centred outside the solid.
    const double a = 0.5 * M_PI * i / kFilletSegments;
    hub.push_back(
        {kHub + kFillet - kFillet * std::sin(a), kThickness + kFillet - kFillet * std::cos(a)});
  }
  // The ends exactly where the neighbouring faces start.
  hub.front() = {kHub + kFillet, kThickness};
  hub.back() = {kHub, kThickness + kFillet};
  hub.push_back({kHub, kHubTop - kHubChamfer});
  hub.push_back({kHub - kHubChamfer, kHubTop});
  hub.push_back({kBore, kHubTop});
  hub.push_back({kBore, 0.0});
  revolve(hub, builder);
  holedAnnulus(kBore, kOuter, 0.0, {0.0, 0.0, -1.0}, builder);
  holedAnnulus(kHub + kFillet, kOuter - kRimChamfer, kThickness, {0.0, 0.0, 1.0}, builder);
  holeWalls(builder);
  return builder.finish();
}
} // namespace aniso::bench
