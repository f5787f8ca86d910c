#include "vtkRadiosityMesher.h"
#include "vtkRadiosityLuminaires.h"
#include "vtkRadiosityAbort.h"
#include "vtkRadiosityAdapter.h"
#include "vtkRadiosityMeshPieces.h"
#include "vtkRadiosityPieces.h"

#include "Base/AccuracyLevels.h"
#include "Mesh/Mesher.h"

#include "vtkAbstractArray.h"
#include "vtkCellArray.h"
#include "vtkGeometryFilter.h"
#include "vtkDoubleArray.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkFieldData.h"
#include "vtkMultiProcessController.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <algorithm>
#include <cmath>
#include <memory>

vtkStandardNewMacro(vtkRadiosityMesher);

namespace
{

/// The input as polygons: a vtkPolyData as it is; another data set (ParaView's
/// RedistributeDataSet gives an unstructured grid) through VTK's geometry filter, with its
/// cell, point and field data.
vtkSmartPointer<vtkPolyData> AsPolyData(vtkDataSet* input)
{
  if (!input || vtkPolyData::SafeDownCast(input))
  {
    return vtkPolyData::SafeDownCast(input);
  }
  vtkNew<vtkGeometryFilter> surface;
  surface->SetInputData(input);
  surface->MergingOff();
  surface->Update();
  vtkSmartPointer<vtkPolyData> polygons = surface->GetOutput();
  polygons->GetFieldData()->PassData(input->GetFieldData());
  return polygons;
}

/// The scene's luminaires (its field arrays Luminaire*) as lamps for the grading: each at its
/// position, lighting the side its aim points to where it sends nothing behind (a
/// downlight), else every side. A luminaire that cannot be made is left to the solver to name.
std::vector<radiosity::LampSpot> PointLampsOf(vtkDataObject* input)
{
  std::vector<radiosity::LuminaireRow> rows;
  std::string error;
  std::vector<radiosity::LampSpot> spots;
  if (!input || !vtkRadiosityLuminaires::Read(input->GetFieldData(), rows, error))
  {
    return spots;
  }
  for (const radiosity::LuminaireRow& row : rows)
  {
    radiosity::PointLight light;
    if (!radiosity::MakePointLight(row, light).empty())
    {
      continue;
    }
    radiosity::Vec3 x, y, z;
    light.Frame(x, y, z);
    bool dark = true; // behind the aim: 8 rings of 16 directions
    for (int i = 1; i <= 8 && dark; ++i)
    {
      for (int j = 0; j < 16 && dark; ++j)
      {
        const double polar = radiosity::Pi / 2 + i * radiosity::Pi / 16, turn = j * radiosity::Pi / 8;
        const radiosity::Vec3 d = x * (std::sin(polar) * std::cos(turn)) + y * (std::sin(polar) * std::sin(turn)) +
          z * std::cos(polar);
        dark = !(light.Toward(d) > 0);
      }
    }
    radiosity::LampSpot spot;
    spot.Centre = light.Position;
    spot.Normal = dark ? z : radiosity::Vec3();
    spots.push_back(spot);
  }
  return spots;
}

/// The mesher's options as this filter's properties set them, for `mesh` (its lamps, and
/// on MPI `whole`, the whole scene's polygons, with the float noise of the whole): the one
/// place they are made, so the panel's estimate, the element budget and the mesh agree.
radiosity::MesherOptions OptionsFor(vtkRadiosityMesher* self, const radiosity::SceneMesh& mesh,
  std::vector<char> lamps, const radiosity::PolygonArrays* whole = nullptr, double wholeQuantum = 0,
  const radiosity::WholeSceneSurfaces* surfaces = nullptr)
{
  radiosity::MesherOptions options;
  options.MergeTriangles = self->GetMergeTriangles();
  options.SharePatches = self->GetSharePatches();
  options.ClusterAngle = self->GetClusterAngle();
  options.LampGrading = self->GetLampGradingInUse();
  options.ShadowGrading = self->GetShadowGradingInUse();
  // The lamps' bins are sized by the grading's reach (whatever the scene's unit).
  options.ElementSize = self->GetElementSizeInUse() > 0 ? self->GetElementSizeInUse() : options.ElementSize;
  options.WholeScene = whole;
  options.WholeSurfaces = surfaces;
  options.PointQuantum = std::max(mesh.PointQuantum, wholeQuantum);
  options.Lamps = std::move(lamps);
  return options;
}

} // namespace

