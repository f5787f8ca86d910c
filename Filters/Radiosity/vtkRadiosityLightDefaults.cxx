#include "vtkRadiosityLightDefaults.h"

#include "Lights/LightColors.h"

#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkPolyData.h"
#include "vtkStringArray.h"

std::vector<radiosity::Vec3> vtkRadiosityLightDefaultColors(vtkPolyData* data, int lights)
{
  std::vector<double> given;
  vtkDataArray* defaults = data->GetFieldData()->GetArray("LightDefaultColors");
  for (vtkIdType i = 0; defaults && defaults->GetNumberOfComponents() == 3 && i < 3 * defaults->GetNumberOfTuples(); ++i)
  {
    given.push_back(defaults->GetComponent(i / 3, static_cast<int>(i % 3)));
  }
  std::vector<int> ids;
  std::vector<radiosity::Vec3> emission;
  vtkDataArray* lightId = data->GetCellData()->GetArray("LightId");
  vtkDataArray* emitted = data->GetCellData()->GetArray("Emission");
  const bool fromCells = given.size() != 3 * static_cast<size_t>(lights); // else the cells are not read
  for (vtkIdType c = 0; fromCells && lightId && emitted && emitted->GetNumberOfComponents() == 3 && c < data->GetNumberOfCells(); ++c)
  {
    ids.push_back(static_cast<int>(lightId->GetComponent(c, 0)));
    emission.push_back({ emitted->GetComponent(c, 0), emitted->GetComponent(c, 1), emitted->GetComponent(c, 2) });
  }
  return radiosity::LightDefaultColors(lights, given, ids, emission);
}

std::vector<double> vtkRadiosityFlatColors(const std::vector<radiosity::Vec3>& colors)
{
  std::vector<double> rgb;
  for (const radiosity::Vec3& c : colors)
  {
    rgb.insert(rgb.end(), { c.x, c.y, c.z });
  }
  return rgb;
}

std::vector<std::string> vtkRadiosityLightNames(vtkFieldData* fields)
{
  std::vector<std::string> names;
  auto* given = fields ? vtkStringArray::SafeDownCast(fields->GetAbstractArray("LightNames")) : nullptr;
  for (vtkIdType i = 0; given && i < given->GetNumberOfValues(); ++i)
  {
    names.push_back(given->GetValue(i));
  }
  return names;
}
