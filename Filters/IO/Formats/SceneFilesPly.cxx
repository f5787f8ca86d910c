// PLY through vtkPLYReader: face colors, or else the mean of the corners' colors, as
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

vtkDataArray* Colors(vtkDataSetAttributes* attributes)
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

radiosity::Vec3 Linear(vtkDataArray* colors, vtkIdType i)
{
  auto channel = [&](int c) { return SrgbToLinear(colors->GetComponent(i, c) / 255.0); };
  return { channel(0), channel(1), channel(2) };
}

/// Each polygon's color: its own, or the mean of its corners'; empty if the file has none.
std::vector<radiosity::Vec3> PolygonColors(vtkPolyData* data)
{
  std::vector<radiosity::Vec3> colors;
  if (vtkDataArray* cells = Colors(data->GetCellData()))
  {
    const vtkIdType base = data->GetNumberOfVerts() + data->GetNumberOfLines();
    for (vtkIdType c = 0; c < data->GetNumberOfPolys(); ++c)
    {
      colors.push_back(Linear(cells, base + c));
    }
    return colors;
  }
  vtkDataArray* points = Colors(data->GetPointData());
  if (!points)
  {
    return colors;
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
    colors.push_back(sum * (count ? 1.0 / count : 0.0));
  }
  return colors;
}

} // namespace

std::string ReadPly(const std::string& path, radiosity::RawScene& raw, std::vector<std::string>& warnings)
{
  bool realColors = false;
  const std::string unsafe = CheckPly(path, &realColors);
  if (!unsafe.empty())
  {
    return unsafe;
  }
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
  const std::vector<radiosity::Vec3> colors = realColors ? std::vector<radiosity::Vec3>() : PolygonColors(data);
  if (colors.empty())
  {
    material.Diffuse = { 0.8, 0.8, 0.8 };
    warnings.push_back(realColors ? "the PLY's colors are floating-point numbers, which VTK's PLY reader takes "
                                    "as 8-bit values (1.0 as 1 of 255): reflectance 0.8; write them as 8-bit "
                                    "colors (uchar red, green, blue) to use them"
                                  : "the PLY has no colors: reflectance 0.8");
  }
  raw.Materials.push_back(material);
  const int first = raw.NumberOfPolygons();
  if (AppendPolygons(data, nullptr, 0, -1, raw))
  {
    warnings.push_back("points and lines in the PLY are not surfaces; left out");
  }
  if (!colors.empty())
  {
    raw.Color.resize(first, { 1, 1, 1 });
    raw.Color.insert(raw.Color.end(), colors.begin(), colors.end());
    raw.Color.resize(raw.NumberOfPolygons(), { 1, 1, 1 }); // strips' triangles, if any
  }
  return std::string();
}

}