struct vtkRadiosityMesher::Polygons
{
  radiosity::SceneMesh Mesh;
  std::vector<int> SurfaceKey; ///< as meshing keys them (triangle pairs join within one)
  std::vector<char> Lamps;
  std::vector<radiosity::LampSpot> PointLamps; ///< the luminaires
};

vtkRadiosityMesher::vtkRadiosityMesher()
  : SeenInput(new Polygons)
{
}

vtkRadiosityMesher::~vtkRadiosityMesher() = default;

namespace
{
/// The sizes to mesh at, an Accuracy level's scale applied to the element (at most the patch).
std::pair<double, double> SizesAtAccuracy(double patch, double element, double suggestedPatch, int accuracy)
{
  auto sizes = radiosity::SizesInUse(patch, element, suggestedPatch);
  if (accuracy >= 0)
  {
    sizes.second = std::min(sizes.second * radiosity::AccuracyLevelOf(accuracy).ElementScale, sizes.first);
  }
  return sizes;
}
} // namespace

void vtkRadiosityMesher::ResolveSizes(double suggestedPatch)
{
  const auto sizes = SizesAtAccuracy(this->PatchSize, this->ElementSize, suggestedPatch, this->Accuracy);
  this->PatchSizeInUse = sizes.first;
  this->ElementSizeInUse = sizes.second;
}

double vtkRadiosityMesher::GetLampGradingInUse() const
{
  return this->Accuracy >= 0 ? radiosity::AccuracyLevelOf(this->Accuracy).LampGrading : this->LampGrading;
}

double vtkRadiosityMesher::GetShadowGradingInUse() const
{
  return this->Accuracy >= 0 ? radiosity::AccuracyLevelOf(this->Accuracy).ShadowGrading : this->ShadowGrading;
}

double vtkRadiosityMesher::GetAccuracyShadowGrading(int level)
{
  return radiosity::AccuracyLevelOf(level).ShadowGrading;
}

double vtkRadiosityMesher::GetAccuracyElementScale(int level)
{
  return radiosity::AccuracyLevelOf(level).ElementScale;
}

double vtkRadiosityMesher::GetAccuracyLampGrading(int level)
{
  return radiosity::AccuracyLevelOf(level).LampGrading;
}

int vtkRadiosityMesher::GetAccuracyGatherRays(int level)
{
  return radiosity::AccuracyLevelOf(level).GatherRays;
}

double vtkRadiosityMesher::GetAccuracyClusterSeparation(int level)
{
  return radiosity::AccuracyLevelOf(level).ClusterSeparation;
}

int vtkRadiosityMesher::GetAccuracyGatherSweeps(int level)
{
  return radiosity::AccuracyLevelOf(level).GatherSweeps;
}

const char* vtkRadiosityMesher::GetAccuracyName(int level)
{
  return radiosity::AccuracyLevelOf(level).Name;
}

int vtkRadiosityMesher::GetNumberOfAccuracyLevels()
{
  return radiosity::kAccuracyLevels;
}

double vtkRadiosityMesher::EstimateElements(double patchSize, double elementSize)
{
  if (this->GetNumberOfInputConnections(0) > 0)
  {
    // Without it a script got 0 until it called UpdateInformation itself; the pass does
    // nothing when the input has not changed since the last one.
    this->UpdateInformation();
  }
  const radiosity::SceneMesh& mesh = this->SeenInput->Mesh;
  const auto sizes = SizesAtAccuracy(patchSize, elementSize, this->SuggestedPatchSize, this->Accuracy);
  radiosity::MesherOptions options = OptionsFor(this, mesh, this->SeenInput->Lamps);
  options.PointLamps = this->SeenInput->PointLamps;
  options.ElementSize = sizes.second;
  const radiosity::ElementCounter count(mesh.Points, mesh.Offsets, mesh.Connectivity, this->SeenInput->SurfaceKey, options);
  return count(sizes.first, sizes.second);
}

