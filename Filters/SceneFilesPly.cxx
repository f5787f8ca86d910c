// PLY through vtkPLYReader: face colours, or else the mean of the corners' colours, as
// each polygon's reflectance (8-bit sRGB made linear). PLY has no materials or emission:
// the whole file is one material named after it, and lights are marked afterwards.
#include "SceneFiles.h"
#include "SceneFilesErrors.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkNew.h"
#include "vtkPLYReader.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"

#include <vtksys/SystemTools.hxx>

#include <cmath>

namespace SceneFiles
{
namespace
{

vtkDataArray* Colours(vtkDataSetAttributes* attributes)
{
  for (const char* name : { "RGB", "RGBA" })
  {
    vtkDataArray* array = attributes->GetArray(name);
    if (array && array->GetNumberOfComponents() >= 3)
    {
      return array;
    }
  }
  return nullptr;
}

radiosity::Vec3 Linear(vtkDataArray* colours, vtkIdType i)
{
  auto channel = [&](int c) { return SrgbToLinear(colours->GetComponent(i, c) / 255.0); };
  return { channel(0), channel(1), channel(2) };
}

/// Each polygon's colour: its own, or the mean of its corners'; empty if the file has none.
std::vector<radiosity::Vec3> PolygonColours(vtkPolyData* data)
{
  std::vector<radiosity::Vec3> colours;
  if (vtkDataArray* cells = Colours(data->GetCellData()))
  {
    const vtkIdType base = data->GetNumberOfVerts() + data->GetNumberOfLines();
    for (vtkIdType c = 0; c < data->GetNumberOfPolys(); ++c)
    {
      colours.push_back(Linear(cells, base + c));
    }
    return colours;
  }
  vtkDataArray* points = Colours(data->GetPointData());
  if (!points)
  {
    return colours;
  }
  auto iterator = vtk::TakeSmartPointer(data->GetPolys()->NewIterator());
  for (iterator->GoToFirstCell(); !iterator->IsDoneWithTraversal(); iterator->GoToNextCell())
  {
    vtkIdType count = 0;
    const vtkIdType* ids = nullptr;
    iterator->GetCurrentCell(count, ids);
    radiosity::Vec3 sum;
    for (vtkIdType k = 0; k < count; ++k)
    {
      sum += Linear(points, ids[k]);
    }
    colours.push_back(sum * (count ? 1.0 / count : 0.0));
  }
  return colours;
}

} // namespace

std::string ReadPly(const std::string& path, radiosity::RawScene& raw, std::vector<std::string>& warnings)
{
  vtkNew<vtkPLYReader> reader;
  reader->SetFileName(path.c_str());
  const ErrorCapture capture(reader);
  reader->Update();
  vtkPolyData* data = reader->GetOutput();
  if (!capture.Message().empty() || data->GetNumberOfPolys() == 0)
  {
    return "'" + path + "' has no polygons readable as PLY" +
      (capture.Message().empty() ? std::string() : " (" + capture.Message() + ")");
  }
  radiosity::ImportMaterial material;
  material.Name = vtksys::SystemTools::GetFilenameWithoutLastExtension(path);
  material.Diffuse = { 1, 1, 1 };
  const std::vector<radiosity::Vec3> colours = PolygonColours(data);
  if (colours.empty())
  {
    material.Diffuse = { 0.8, 0.8, 0.8 };
    warnings.push_back("the PLY has no colours: reflectance 0.8");
  }
  raw.materials.push_back(material);
  const int first = raw.NumberOfPolygons();
  if (AppendPolygons(data, nullptr, 0, -1, raw))
  {
    warnings.push_back("points and lines in the PLY are not surfaces; left out");
  }
  if (!colours.empty())
  {
    raw.colour.resize(first, { 1, 1, 1 });
    raw.colour.insert(raw.colour.end(), colours.begin(), colours.end());
    raw.colour.resize(raw.NumberOfPolygons(), { 1, 1, 1 }); // strips' triangles, if any
  }
  return std::string();
}

}
