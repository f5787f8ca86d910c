#include "vtkRadiosityCombine.h"
#include "vtkRadiosityAdapter.h"
#include "vtkRadiosityLightDefaults.h"

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
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"

#include <cmath>

namespace
{
const std::string kPrefix = "Radiosity_";

/// The arrays `arrays` of `data` as a table of `tuples` items; false with `error` naming
/// the first that is missing or of the wrong shape or type.
bool ReadTable(vtkFieldData* data, const std::vector<std::string>& arrays, vtkIdType tuples,
  radiosity::SolutionTable& table, std::string& error)
{
  table = radiosity::SolutionTable();
  table.Items = static_cast<size_t>(tuples);
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
      table.Floats.push_back(f->GetPointer(0));
    }
    else if (auto* d = vtkDoubleArray::FastDownCast(array))
    {
      table.Doubles.push_back(d->GetPointer(0));
    }
    else
    {
      error = "array '" + name + "' is a " + array->GetClassName() + "; solutions must be float or double";
      return false;
    }
  }
  if (!table.Floats.empty() && !table.Doubles.empty())
  {
    error = "the solution arrays mix float and double; use one type";
    return false;
  }
  return true;
}

/// out = `table` weighted by `weights`; false, with `error`, where the sum is not finite.
bool CombineInto(const radiosity::SolutionTable& table, const std::vector<double>& weights, vtkFloatArray* out,
  std::string& error)
{
  out->SetNumberOfComponents(3);
  out->SetNumberOfTuples(static_cast<vtkIdType>(table.Items));
  const auto pool = vtkRadiosityAdapter::SharedPool();
  radiosity::CombineTable(table, weights, out->GetPointer(0), pool.get());
  const vtkIdType bad = vtkRadiosityFirstNonFinite(out);
  if (bad >= 0)
  {
    error = "the combination is not finite at item " + std::to_string(bad) +
      "; a solution array or a light setting holds NaN or infinity";
    return false;
  }
  return true;
}

/// The lights of `data`: LightNames, else the names of its Radiosity_<name> arrays; "" or
/// why there are none to relight.
std::string FindLights(vtkPolyData* data, std::vector<std::string>& names)
{
  names = vtkRadiosityLightNames(data->GetFieldData());
  if (!data->GetFieldData()->GetAbstractArray("LightNames"))
  {
    vtkFieldData* source = data->GetPointData()->GetNumberOfArrays() > 0
      ? static_cast<vtkFieldData*>(data->GetPointData())
      : static_cast<vtkFieldData*>(data->GetCellData());
    for (int a = 0; a < source->GetNumberOfArrays(); ++a)
    {
      const char* name = source->GetArrayName(a);
      if (name && std::string(name).compare(0, kPrefix.size(), kPrefix) == 0)
      {
        names.push_back(std::string(name).substr(kPrefix.size()));
      }
    }
  }
  bool perLight = false;
  for (const std::string& name : names)
  {
    perLight = perLight || data->GetCellData()->GetAbstractArray((kPrefix + name).c_str()) ||
      data->GetPointData()->GetAbstractArray((kPrefix + name).c_str());
  }
  if (!perLight && data->GetCellData()->GetAbstractArray("Radiosity"))
  {
    return "the input holds one combined solution (SolutionMode StandardCombined); relighting needs the "
           "per-light solutions of LightTagged or StandardSeparate";
  }
  return names.empty() ? "the input has no lights (no field array 'LightNames' and no 'Radiosity_<name>' "
                         "arrays); run vtkLightTaggedRadiosity first"
                       : "";
}

/// Radiosity_<name> per light and, `withDirect`, Direct_<name> after them; "" or why the
/// direct parts cannot be had.
std::string ArrayNames(vtkPolyData* data, const std::vector<std::string>& names, bool withDirect,
  std::vector<std::string>& arrays)
{
  for (const std::string& name : names)
  {
    arrays.push_back(kPrefix + name);
  }
  if (!withDirect)
  {
    return "";
  }
  const std::string direct = "Direct_" + names[0];
  if (!data->GetPointData()->GetAbstractArray(direct.c_str()) && !data->GetCellData()->GetAbstractArray(direct.c_str()))
  {
    return "IndirectScale needs the arrays '" + direct + "' etc.; turn on SeparateDirect in the solver";
  }
  for (const std::string& name : names)
  {
    arrays.push_back("Direct_" + name);
  }
  return "";
}
} // namespace

bool vtkRadiosityCombineSolutions(vtkFieldData* data, const std::vector<std::string>& arrays,
  const std::vector<double>& weights, vtkIdType tuples, vtkFloatArray* out, std::string& error)
{
  radiosity::SolutionTable table;
  return ReadTable(data, arrays, tuples, table, error) && CombineInto(table, weights, out, error);
}