void vtkRadiosityMesher::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "PatchSize: " << this->PatchSize << (this->PatchSize > 0 ? "" : " (from the scene)") << "\n";
  os << indent << "ElementSize: " << this->ElementSize << (this->ElementSize > 0 ? "" : " (a quarter of the patch)") << "\n";
  os << indent << "MaximumElements: " << this->MaximumElements << (this->MaximumElements > 0 ? "" : " (none)") << "\n";
  os << indent << "MergeTriangles: " << this->MergeTriangles << "\n";
  os << indent << "SharePatches: " << this->SharePatches << "\n";
  os << indent << "ClusterAngle: " << this->ClusterAngle << "\n";
  os << indent << "LampGrading: " << this->LampGrading << "\n";
  os << indent << "ShadowGrading: " << this->ShadowGrading << "\n";
  os << indent << "Accuracy: " << this->Accuracy << (this->Accuracy < 0 ? " (custom)" : "") << "\n";
}

int vtkRadiosityMesher::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkDataSet");
  return 1;
}

int vtkRadiosityMesher::RequestInformation(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector*)
{
  // The input has data here only if it executed before (a reader applied in ParaView);
  // otherwise RequestData suggests, so that a script reads the suggestion after an update.
  this->SuggestFor(vtkDataSet::GetData(inputVector[0]));
  return 1;
}

void vtkRadiosityMesher::SuggestFor(vtkDataSet* given)
{
  // Every property change runs the information pass; the suggestion changes only with the input.
  vtkSmartPointer<vtkPolyData> surface = given && given->GetMTime() != this->SuggestedForInput ? AsPolyData(given) : nullptr;
  vtkPolyData* input = surface ? surface.Get() : vtkPolyData::SafeDownCast(given);
  const vtkMTimeType inputTime = given ? given->GetMTime() : 0;
  if (inputTime == this->SuggestedForInput)
  {
    return;
  }
  this->SuggestedForInput = inputTime;
  radiosity::SceneMesh& mesh = this->SeenInput->Mesh;
  mesh = radiosity::SceneMesh();
  std::string error;
  // Before the input has run there is nothing to suggest from: 0, so a proxy made then
  // (pvbatch) keeps the automatic sizes.
  radiosity::SuggestedSizes sizes{ 0.0, 0.0, 0.0, 0.0 };
  if (input && input->GetNumberOfCells() > 0 && vtkRadiosityAdapter::CopyPolygons(input, mesh, error))
  {
    sizes = radiosity::SuggestMeshSizes(mesh.Points, mesh.Offsets, mesh.Connectivity, vtkRadiosityAdapter::SizingSpan(input));
    std::vector<radiosity::Vec3> emission;
    // Without valid arrays the mesher will refuse the input; the estimate then pairs all.
    vtkRadiosityAdapter::ReadSceneArrays(input, mesh, emission, error);
    this->SeenInput->SurfaceKey = vtkRadiosityMeshPieces::SurfaceKeys(mesh, emission);
    this->SeenInput->Lamps = vtkRadiosityMeshPieces::Lamps(mesh, emission);
    this->SeenInput->PointLamps = PointLampsOf(input);
  }
  else
  {
    mesh = radiosity::SceneMesh();
    this->SeenInput->SurfaceKey.clear();
    this->SeenInput->Lamps.clear();
    this->SeenInput->PointLamps.clear();
  }
  this->SuggestedPatchSize = sizes.PatchSize;
  this->SuggestedElementSize = sizes.ElementSize;
  this->InputArea = sizes.Area;
  this->SuggestedElements = sizes.Elements;
}

