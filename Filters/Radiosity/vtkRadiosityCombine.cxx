#include "vtkRadiosityCombine.h"
#include "vtkRadiosityAdapter.h"

#include "Geometry/Polygon.h"
#include "Relight/Exposure.h"
#include "Relight/Relight.h"

#include "vtkDoubleArray.h"
#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellData.h"
#include "vtkFieldData.h"
#include "vtkPolyData.h"
#include "vtkFloatArray.h"
#include "vtkPoints.h"

#include <cmath>

bool vtkRadiosityCombineSolutions(vtkFieldData* data, const std::vector<std::string>& arrays,
  const std::vector<double>& weights, vtkIdType tuples, vtkFloatArray* out, std::string& error)
{
  std::vector<const float*> floats;
  std::vector<const double*> doubles;
  for (const std::string& name : arrays)
  {
    vtkAbstractArray* array = data->GetAbstractArray(name.c_str());
    if (!array)
    {
      error = "array '" + name + "' is missing";
      return false;
    }
    if (array->GetNumberOfComponents() != 3 || array->GetNumberOfTuples() != tuples)
    {
      error = "array '" + name + "' must have 3 components and one tuple per item";
      return false;
    }
    if (auto* f = vtkFloatArray::FastDownCast(array))
    {
      floats.push_back(f->GetPointer(0));
    }
    else if (auto* d = vtkDoubleArray::FastDownCast(array))
    {
      doubles.push_back(d->GetPointer(0));
    }
    else
    {
      error = "array '" + name + "' is a " + array->GetClassName() +
        "; solutions must be float or double";
      return false;
    }
  }
  if (!floats.empty() && !doubles.empty())
  {
    error = "the solution arrays mix float and double; use one type";
    return false;
  }
  out->SetNumberOfComponents(3);
  out->SetNumberOfTuples(tuples);
  const auto pool = vtkRadiosityAdapter::SharedPool();
  if (!floats.empty())
  {
    radiosity::CombineLights(floats, weights, static_cast<size_t>(tuples), out->GetPointer(0), pool.get());
  }
  else
  {
    radiosity::CombineLights(doubles, weights, static_cast<size_t>(tuples), out->GetPointer(0), pool.get());
  }
  const vtkIdType bad = vtkRadiosityFirstNonFinite(out);
  if (bad >= 0)
  {
    error = "the combination is not finite at item " + std::to_string(bad) +
      "; a solution array or a light setting holds NaN or infinity";
    return false;
  }
  return true;
}

namespace
{
/// Each polygon's area (`cells`), or each point's share of its polygons' (a third of each
/// triangle's, a quarter of each quad's); other cells count nothing.
std::vector<double> Areas(vtkPolyData* data, bool cells)
{
  std::vector<double> area(cells ? data->GetNumberOfCells() : data->GetNumberOfPoints(), 0.0);
  vtkPoints* points = data->GetPoints();
  if (!points)
  {
    return {};
  }
  const vtkIdType first = data->GetNumberOfVerts() + data->GetNumberOfLines();
  auto polygons = vtk::TakeSmartPointer(data->GetPolys()->NewIterator());
  vtkIdType c = first;
  std::vector<radiosity::Vec3> loop;
  for (polygons->GoToFirstCell(); !polygons->IsDoneWithTraversal(); polygons->GoToNextCell(), ++c)
  {
    vtkIdType count;
    const vtkIdType* ids;
    polygons->GetCurrentCell(count, ids);
    loop.clear();
    for (vtkIdType k = 0; k < count; ++k)
    {
      double p[3];
      points->GetPoint(ids[k], p);
      loop.push_back({ p[0], p[1], p[2] });
    }
    const double a = count >= 3 ? radiosity::PolygonArea(loop.data(), static_cast<int>(count)) : 0.0;
    if (cells)
    {
      area[c] = a;
      continue;
    }
    for (vtkIdType k = 0; k < count; ++k)
    {
      area[ids[k]] += a / static_cast<double>(count);
    }
  }
  return area;
}

/// Per cell (or per point, for the points of such cells) whether it emits (LightId >= 0).
std::vector<char> Emitters(vtkPolyData* data, bool cells)
{
  vtkDataArray* lightId = data->GetCellData()->GetArray("LightId");
  std::vector<char> emits;
  if (!lightId || lightId->GetNumberOfTuples() != data->GetNumberOfCells())
  {
    return emits;
  }
  emits.assign(cells ? data->GetNumberOfCells() : data->GetNumberOfPoints(), 0);
  if (cells)
  {
    for (vtkIdType c = 0; c < lightId->GetNumberOfTuples(); ++c)
    {
      emits[c] = lightId->GetComponent(c, 0) >= 0 ? 1 : 0;
    }
    return emits;
  }
  // Only polygons carry light (the mesher's and solver's output holds nothing else).
  const vtkIdType first = data->GetNumberOfVerts() + data->GetNumberOfLines();
  auto polygons = vtk::TakeSmartPointer(data->GetPolys()->NewIterator());
  vtkIdType c = first;
  for (polygons->GoToFirstCell(); !polygons->IsDoneWithTraversal(); polygons->GoToNextCell(), ++c)
  {
    vtkIdType count;
    const vtkIdType* ids;
    polygons->GetCurrentCell(count, ids);
    for (vtkIdType k = 0; k < count && lightId->GetComponent(c, 0) >= 0; ++k)
    {
      emits[ids[k]] = 1;
    }
  }
  return emits;
}
} // namespace

double vtkRadiosityMeteredExposure(vtkPolyData* data, vtkFloatArray* relit, bool cells, double unlit)
{
  const std::vector<char> emits = Emitters(data, cells);
  const size_t n = static_cast<size_t>(relit->GetNumberOfTuples());
  return radiosity::MeteredExposure(relit->GetPointer(0), n, emits.size() == n ? emits : std::vector<char>(), unlit,
    Areas(data, cells));
}

vtkIdType vtkRadiosityFirstNonFinite(vtkFloatArray* values)
{
  const float* v = values->GetPointer(0);
  for (vtkIdType i = 0; i < 3 * values->GetNumberOfTuples(); ++i)
  {
    if (!std::isfinite(v[i]))
    {
      return i / 3;
    }
  }
  return -1;
}