struct vtkRadiosityRelitInput::Internals
{
  std::vector<std::string> Names;
  std::vector<radiosity::Vec3> Defaults;
  radiosity::SolutionTable Points, Cells;
};

vtkRadiosityRelitInput::vtkRadiosityRelitInput()
  : Impl(new Internals)
{
}

vtkRadiosityRelitInput::~vtkRadiosityRelitInput() = default;

std::string vtkRadiosityRelitInput::ReadLights(vtkPolyData* data)
{
  Internals& in = *this->Impl;
  in = Internals();
  const std::string error = FindLights(data, in.Names);
  if (error.empty())
  {
    in.Defaults = vtkRadiosityLightDefaultColors(data, static_cast<int>(in.Names.size()));
  }
  return error;
}

std::string vtkRadiosityRelitInput::ReadTables(vtkPolyData* data, bool withDirect)
{
  Internals& in = *this->Impl;
  in.Points = in.Cells = radiosity::SolutionTable();
  std::vector<std::string> arrays;
  std::string error = in.Names.empty() ? "no lights read" : ArrayNames(data, in.Names, withDirect, arrays);
  if (!error.empty())
  {
    return error;
  }
  const std::pair<vtkFieldData*, vtkIdType> kinds[2] = { { data->GetPointData(), data->GetNumberOfPoints() },
    { data->GetCellData(), data->GetNumberOfCells() } };
  radiosity::SolutionTable* tables[2] = { &in.Points, &in.Cells };
  for (int k = 0; k < 2; ++k)
  {
    if (kinds[k].first->GetAbstractArray(arrays[0].c_str()) &&
      !ReadTable(kinds[k].first, arrays, kinds[k].second, *tables[k], error))
    {
      return error;
    }
  }
  return in.Points.Empty() && in.Cells.Empty() ? "no point or cell array '" + arrays[0] + "'" : "";
}

const std::vector<std::string>& vtkRadiosityRelitInput::GetNames() const
{
  return this->Impl->Names;
}

std::vector<radiosity::Vec3> vtkRadiosityRelitInput::GetDefaultColors() const
{
  return this->Impl->Defaults;
}

bool vtkRadiosityRelitInput::HasPoints() const
{
  return !this->Impl->Points.Empty();
}

bool vtkRadiosityRelitInput::HasCells() const
{
  return !this->Impl->Cells.Empty();
}

bool vtkRadiosityRelitInput::Combine(
  bool cells, const std::vector<double>& weights, vtkFloatArray* out, std::string& error) const
{
  return CombineInto(cells ? this->Impl->Cells : this->Impl->Points, weights, out, error);
}

std::vector<float> vtkRadiosityRelitInput::Interleaved(bool cells) const
{
  const radiosity::SolutionTable& table = cells ? this->Impl->Cells : this->Impl->Points;
  const size_t k = table.Floats.size() + table.Doubles.size();
  std::vector<float> values(table.Items * k * 3);
  for (size_t l = 0; l < k; ++l)
  {
    const float* floats = l < table.Floats.size() ? table.Floats[l] : nullptr;
    const double* doubles = floats ? nullptr : table.Doubles[l];
    for (size_t i = 0; i < table.Items; ++i)
    {
      for (size_t c = 0; c < 3; ++c)
      {
        values[(i * k + l) * 3 + c] = floats ? floats[3 * i + c] : static_cast<float>(doubles[3 * i + c]);
      }
    }
  }
  return values;
}

bool vtkRadiosityRelitInput::FindNonFinite(bool cells, size_t& item, size_t& light) const
{
  const radiosity::SolutionTable& table = cells ? this->Impl->Cells : this->Impl->Points;
  const size_t k = table.Floats.size() + table.Doubles.size();
  for (size_t l = 0; l < k; ++l)
  {
    const float* floats = l < table.Floats.size() ? table.Floats[l] : nullptr;
    const double* doubles = floats ? nullptr : table.Doubles[l];
    for (size_t i = 0; i < 3 * table.Items; ++i)
    {
      if (!std::isfinite(floats ? static_cast<double>(floats[i]) : doubles[i]))
      {
        item = i / 3;
        light = l;
        return true;
      }
    }
  }
  return false;
}

double vtkRadiosityRelitInput::MeterAtDefaults(vtkPolyData* data) const
{
  const bool cells = this->HasCells();
  const radiosity::SolutionTable& table = cells ? this->Impl->Cells : this->Impl->Points;
  // The direct parts, where the table holds them, weigh nothing here.
  std::vector<double> weights = vtkRadiosityFlatColors(this->Impl->Defaults);
  weights.resize(3 * (table.Floats.size() + table.Doubles.size()), 0.0);
  vtkNew<vtkFloatArray> sum;
  std::string error;
  return !this->Impl->Names.empty() && this->Combine(cells, weights, sum, error)
    ? vtkRadiosityMeteredExposure(data, sum, cells, 0.0)
    : 0.0;
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