namespace
{

/// Meshes the polygons of `input` with `self`'s settings into `meshed`; an empty string
/// or what is wrong.
/// On MPI, what every rank needs of the whole scene: its polygons (surfaces of other pieces
/// standing on this one cut it) and how far float input can be off (the largest of the
/// ranks': a piece near the origin would take its float noise for finer than the scene's).
struct WholeScene
{
  const radiosity::PolygonArrays* Polygons = nullptr;
  double PointQuantum = 0;
  /// Its surfaces and where this piece begins in it: copies and overlaps across ranks.
  const radiosity::WholeSceneSurfaces* Surfaces = nullptr;
};

/// The element size and whether the lamps grade it (MaximumElements on MPI may say not).
struct ElementSizing
{
  double Size = 0;
  bool Graded = true;
};

std::string MeshPiece(vtkRadiosityMesher* self, vtkPolyData* input, ElementSizing sizing, double budget,
  const WholeScene& whole, radiosity::MeshedPolygons& meshed, vtkRadiosityAdapter::WarningList& warnings)
{
  radiosity::SceneMesh mesh;
  std::vector<radiosity::Vec3> emission;
  std::string error;
  if (!vtkRadiosityAdapter::CopyPolygons(input, mesh, error) ||
    !vtkRadiosityAdapter::ReadSceneArrays(input, mesh, emission, error))
  {
    return error;
  }

  const std::vector<int> surfaceKey = vtkRadiosityMeshPieces::SurfaceKeys(mesh, emission);

  radiosity::MesherOptions options =
    OptionsFor(self, mesh, vtkRadiosityMeshPieces::Lamps(mesh, emission), whole.Polygons, whole.PointQuantum,
      whole.Surfaces);
  options.PointLamps = PointLampsOf(input);
  options.PatchSize = self->GetPatchSizeInUse();
  options.ElementSize = sizing.Size;
  options.LampGrading = sizing.Graded ? options.LampGrading : 0.0;
  options.ElementBudget = budget;
  options.Warning = [self, &warnings](const std::string& message) { warnings.Add(self, message); };
  const vtkRadiosityAbortWatch abort(self);
  options.Progress = [self, abort](double f) {
    self->UpdateProgress(f);
    return !abort.Stop();
  };
  return radiosity::MeshPolygons(mesh.Points, mesh.Offsets, mesh.Connectivity, surfaceKey, options, meshed);
}

/// On MPI, MaximumElements bounds the whole scene: every rank searches the same element
/// size over the sum of the ranks' counts (a rank without usable polygons counts none),
/// leaving the lamps' grading out first, as MeshPolygons does.
ElementSizing ElementSizeEverywhere(vtkRadiosityMesher* self, vtkMultiProcessController* parallel, vtkPolyData* input,
  const WholeScene& whole, vtkRadiosityAdapter::WarningList& warnings)
{
  radiosity::SceneMesh mesh;
  std::string error;
  std::vector<radiosity::Vec3> emission;
  const bool usable = input && input->GetNumberOfCells() > 0 && !vtkRadiosityAdapter::FailedUpstream(input) &&
    vtkRadiosityAdapter::CopyPolygons(input, mesh, error) &&
    vtkRadiosityAdapter::ReadSceneArrays(input, mesh, emission, error);
  // Counted as the rank will mesh its piece: triangle pairs merged, contacts cut.
  radiosity::MesherOptions options =
    OptionsFor(self, mesh, usable ? vtkRadiosityMeshPieces::Lamps(mesh, emission) : std::vector<char>(),
      whole.Polygons, whole.PointQuantum, whole.Surfaces);
  options.PointLamps = usable ? PointLampsOf(input) : std::vector<radiosity::LampSpot>();
  const std::vector<int> keys = usable ? vtkRadiosityMeshPieces::SurfaceKeys(mesh, emission) : std::vector<int>();
  auto counter = std::make_unique<radiosity::ElementCounter>(mesh.Points, mesh.Offsets, mesh.Connectivity, keys, options);
  auto count = [&](double size) {
    const double here = usable ? (*counter)(self->GetPatchSizeInUse(), size) : 0;
    return static_cast<double>(vtkRadiosityPieces::SumOverRanks(parallel, static_cast<long long>(here)));
  };
  const double budget = static_cast<double>(self->GetMaximumElements());
  ElementSizing sizing{ self->GetElementSizeInUse(), options.LampGrading > 0 };
  if (sizing.Graded && count(std::min(sizing.Size, self->GetPatchSizeInUse())) > budget)
  {
    options.LampGrading = 0;
    counter = std::make_unique<radiosity::ElementCounter>(mesh.Points, mesh.Offsets, mesh.Connectivity, keys, options);
    sizing.Graded = false;
    if (parallel->GetLocalProcessId() == 0)
    {
      warnings.Add(self, "LampGrading left out: the finer elements by the lamps would exceed MaximumElements (" +
          std::to_string(static_cast<long long>(budget)) + ").");
    }
  }
  const double wanted = count(sizing.Size);
  if (wanted <= budget)
  {
    return sizing;
  }
  sizing.Size = radiosity::ElementSizeForBudget(count, self->GetPatchSizeInUse(), self->GetElementSizeInUse(), budget);
  if (parallel->GetLocalProcessId() == 0)
  {
    warnings.Add(self, "ElementSize " + std::to_string(self->GetElementSizeInUse()) + " would make " +
        std::to_string(static_cast<long long>(wanted)) + " elements over all ranks, more than MaximumElements (" +
        std::to_string(static_cast<long long>(budget)) + "); using " + std::to_string(sizing.Size) + ".");
  }
  return sizing;
}

void AddFieldInt(vtkFieldData* fields, const char* name, int value)
{
  vtkNew<vtkIntArray> array;
  array->SetName(name);
  array->InsertNextValue(value);
  fields->AddArray(array);
}

/// The patch size suggested for the whole scene (`whole` where given, else `input`); 0
/// where it has no usable polygons.
double SuggestedPatch(const radiosity::SceneMesh* whole, vtkPolyData* input)
{
  if (vtkRadiosityAdapter::SizingSpan(input) > 0) // every piece carries the model's span
  {
    return radiosity::PatchSizeForSpan(vtkRadiosityAdapter::SizingSpan(input));
  }
  if (whole)
  {
    return radiosity::SuggestPatchSize(whole->Points, whole->Connectivity);
  }
  radiosity::SceneMesh mesh;
  std::string error;
  const bool usable = input && input->GetNumberOfCells() > 0 && !vtkRadiosityAdapter::FailedUpstream(input) &&
    vtkRadiosityAdapter::CopyPolygons(input, mesh, error);
  return usable ? radiosity::SuggestPatchSize(mesh.Points, mesh.Connectivity) : 0.0;
}

/// The elements as the output's points and polygons, each with its source polygon's cell
/// data and PatchId (offset by `firstPatch`), and the mesher's field arrays.
void WriteMeshed(vtkPolyData* output, vtkPolyData* input, const radiosity::MeshedPolygons& meshed,
  long long firstPatch, double patchSize, double wholeQuantum, const vtkRadiosityAdapter::WarningList& warnings)
{
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(static_cast<vtkIdType>(meshed.Points.size()));
  for (size_t p = 0; p < meshed.Points.size(); ++p)
  {
    const radiosity::Vec3& x = meshed.Points[p];
    points->SetPoint(static_cast<vtkIdType>(p), x.x, x.y, x.z);
  }
  vtkNew<vtkCellArray> polys;
  const vtkIdType elements = static_cast<vtkIdType>(meshed.SourcePolygon.size());
  polys->AllocateExact(elements, static_cast<vtkIdType>(meshed.Connectivity.size()));
  for (vtkIdType e = 0; e < elements; ++e)
  {
    polys->InsertNextCell(meshed.Offsets[e + 1] - meshed.Offsets[e]);
    for (int k = meshed.Offsets[e]; k < meshed.Offsets[e + 1]; ++k)
    {
      polys->InsertCellPoint(meshed.Connectivity[k]);
    }
  }
  output->SetPoints(points);
  output->SetPolys(polys);
  vtkCellData* outCD = output->GetCellData();
  outCD->CopyAllocate(input->GetCellData(), elements);
  vtkNew<vtkIntArray> patchId;
  patchId->SetName("PatchId");
  patchId->SetNumberOfValues(elements);
  for (vtkIdType e = 0; e < elements; ++e)
  {
    outCD->CopyData(input->GetCellData(), meshed.SourcePolygon[e], e);
    patchId->SetValue(e, static_cast<int>(firstPatch + meshed.PatchId[e]));
  }
  outCD->AddArray(patchId);
  vtkFieldData* fields = output->GetFieldData();
  fields->ShallowCopy(input->GetFieldData());
  AddFieldInt(fields, "MergedTrianglePairs", meshed.MergedTrianglePairs);
  AddFieldInt(fields, "ClusteredPatches", meshed.ClusteredPatches);
  vtkNew<vtkDoubleArray> used;
  used->SetName("MesherElementSize");
  used->InsertNextValue(meshed.ElementSize);
  fields->AddArray(used);
  vtkNew<vtkDoubleArray> patch;
  patch->SetName("MesherPatchSize");
  patch->InsertNextValue(patchSize);
  fields->AddArray(patch);
  vtkNew<vtkDoubleArray> quantum;
  quantum->SetName(vtkRadiosityAdapter::PointQuantumName);
  quantum->InsertNextValue(std::max(vtkRadiosityMeshPieces::OwnQuantum(input, false), wholeQuantum));
  fields->AddArray(quantum);
  warnings.AddTo(fields);
}
}

