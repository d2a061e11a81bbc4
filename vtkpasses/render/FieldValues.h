#pragma once
// A data field's values on a surface's points (core/fields/field_mapping.h): the array named by
// the field, point data as it is, cell data averaged to the points (each point takes the mean
// of the finite values of the triangles around it; NaN where none is finite), one value per
// tuple (a component or the magnitude). What a material draws the field with, and the range a
// scene resolves "auto" to.
#include "core/fields/field_mapping.h"
#include "vtkpasses/render/MaterialSettings.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>
#include <vtkSmartPointer.h>

class vtkPolyData;
class vtkScalarBarActor;

namespace aniso
{
struct FieldStatistics
{
  bool perCell = false;
  int components = 0;
  int64_t values = 0;    // tuples of the array
  int64_t nonFinite = 0; // tuples that give NaN (a NaN or Inf used, or no such component)
  double minimum = 0.0;  // over the finite values; NaN when there is none
  double maximum = 0.0;
};

// SPEC's array on SURFACE (a point array first, else a cell array of that name) and its
// statistics, or nullopt when the surface has no numeric array of that name.
std::optional<FieldStatistics> fieldStatistics(vtkPolyData* surface, const FieldSpec& spec);

// The finite range over several surfaces' statistics (the parts that show one field), or
// nullopt when none has a finite value.
std::optional<FieldRange> jointFieldRange(const std::vector<FieldStatistics>& statistics);

// SPEC's values on SURFACE's points (cell data averaged as above), NaN where not finite; empty
// when the surface has no such array.
std::vector<double> fieldPointValues(vtkPolyData* surface, const FieldSpec& spec);

// Writes fieldPointValues as the point array NAME, replacing one of that name: float2, the value
// less OFFSET (returned: the finite mean of the values, so that data far from zero keeps its
// precision in single precision) and 1 where the value is NaN (0 elsewhere; the value is then
// 0). Removes NAME and returns nullopt when the surface has no such array.
std::optional<double> writeFieldValues(vtkPolyData* surface, const FieldSpec& spec,
                                       const char* name);
// A scene's automatic field ranges, resolved as ParaView colours an array of a multiblock dataset:
// every material MATERIALS[i] (drawing SURFACES[i]) whose field's range is automatic gets the
// joint finite range of that array (and component) over all the surfaces whose materials show
// it. A field with no finite value anywhere keeps its automatic range (each mesh then maps its
// own, none).
void resolveFieldRanges(const std::vector<vtkPolyData*>& surfaces,
                        const std::vector<MaterialSettings*>& materials);

// A colour legend of a field shown through a colour map (albedo or F0): its title (the array,
// and the component), colour map and resolved range.
struct FieldLegend
{
  std::string title;
  ColorMap colorMap = ColorMap::Viridis;
  double minimum = 0.0;
  double maximum = 1.0;
  bool operator==(const FieldLegend& o) const
  {
    return title == o.title && colorMap == o.colorMap && minimum == o.minimum &&
           maximum == o.maximum;
  }
};
// The distinct legends of MATERIALS' colour fields with resolved ranges, in order.
std::vector<FieldLegend> fieldLegends(const std::vector<const MaterialSettings*>& materials);
// The legend as VTK draws one: a vertical colour bar at the right of the view (the INDEX-th from
// the right edge), its colours the map's sRGB display colours with the preset's NaN colour shown.
vtkSmartPointer<vtkScalarBarActor> makeFieldLegendActor(const FieldLegend& legend, int index);
} // namespace aniso
