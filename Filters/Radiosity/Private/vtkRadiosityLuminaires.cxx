#include "vtkRadiosityLuminaires.h"
#include "vtkRadiosityAdapter.h"

#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkNew.h"
#include "vtkStringArray.h"

namespace vtkRadiosityLuminaires
{
namespace
{
const char* const kNames = "LuminaireNames";
const char* const kKinds = "LuminaireKinds";
const char* const kParameters = "LuminaireParameters";
const char* const kPlacement = "LuminairePlacement";

vtkStringArray* Strings(vtkFieldData* fields, const char* name)
{
  return vtkStringArray::SafeDownCast(fields->GetAbstractArray(name));
}

} // namespace

bool Read(vtkFieldData* fields, std::vector<radiosity::LuminaireRow>& rows, std::string& error)
{
  rows.clear();
  vtkStringArray* names = fields ? Strings(fields, kNames) : nullptr;
  if (!names)
  {
    return true;
  }
  vtkStringArray* kinds = Strings(fields, kKinds);
  vtkStringArray* parameters = Strings(fields, kParameters);
  vtkDataArray* placement = fields->GetArray(kPlacement);
  const vtkIdType n = names->GetNumberOfValues();
  if (!kinds || !parameters || !placement || kinds->GetNumberOfValues() != n || parameters->GetNumberOfValues() != n ||
    placement->GetNumberOfTuples() != n || placement->GetNumberOfComponents() != radiosity::kLuminairePlacementValues)
  {
    error = "the field arrays LuminaireNames, LuminaireKinds, LuminaireParameters (strings) and LuminairePlacement "
            "(10 numbers: position, aim, rotation, color) need one entry per luminaire";
    return false;
  }
  for (vtkIdType i = 0; i < n; ++i)
  {
    double v[radiosity::kLuminairePlacementValues];
    placement->GetTuple(i, v);
    radiosity::LuminaireRow row;
    row.Name = names->GetValue(i);
    row.Kind = kinds->GetValue(i);
    row.Parameters = parameters->GetValue(i);
    row.Position = { v[0], v[1], v[2] };
    row.Aim = { v[3], v[4], v[5] };
    row.Rotation = v[6];
    row.Color = { v[7], v[8], v[9] };
    rows.push_back(row);
  }
  return true;
}

void Write(vtkFieldData* fields, const std::vector<radiosity::LuminaireRow>& rows)
{
  for (const char* name : { kNames, kKinds, kParameters, kPlacement })
  {
    fields->RemoveArray(name);
  }
  if (rows.empty())
  {
    return;
  }
  std::vector<std::string> names, kinds, parameters;
  vtkNew<vtkDoubleArray> placement;
  placement->SetName(kPlacement);
  placement->SetNumberOfComponents(radiosity::kLuminairePlacementValues);
  for (const radiosity::LuminaireRow& row : rows)
  {
    names.push_back(row.Name);
    kinds.push_back(row.Kind);
    parameters.push_back(row.Parameters);
    const double v[radiosity::kLuminairePlacementValues] = { row.Position.x, row.Position.y, row.Position.z, row.Aim.x,
      row.Aim.y, row.Aim.z, row.Rotation, row.Color.x, row.Color.y, row.Color.z };
    placement->InsertNextTuple(v);
  }
  vtkRadiosityAdapter::AddStrings(fields, kNames, names);
  vtkRadiosityAdapter::AddStrings(fields, kKinds, kinds);
  vtkRadiosityAdapter::AddStrings(fields, kParameters, parameters);
  fields->AddArray(placement);
}
}
