#pragma once
// What each pixel of a render sees, computed on the CPU from the same triangles the GPU draws:
// the first hit of the ray through the pixel centre, with the normal and tangent interpolated
// at the hit as the material's shaders do (barycentric, i.e. perspective-correct; the normal
// normalised and reversed on back faces, the tangent made orthogonal to it by Gram-Schmidt). The
// CPU reference integrator then shades exactly the frames the shader shades. GL-free.
#include <array>
#include <cstdint>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <vector>

namespace aniso
{
// A triangle mesh as plain arrays: the point arrays "Normals" and "Tangents" of a prepared
// surface (SurfacePreparation.h), one entry per point; a scene of parts is one mesh whose
// triangles say which part's material they take (empty: all the first).
struct TriangleMesh
{
  std::vector<glm::dvec3> positions;
  std::vector<glm::dvec3> normals;
  std::vector<glm::dvec3> tangents;
  std::vector<std::array<uint32_t, 3>> triangles;
  std::vector<int> triangleMaterials; // per triangle, or empty
};

struct PixelSample
{
  bool hit = false;
  glm::dvec3 position{0.0};
  glm::dvec3 normal{0.0, 0.0, 1.0};  // unit; reversed when the triangle is seen from behind
  glm::dvec3 tangent{1.0, 0.0, 0.0}; // unit, orthogonal to normal
  glm::dvec3 view{0.0, 0.0, 1.0};    // unit, from the hit towards the eye
  int material = 0;                  // the hit triangle's (TriangleMesh::triangleMaterials)
};

// Ray through the centre of pixel (x, y), row 0 at the top, of a width x height image drawn
// with CLIP_TO_WORLD (the inverse of the matrix the mappers draw with): from the near plane
// towards the far plane, as the shader reconstructs its view rays.
struct PixelRay
{
  glm::dvec3 origin;
  glm::dvec3 direction; // unit
};
PixelRay pixelRay(const glm::dmat4& clipToWorld, int x, int y, int width, int height);

// Appends PART's triangles to SCENE, its positions mapped p -> (p - centre) / scale (a scene drawn
// in the frame of its bounding sphere, vtkpasses/render/DrawingFrame.h), its triangles taking
// MATERIAL.
void appendTriangles(TriangleMesh& scene, const TriangleMesh& part, int material,
                     const glm::dvec3& centre = glm::dvec3(0.0), double scale = 1.0);

// Every pixel of the image, row-major from the top row. Rays run on all hardware threads.
// Throws aniso::Error "mesh: reason" for inconsistent arrays or out-of-range indices.
std::vector<PixelSample> castPixels(const TriangleMesh& mesh, const glm::dmat4& clipToWorld,
                                    int width, int height);
} // namespace aniso