void vtkRadiosityMesher::ChooseSizes(vtkDataSet* given, bool parallel, const std::function<double()>& scenePatch)
{
  if (!parallel)
  {
    this->SuggestFor(given); // done already by the information pass for this input (the usual case)
  }
  const bool suggested = !parallel && given && given->GetMTime() == this->SuggestedForInput && this->SuggestedPatchSize > 0;
  this->ResolveSizes(this->PatchSize > 0 ? 0.0 : suggested ? this->SuggestedPatchSize : scenePatch());
  this->MesherPatchSize = this->MesherElementSize = 0.0; // until this run has meshed
}

vtkSmartPointer<vtkPolyData> vtkRadiosityMesher::InputOf(vtkInformationVector** inputs)
{
  return AsPolyData(vtkDataSet::GetData(inputs[0]));
}

bool vtkRadiosityMesher::GuardsInput(const Run& run)
{
  // On ParaView's MPI server each rank meshes its piece, and a rank may hold none. Every
  // rank joins the same collectives, whatever happened to it (an upstream failure, an
  // exception), so one that fails never leaves the others waiting; patch ids then follow
  // those of the ranks before.
  return !run.Parallel;
}

int vtkRadiosityMesher::Execute(const Run& run)
{
  vtkPolyData* input = run.Input;
  vtkMultiProcessController* parallel = run.Parallel;
  vtkPolyData* output = run.Output;
  const bool upstream = vtkRadiosityAdapter::FailedUpstream(input);
  const bool empty = !input || input->GetNumberOfCells() == 0;
  vtkRadiosityAdapter::WarningList warnings;
  using vtkRadiosityMeshPieces::GatheredScene;
  const GatheredScene gathered =
    parallel ? vtkRadiosityMeshPieces::GatherWholeScene(this, parallel, input, upstream, warnings) : GatheredScene();
  const radiosity::SceneMesh& whole = gathered.Mesh;
  const radiosity::PolygonArrays wholeArrays{ whole.Points, whole.Offsets, whole.Connectivity };
  const WholeScene wholeScene{ parallel ? &wholeArrays : nullptr,
    parallel ? vtkRadiosityPieces::MaxOverRanks(parallel, vtkRadiosityMeshPieces::OwnQuantum(input, upstream)) : 0.0,
    parallel && gathered.HasSurfaces ? &gathered.Surfaces : nullptr };
  // Sizes from the scene are taken from all of it, so every rank meshes alike.
  this->ChooseSizes(vtkDataSet::GetData(run.Inputs[0]), parallel != nullptr,
    [&]() { return SuggestedPatch(parallel ? &whole : nullptr, input); });
  const ElementSizing sizing = parallel && this->MaximumElements > 0
    ? ElementSizeEverywhere(this, parallel, input, wholeScene, warnings)
    : ElementSizing{ this->ElementSizeInUse, true };
  const double localBudget = parallel ? 0.0 : static_cast<double>(this->MaximumElements);
  radiosity::MeshedPolygons meshed;
  std::string error = upstream ? "a filter upstream failed"
    : parallel && empty        ? std::string()
                               : vtkRadiosityAdapter::Caught([&]() {
                                   return MeshPiece(this, input, sizing, localBudget, wholeScene, meshed, warnings);
                                 });
  long long firstPatch = 0;
  if (parallel)
  {
    error = vtkRadiosityMeshPieces::AgreeOnPieces(parallel, error, empty, input, meshed, firstPatch);
    warnings = vtkRadiosityMeshPieces::EveryRanksWarnings(parallel, warnings);
  }
  if (!error.empty())
  {
    if (!upstream) // that filter has said why
    {
      vtkErrorMacro(<< "Cannot mesh: " << error << ".");
    }
    return 0;
  }
  if (empty)
  {
    output->GetFieldData()->ShallowCopy(input->GetFieldData());
    return 1;
  }
  WriteMeshed(output, input, meshed, firstPatch, this->PatchSizeInUse, wholeScene.PointQuantum, warnings);
  // The level for the solver (which takes its gather rays and separation from it).
  output->GetFieldData()->RemoveArray("Accuracy");
  if (this->Accuracy >= 0)
  {
    AddFieldInt(output->GetFieldData(), "Accuracy", this->Accuracy);
  }
  this->MesherPatchSize = this->PatchSizeInUse;
  this->MesherElementSize = meshed.ElementSize;
  return 1;
}
