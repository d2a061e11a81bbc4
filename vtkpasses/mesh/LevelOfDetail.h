#pragma once
// A coarse stand-in of a large surface, drawn while the view moves (the way ParaView draws a
// decimated "LOD" of large data during interaction): on a software rasteriser a render costs
// about in proportion to the triangles, whatever the pixels (llvmpipe: about 0.45 us per
// triangle, so 320 000 triangles take some 140 ms a render), which no reduction of samples,
// resolution or rows brings within an interactive frame.
//
// The stand-in is vtkQuadricClustering of the surface on a uniform grid of its bounding box,
// each output point one of the surface's own points (UseInputPoints), so every point array
// (normals, tangents, texture coordinates) is the surface's own value at that point, exactly. A
// hard edge or a UV seam, whose vertices are duplicated in the surface, keeps one of its
// duplicates; that shows only while moving.
#include <vtkSmartPointer.h>
#include <vtkType.h>

class vtkPolyData;

namespace aniso
{
// Surfaces of more than this many triangles get a stand-in while the view moves.
constexpr vtkIdType kInteractiveTriangleLimit = 100000;
// The stand-in's triangles at most.
constexpr vtkIdType kInteractiveTriangles = 40000;

// A part's stand-in in a file of many parts: the parts are drawn together, so a scene of many
// small parts is as slow to draw while moving as one large surface of their triangles. When the
// file's parts have more than LIMIT triangles together (SCENETRIANGLES), each part of
// PARTTRIANGLES gets its share of MAXTRIANGLES in proportion to its triangles (at least
// kInteractivePartTriangles): what interactiveLevelOfDetail is then asked for, a part at or under
// its share drawn as it is. 0 when the parts together are within LIMIT (no stand-in for any).
// One part alone is the single-surface rule: its stand-in when it is over LIMIT.
constexpr vtkIdType kInteractivePartTriangles = 16;
vtkIdType partStandInTriangles(vtkIdType partTriangles, vtkIdType sceneTriangles,
                               vtkIdType limit = kInteractiveTriangleLimit,
                               vtkIdType maxTriangles = kInteractiveTriangles);

// The stand-in of SURFACE (triangles, as prepareSurface returns them) with at most
// MAXTRIANGLES triangles, or null when the surface has no more than LIMIT triangles (it is drawn
// as it is).
vtkSmartPointer<vtkPolyData>
interactiveLevelOfDetail(vtkPolyData* surface, vtkIdType limit = kInteractiveTriangleLimit,
                         vtkIdType maxTriangles = kInteractiveTriangles);
} // namespace aniso
