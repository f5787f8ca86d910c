#include "vtkRadiosityMesher.h"
#include "vtkRadiosityAbort.h"
#include "vtkRadiosityAdapter.h"

#include "Mesher.h"

#include "vtkCellArray.h"
#include "vtkDoubleArray.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <map>
#include <tuple>

vtkStandardNewMacro(vtkRadiosityMesher);

struct vtkRadiosityMesher::Polygons
{
  radiosity::SceneMesh Mesh;
};

vtkRadiosityMesher::vtkRadiosityMesher()
  : SeenInput(new Polygons)
{
}

vtkRadiosityMesher::~vtkRadiosityMesher() = default;

double vtkRadiosityMesher::EstimateElements(double patchSize, double elementSize)
{
  const radiosity::SceneMesh& mesh = this->SeenInput->Mesh;
  return radiosity::CountElements(mesh.points, mesh.offsets, mesh.connectivity, patchSize, elementSize);
}

void vtkRadiosityMesher::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "PatchSize: " << this->PatchSize << "\n";
  os << indent << "ElementSize: " << this->ElementSize << "\n";
}

int vtkRadiosityMesher::RequestInformation(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector*)
{
  // The input has data here only if it executed before (a reader applied in ParaView).
  // Every property change runs this pass; the suggestion changes only with the input.
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  const vtkMTimeType inputTime = input ? input->GetMTime() : 0;
  if (inputTime == this->SuggestedForInput)
  {
    return 1;
  }
  this->SuggestedForInput = inputTime;
  radiosity::SceneMesh& mesh = this->SeenInput->Mesh;
  mesh = radiosity::SceneMesh();
  std::string error;
  radiosity::SuggestedSizes sizes;
  if (input && input->GetNumberOfCells() > 0 && vtkRadiosityAdapter::CopyPolygons(input, mesh, error))
  {
    sizes = radiosity::SuggestMeshSizes(mesh.points, mesh.offsets, mesh.connectivity);
  }
  else
  {
    mesh = radiosity::SceneMesh();
  }
  this->SuggestedPatchSize = sizes.PatchSize;
  this->SuggestedElementSize = sizes.ElementSize;
  this->InputArea = sizes.Area;
  this->SuggestedElements = sizes.Elements;
  return 1;
}

int vtkRadiosityMesher::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  return vtkRadiosityAdapter::Guarded(this, vtkPolyData::GetData(inputVector[0]), vtkPolyData::GetData(outputVector), [&]() -> int {
    vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
    vtkPolyData* output = vtkPolyData::GetData(outputVector);

    radiosity::SceneMesh mesh;
    std::vector<radiosity::Vec3> emission;
    std::string error;
    if (!vtkRadiosityAdapter::CopyPolygons(input, mesh, error) ||
      !vtkRadiosityAdapter::ReadSceneArrays(input, mesh, emission, error))
    {
      vtkErrorMacro(<< "Cannot mesh: " << error << ".");
      return 0;
    }

    // Cells share points only if reflectance, light and emission all agree.
    std::map<std::tuple<double, double, double, int, double, double, double>, int> materials;
    std::vector<int> surfaceKey(mesh.NumberOfPolygons());
    for (int i = 0; i < mesh.NumberOfPolygons(); ++i)
    {
      const radiosity::Vec3& r = mesh.reflectance[i];
      const radiosity::Vec3 e = emission.empty() ? radiosity::Vec3() : emission[i];
      const auto key = std::make_tuple(r.x, r.y, r.z, mesh.lightId[i], e.x, e.y, e.z);
      surfaceKey[i] = materials.emplace(key, static_cast<int>(materials.size())).first->second;
    }

    radiosity::MesherOptions options;
    options.PatchSize = this->PatchSize;
    options.ElementSize = this->ElementSize;
    options.ElementBudget = static_cast<double>(this->MaximumElements);
    vtkRadiosityAdapter::WarningList warnings;
    options.Warning = [this, &warnings](const std::string& message) { warnings.Add(this, message); };
    options.MergeTriangles = this->MergeTriangles;
    options.SharePatches = this->SharePatches;
    const vtkRadiosityAbortWatch abort(this);
    options.Progress = [this, abort](double f) {
      this->UpdateProgress(f);
      return !abort.Stop();
    };
    radiosity::MeshedPolygons meshed;
    error = radiosity::MeshPolygons(mesh.points, mesh.offsets, mesh.connectivity, surfaceKey, options, meshed);
    if (!error.empty())
    {
      vtkErrorMacro(<< "Cannot mesh: " << error << ".");
      return 0;
    }

    vtkNew<vtkPoints> points;
    points->SetDataTypeToDouble();
    points->SetNumberOfPoints(static_cast<vtkIdType>(meshed.points.size()));
    for (size_t p = 0; p < meshed.points.size(); ++p)
    {
      const radiosity::Vec3& x = meshed.points[p];
      points->SetPoint(static_cast<vtkIdType>(p), x.x, x.y, x.z);
    }
    vtkNew<vtkCellArray> polys;
    const vtkIdType elements = static_cast<vtkIdType>(meshed.sourcePolygon.size());
    polys->AllocateExact(elements, static_cast<vtkIdType>(meshed.connectivity.size()));
    for (vtkIdType e = 0; e < elements; ++e)
    {
      polys->InsertNextCell(meshed.offsets[e + 1] - meshed.offsets[e]);
      for (int k = meshed.offsets[e]; k < meshed.offsets[e + 1]; ++k)
      {
        polys->InsertCellPoint(meshed.connectivity[k]);
      }
    }
    output->SetPoints(points);
    output->SetPolys(polys);

    vtkCellData* inCD = input->GetCellData();
    vtkCellData* outCD = output->GetCellData();
    outCD->CopyAllocate(inCD, elements);
    for (vtkIdType e = 0; e < elements; ++e)
    {
      outCD->CopyData(inCD, meshed.sourcePolygon[e], e);
    }
    vtkNew<vtkIntArray> patchId;
    patchId->SetName("PatchId");
    patchId->SetNumberOfValues(elements);
    for (vtkIdType e = 0; e < elements; ++e)
    {
      patchId->SetValue(e, meshed.patchId[e]);
    }
    outCD->AddArray(patchId);
    output->GetFieldData()->ShallowCopy(input->GetFieldData());
    vtkNew<vtkIntArray> merged;
    merged->SetName("MergedTrianglePairs");
    merged->InsertNextValue(meshed.mergedTrianglePairs);
    output->GetFieldData()->AddArray(merged);
    vtkNew<vtkDoubleArray> used;
    used->SetName("MesherElementSize");
    used->InsertNextValue(meshed.elementSize);
    output->GetFieldData()->AddArray(used);
    warnings.AddTo(output->GetFieldData());
    return 1;
  });
}
