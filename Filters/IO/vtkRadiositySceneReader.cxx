#include "vtkRadiositySceneReader.h"
#include "vtkRadiosityAdapter.h"

#include "SceneFiles.h"
#include "Import/SceneImport.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkLogger.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkStringArray.h"

#include <vtksys/SystemTools.hxx>

#include <algorithm>

vtkStandardNewMacro(vtkRadiositySceneReader);

namespace
{

vtkSmartPointer<vtkDoubleArray> Colors(const char* name, const std::vector<radiosity::Vec3>& values)
{
  auto array = vtkSmartPointer<vtkDoubleArray>::New();
  array->SetName(name);
  array->SetNumberOfComponents(3);
  array->SetNumberOfTuples(static_cast<vtkIdType>(values.size()));
  for (size_t i = 0; i < values.size(); ++i)
  {
    array->SetTuple3(static_cast<vtkIdType>(i), values[i].x, values[i].y, values[i].z);
  }
  return array;
}

vtkSmartPointer<vtkIntArray> Ints(const char* name, const std::vector<int>& values)
{
  auto array = vtkSmartPointer<vtkIntArray>::New();
  array->SetName(name);
  array->SetNumberOfValues(static_cast<vtkIdType>(values.size()));
  std::copy(values.begin(), values.end(), array->GetPointer(0));
  return array;
}

vtkSmartPointer<vtkStringArray> Strings(const char* name, const std::vector<std::string>& values)
{
  auto array = vtkSmartPointer<vtkStringArray>::New();
  array->SetName(name);
  for (const std::string& value : values)
  {
    array->InsertNextValue(value);
  }
  return array;
}

/// The scene as polydata with the input contract's arrays.
void Fill(const radiosity::ImportedScene& scene, vtkPolyData* output)
{
  const radiosity::SceneMesh& mesh = scene.Mesh;
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(static_cast<vtkIdType>(mesh.Points.size()));
  for (size_t p = 0; p < mesh.Points.size(); ++p)
  {
    points->SetPoint(static_cast<vtkIdType>(p), mesh.Points[p].x, mesh.Points[p].y, mesh.Points[p].z);
  }
  vtkNew<vtkCellArray> polys;
  polys->AllocateExact(mesh.NumberOfPolygons(), static_cast<vtkIdType>(mesh.Connectivity.size()));
  for (int i = 0; i < mesh.NumberOfPolygons(); ++i)
  {
    polys->InsertNextCell(mesh.PolygonSize(i));
    for (int k = 0; k < mesh.PolygonSize(i); ++k)
    {
      polys->InsertCellPoint(mesh.Polygon(i)[k]);
    }
  }
  output->SetPoints(points);
  output->SetPolys(polys);
  output->GetCellData()->AddArray(Colors("Reflectance", mesh.Reflectance));
  output->GetCellData()->AddArray(Ints("LightId", mesh.LightId));
  output->GetCellData()->AddArray(Colors("Emission", scene.Emission));
  output->GetCellData()->AddArray(Ints("MaterialIds", scene.Material));
  output->GetFieldData()->AddArray(Strings("LightNames", scene.LightNames));
  output->GetFieldData()->AddArray(Strings("MaterialNames", scene.MaterialNames));
  if (mesh.PointQuantum > 0) // the file's coordinates were float, though the output's are double
  {
    vtkNew<vtkDoubleArray> quantum;
    quantum->SetName(vtkRadiosityAdapter::PointQuantumName);
    quantum->InsertNextValue(mesh.PointQuantum);
    output->GetFieldData()->AddArray(quantum);
  }
}

} // namespace

vtkRadiositySceneReader::vtkRadiositySceneReader()
{
  this->SetNumberOfInputPorts(0);
}

vtkRadiositySceneReader::~vtkRadiositySceneReader()
{
  this->SetFileName(nullptr);
}

bool vtkRadiositySceneReader::CanReadFile(const char* fileName)
{
  const SceneFiles::Format* format = fileName ? SceneFiles::FormatOf(fileName) : nullptr;
  return format && (!format->NeedsAssimp || !vtksys::SystemTools::FindProgram("assimp").empty());
}

std::string vtkRadiositySceneReader::GetFileExtensions()
{
  return SceneFiles::AllExtensions();
}

int vtkRadiositySceneReader::RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  const int read = vtkRadiosityAdapter::Guarded(this, nullptr, output, [&]() -> int {
    if (!this->FileName || !*this->FileName)
    {
      vtkErrorMacro(<< "Cannot import: no FileName set.");
      return 0;
    }
    radiosity::RawScene raw;
    std::vector<std::string> notes;
    std::string error = SceneFiles::Read(this->FileName, raw, notes);
    radiosity::ImportOptions options;
    options.UnitScale = this->UnitScale;
    options.LightsPerObject = this->LightsPerObject;
    radiosity::ImportedScene scene;
    if (error.empty() && !(error = radiosity::BuildImportedScene(raw, options, scene)).empty())
    {
      error = "'" + std::string(this->FileName) + "': " + error;
    }
    if (!error.empty())
    {
      vtkErrorMacro(<< "Cannot import: " << error << ".");
      return 0;
    }
    Fill(scene, output);
    vtkRadiosityAdapter::WarningList warnings;
    notes.insert(notes.end(), scene.Warnings.begin(), scene.Warnings.end());
    for (const std::string& note : notes)
    {
      warnings.Add(this, vtksys::SystemTools::GetFilenameName(this->FileName) + ": " + note + ".");
    }
    warnings.AddTo(output->GetFieldData());
    const std::string summary = vtksys::SystemTools::GetFilenameName(this->FileName) + ": " + scene.Summary;
    output->GetFieldData()->AddArray(Strings("ImportSummary", { summary }));
    vtkLogF(INFO, "Imported %s", summary.c_str());
    return 1;
  });
  // On ParaView's MPI server only rank 0 reads (a file is not split into pieces), while the
  // filters below run on every rank and meet in collectives: a failed read passes its
  // empty, marked output on, so that they fail on all ranks together instead of rank 0
  // stopping alone and leaving the others waiting.
  vtkInformation* info = outputVector->GetInformationObject(0);
  const bool pieces = info->Has(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES()) &&
    info->Get(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES()) > 1;
  return read || pieces ? 1 : 0;
}

void vtkRadiositySceneReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
  os << indent << "UnitScale: " << this->UnitScale << "\n";
  os << indent << "LightsPerObject: " << this->LightsPerObject << "\n";
}
