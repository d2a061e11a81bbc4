#include "vtkpasses/render/FieldValues.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkFloatArray.h>
#include <vtkIdList.h>
#include <vtkLookupTable.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkScalarBarActor.h>
#include <vtkTextProperty.h>

namespace aniso
{
namespace
{
// SPEC's array as point data, else as cell data (perCell set), else null.
vtkDataArray* fieldArray(vtkPolyData* surface, const FieldSpec& spec, bool& perCell)
{
  if (!surface)
  {
    return nullptr;
  }
  perCell = false;
  if (vtkDataArray* a = surface->GetPointData()->GetArray(spec.array.c_str()))
  {
    return a;
  }
  perCell = true;
  return surface->GetCellData()->GetArray(spec.array.c_str());
}

std::vector<double> tupleValues(vtkDataArray* array, const FieldSpec& spec)
{
  const int components = array->GetNumberOfComponents();
  std::vector<double> tuple(static_cast<std::size_t>(std::max(components, 1)));
  std::vector<double> values(static_cast<std::size_t>(array->GetNumberOfTuples()));
  for (vtkIdType i = 0; i < array->GetNumberOfTuples(); ++i)
  {
    array->GetTuple(i, tuple.data());
    values[static_cast<std::size_t>(i)] = fieldValue(spec, tuple.data(), components);
  }
  return values;
}
} // namespace

std::optional<FieldStatistics> fieldStatistics(vtkPolyData* surface, const FieldSpec& spec)
{
  bool perCell = false;
  vtkDataArray* array = fieldArray(surface, spec, perCell);
  if (!array)
  {
    return std::nullopt;
  }
  FieldStatistics s;
  s.perCell = perCell;
  s.components = array->GetNumberOfComponents();
  s.values = array->GetNumberOfTuples();
  s.minimum = std::numeric_limits<double>::infinity();
  s.maximum = -std::numeric_limits<double>::infinity();
  for (double v : tupleValues(array, spec))
  {
    if (std::isnan(v))
    {
      ++s.nonFinite;
      continue;
    }
    s.minimum = std::min(s.minimum, v);
    s.maximum = std::max(s.maximum, v);
  }
  if (s.nonFinite == s.values)
  {
    s.minimum = s.maximum = std::numeric_limits<double>::quiet_NaN();
  }
  return s;
}

std::optional<FieldRange> jointFieldRange(const std::vector<FieldStatistics>& statistics)
{
  FieldRange range;
  range.automatic = false;
  range.min = std::numeric_limits<double>::infinity();
  range.max = -std::numeric_limits<double>::infinity();
  for (const FieldStatistics& s : statistics)
  {
    if (!std::isnan(s.minimum))
    {
      range.min = std::min(range.min, s.minimum);
      range.max = std::max(range.max, s.maximum);
    }
  }
  if (!(range.min <= range.max))
  {
    return std::nullopt;
  }
  return range;
}

std::vector<double> fieldPointValues(vtkPolyData* surface, const FieldSpec& spec)
{
  bool perCell = false;
  vtkDataArray* array = fieldArray(surface, spec, perCell);
  if (!array)
  {
    return {};
  }
  const std::vector<double> values = tupleValues(array, spec);
  if (!perCell)
  {
    return values;
  }
  // Cells to points: the mean of the finite values of the cells (triangles, kept one value per
  // triangle by MeshValidation) around each point.
  const vtkIdType points = surface->GetNumberOfPoints();
  std::vector<double> sum(static_cast<std::size_t>(points), 0.0);
  std::vector<int> count(static_cast<std::size_t>(points), 0);
  vtkIdType cell = 0;
  const auto visit = [&](vtkCellArray* cells)
  {
    if (!cells)
    {
      return;
    }
    vtkIdType n = 0;
    const vtkIdType* ids = nullptr;
    for (cells->InitTraversal(); cells->GetNextCell(n, ids); ++cell)
    {
      if (cell >= static_cast<vtkIdType>(values.size()))
      {
        return;
      }
      const double v = values[static_cast<std::size_t>(cell)];
      if (std::isnan(v))
      {
        continue;
      }
      for (vtkIdType k = 0; k < n; ++k)
      {
        if (ids[k] >= 0 && ids[k] < points)
        {
          sum[static_cast<std::size_t>(ids[k])] += v;
          ++count[static_cast<std::size_t>(ids[k])];
        }
      }
    }
  };
  // Cell ids run over verts, lines, polys and strips in that order (vtkPolyData's numbering).
  visit(surface->GetVerts());
  visit(surface->GetLines());
  visit(surface->GetPolys());
  visit(surface->GetStrips());
  std::vector<double> out(static_cast<std::size_t>(points));
  for (std::size_t i = 0; i < out.size(); ++i)
  {
    out[i] = count[i] ? sum[i] / count[i] : std::numeric_limits<double>::quiet_NaN();
  }
  return out;
}

std::optional<double> writeFieldValues(vtkPolyData* surface, const FieldSpec& spec,
                                       const char* name)
{
  const std::vector<double> values = fieldPointValues(surface, spec);
  if (values.empty() || static_cast<vtkIdType>(values.size()) != surface->GetNumberOfPoints())
  {
    if (surface && surface->GetPointData()->GetArray(name))
    {
      surface->GetPointData()->RemoveArray(name);
    }
    return std::nullopt;
  }
  double sum = 0.0;
  std::size_t finite = 0;
  for (double v : values)
  {
    if (!std::isnan(v))
    {
      sum += v;
      ++finite;
    }
  }
  const double offset = finite ? sum / double(finite) : 0.0;
  vtkNew<vtkFloatArray> out;
  out->SetName(name);
  out->SetNumberOfComponents(2);
  out->SetNumberOfTuples(static_cast<vtkIdType>(values.size()));
  const double largest = std::numeric_limits<float>::max();
  for (std::size_t i = 0; i < values.size(); ++i)
  {
    const bool nan = std::isnan(values[i]);
    // A difference beyond float's range is clamped to it rather than made infinite.
    const double relative = nan ? 0.0 : std::clamp(values[i] - offset, -largest, largest);
    out->SetTypedComponent(static_cast<vtkIdType>(i), 0, static_cast<float>(relative));
    out->SetTypedComponent(static_cast<vtkIdType>(i), 1, nan ? 1.0f : 0.0f);
  }
  surface->GetPointData()->AddArray(out);
  return offset;
}
void resolveFieldRanges(const std::vector<vtkPolyData*>& surfaces,
                        const std::vector<MaterialSettings*>& materials)
{
  for (MaterialSettings* m : materials)
  {
    if (!m || !m->field || !m->field->range.automatic)
    {
      continue;
    }
    const FieldSpec spec = m->field->spec;
    std::vector<FieldStatistics> statistics;
    for (std::size_t i = 0; i < surfaces.size() && i < materials.size(); ++i)
    {
      const MaterialSettings* other = materials[i];
      if (other && other->field && other->field->spec == spec)
      {
        if (const auto s = fieldStatistics(surfaces[i], spec))
        {
          statistics.push_back(*s);
        }
      }
    }
    if (const auto range = jointFieldRange(statistics))
    {
      m->field->range = *range;
    }
  }
}

std::vector<FieldLegend> fieldLegends(const std::vector<const MaterialSettings*>& materials)
{
  std::vector<FieldLegend> legends;
  for (const MaterialSettings* m : materials)
  {
    if (!m || !m->field || !m->field->colors() || m->field->range.automatic)
    {
      continue;
    }
    const FieldMapping& f = *m->field;
    FieldLegend legend;
    legend.title = f.spec.array;
    if (f.spec.component >= 0)
    {
      legend.title += " [" + std::to_string(f.spec.component) + "]";
    }
    legend.colorMap = f.colorMap;
    legend.minimum = f.range.min;
    legend.maximum = f.range.max;
    if (std::find(legends.begin(), legends.end(), legend) == legends.end())
    {
      legends.push_back(legend);
    }
  }
  return legends;
}

vtkSmartPointer<vtkScalarBarActor> makeFieldLegendActor(const FieldLegend& legend, int index)
{
  constexpr int kColors = 256;
  vtkNew<vtkLookupTable> table;
  table->SetNumberOfTableValues(kColors);
  table->SetRange(legend.minimum, legend.maximum);
  for (int i = 0; i < kColors; ++i)
  {
    const glm::dvec3 c = colorMapColor(legend.colorMap, double(i) / (kColors - 1));
    table->SetTableValue(i, c.x, c.y, c.z, 1.0);
  }
  const glm::dvec3 nan = colorMapNanColor(legend.colorMap);
  table->SetNanColor(nan.x, nan.y, nan.z, 1.0);
  auto bar = vtkSmartPointer<vtkScalarBarActor>::New();
  bar->SetLookupTable(table);
  bar->SetTitle(legend.title.c_str());
  bar->SetNumberOfLabels(5);
  bar->SetOrientationToVertical();
  bar->SetPosition(0.85 - 0.14 * index, 0.1);
  bar->SetPosition2(0.14, 0.8); // width and height, normalised viewport
  bar->SetMaximumWidthInPixels(120);
  bar->SetTextPositionToPrecedeScalarBar();
  bar->DrawNanAnnotationOn();
  bar->SetNanAnnotation("NaN");
  for (vtkTextProperty* text :
       {bar->GetTitleTextProperty(), bar->GetLabelTextProperty(), bar->GetAnnotationTextProperty()})
  {
    text->SetColor(1.0, 1.0, 1.0);
    text->SetShadow(1);
    text->SetItalic(0);
    text->SetBold(0);
    text->SetFontSize(12);
  }
  return bar;
}
} // namespace aniso
