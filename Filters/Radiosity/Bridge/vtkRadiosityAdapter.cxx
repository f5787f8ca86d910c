#include "vtkRadiosityAdapter.h"

#include "Base/WorkerPool.h"
#include "vtkRadiosityLightDefaults.h"

#include "vtkAlgorithm.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCommunicator.h"
#include "vtkDataArray.h"
#include "vtkExecutive.h"
#include "vtkFieldData.h"
#include "vtkIntArray.h"
#include "vtkMultiProcessController.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkStringArray.h"

#include <algorithm>
#include <cmath>
#include <exception>
#include <new>
#include <set>

namespace vtkRadiosityAdapter
{

double PointQuantum(vtkPolyData* input, double farthest)
{
  // The scene reader and the mesher write what their input had (their own points are
  // double, whatever they were given); float points of this input's own count too.
  const bool single = input->GetPoints() && input->GetPoints()->GetDataType() == VTK_FLOAT;
  double quantum = single ? farthest * std::ldexp(1.0, -23) : 0.0;
  vtkDataArray* given = input->GetFieldData()->GetArray(PointQuantumName);
  const double written = given && given->GetNumberOfTuples() > 0 ? given->GetTuple1(0) : 0.0;
  return written >= 0 && written <= VTK_DOUBLE_MAX ? std::max(quantum, written) : quantum;
}

double SizingSpan(vtkDataObject* input)
{
  vtkDataArray* given = input ? input->GetFieldData()->GetArray(SizingSpanName) : nullptr;
  const double span = given && given->GetNumberOfTuples() > 0 ? given->GetTuple1(0) : 0.0;
  return span > 0 && span <= VTK_DOUBLE_MAX ? span : 0.0;
}

bool CopyPolygons(vtkPolyData* input, radiosity::SceneMesh& mesh, std::string& error)
{
  if (!input || input->GetNumberOfPolys() == 0)
  {
    error = input && input->GetNumberOfStrips() > 0
      ? "the input has triangle strips and no polygons; only polygons are read (apply vtkTriangleFilter, "
        "ParaView's Triangulate, first)"
      : "the input has no polygons";
    return false;
  }
  if (input->GetNumberOfVerts() + input->GetNumberOfLines() + input->GetNumberOfStrips() > 0)
  {
    error = "the input has vertices, lines or triangle strips; only polygons are supported "
            "(apply vtkTriangleFilter or extract the surface polygons first)";
    return false;
  }
  const vtkIdType nPoints = input->GetNumberOfPoints();
  mesh.Points.resize(nPoints);
  double farthest = 0;
  for (vtkIdType p = 0; p < nPoints; ++p)
  {
    double x[3];
    input->GetPoint(p, x);
    mesh.Points[p] = { x[0], x[1], x[2] };
    farthest = std::max({ farthest, std::fabs(x[0]), std::fabs(x[1]), std::fabs(x[2]) });
  }
  mesh.PointQuantum = PointQuantum(input, farthest);
  mesh.Offsets.assign(1, 0);
  mesh.Connectivity.clear();
  vtkCellArray* polys = input->GetPolys();
  vtkIdType npts;
  const vtkIdType* ids;
  for (polys->InitTraversal(); polys->GetNextCell(npts, ids);)
  {
    for (vtkIdType i = 0; i < npts; ++i)
    {
      mesh.Connectivity.push_back(static_cast<int>(ids[i]));
    }
    mesh.Offsets.push_back(static_cast<int>(mesh.Connectivity.size()));
  }
  return true;
}

vtkDataArray* RequireCellArray(
  vtkPolyData* input, const char* name, int components, bool integral, std::string& error)
{
  vtkAbstractArray* abstract = input->GetCellData()->GetAbstractArray(name);
  if (!abstract)
  {
    error = std::string("the input has no cell array '") + name + "'";
    return nullptr;
  }
  vtkDataArray* array = vtkDataArray::SafeDownCast(abstract);
  if (!array)
  {
    error = std::string("cell array '") + name + "' is a " + abstract->GetClassName() +
      "; it must be a numeric array";
    return nullptr;
  }
  if (array->GetNumberOfTuples() != input->GetNumberOfCells())
  {
    error = std::string("cell array '") + name + "' has " + std::to_string(array->GetNumberOfTuples()) +
      " tuples; it needs one per cell (" + std::to_string(input->GetNumberOfCells()) + ")";
    return nullptr;
  }
  if (array->GetNumberOfComponents() != components)
  {
    error = std::string("cell array '") + name + "' has " +
      std::to_string(array->GetNumberOfComponents()) + " components; it needs " +
      std::to_string(components);
    return nullptr;
  }
  if (integral)
  {
    for (vtkIdType i = 0; i < array->GetNumberOfTuples(); ++i)
    {
      const double v = array->GetComponent(i, 0);
      // Integral and within int: ids are used as indices.
      if (!(std::floor(v) == v) || std::fabs(v) > 2147483647.0)
      {
        error = std::string("cell array '") + name + "' must hold integers (in the int range); cell " +
          std::to_string(i) + " has " + std::to_string(v);
        return nullptr;
      }
    }
  }
  return array;
}

bool ReadSceneArrays(vtkPolyData* input, radiosity::SceneMesh& mesh,
  std::vector<radiosity::Vec3>& emission, std::string& error)
{
  vtkDataArray* reflectance = RequireCellArray(input, "Reflectance", 3, false, error);
  vtkDataArray* lightId = reflectance ? RequireCellArray(input, "LightId", 1, true, error) : nullptr;
  if (!lightId)
  {
    return false;
  }
  vtkDataArray* patch = nullptr;
  if (input->GetCellData()->GetAbstractArray("PatchId") &&
    !(patch = RequireCellArray(input, "PatchId", 1, true, error)))
  {
    return false;
  }
  vtkDataArray* color = nullptr;
  if (input->GetCellData()->GetAbstractArray("Emission") &&
    !(color = RequireCellArray(input, "Emission", 3, false, error)))
  {
    return false;
  }
  const vtkIdType n = input->GetNumberOfPolys();
  mesh.Reflectance.resize(n);
  mesh.LightId.resize(n);
  mesh.PatchId.assign(patch ? n : 0, 0);
  emission.assign(color ? n : 0, radiosity::Vec3());
  for (vtkIdType i = 0; i < n; ++i)
  {
    double r[3];
    reflectance->GetTuple(i, r);
    mesh.Reflectance[i] = { r[0], r[1], r[2] };
    if (!(error = radiosity::ReflectanceProblem(mesh.Reflectance[i], i)).empty())
    {
      return false;
    }
    mesh.LightId[i] = static_cast<int>(lightId->GetComponent(i, 0));
    if (patch)
    {
      mesh.PatchId[i] = static_cast<int>(patch->GetComponent(i, 0));
    }
    if (color)
    {
      color->GetTuple(i, r);
      if (!std::isfinite(r[0]) || !std::isfinite(r[1]) || !std::isfinite(r[2]) || r[0] < 0 ||
        r[1] < 0 || r[2] < 0)
      {
        error = "Emission of cell " + std::to_string(i) + " must be finite and non-negative";
        return false;
      }
      emission[i] = { r[0], r[1], r[2] };
    }
  }
  return true;
}

void AddStrings(vtkFieldData* fields, const char* name, const std::vector<std::string>& values)
{
  vtkNew<vtkStringArray> array;
  array->SetName(name);
  for (const std::string& value : values)
  {
    array->InsertNextValue(value);
  }
  fields->AddArray(array);
}

std::vector<std::string> LightNames(vtkFieldData* fields, int count)
{
  std::vector<std::string> names(count);
  const std::vector<std::string> given = vtkRadiosityLightNames(fields);
  std::set<std::string> used;
  for (int i = 0; i < count; ++i)
  {
    std::string name = i < static_cast<int>(given.size()) ? given[i] : std::string();
    // Names become array names: keep them non-empty and unique.
    if (name.empty() || !used.insert(name).second)
    {
      name = "Light" + std::to_string(i);
      for (int suffix = 1; !used.insert(name).second; ++suffix)
      {
        name = "Light" + std::to_string(i) + "_" + std::to_string(suffix);
      }
    }
    names[i] = name;
  }
  return names;
}


bool FailedUpstream(vtkDataObject* input)
{
  return input && input->GetFieldData()->GetAbstractArray(FailureMarker) != nullptr;
}

namespace
{
/// Empties `output` and marks it, so that filters downstream stay quiet instead of
/// repeating the error in their own words.
void MarkFailed(vtkPolyData* output)
{
  if (!output)
  {
    return;
  }
  output->Initialize();
  vtkNew<vtkIntArray> marker;
  marker->SetName(FailureMarker);
  marker->InsertNextValue(1);
  output->GetFieldData()->AddArray(marker);
}
}

int Threads(int asked)
{
  if (asked > 0)
  {
    return asked;
  }
  const char* backend = vtkSMPTools::GetBackend();
  return backend && std::string(backend) != "Sequential" ? vtkSMPTools::GetEstimatedNumberOfThreads() : 0;
}

std::string Caught(const std::function<std::string()>& work)
{
  try
  {
    return work();
  }
  catch (const std::bad_alloc&)
  {
    return "out of memory; use a larger ElementSize (or PatchSize), fewer lights, or LightBanks";
  }
  catch (const std::exception& e)
  {
    return std::string("internal error: ") + e.what();
  }
}

int Guarded(vtkAlgorithm* self, vtkDataObject* input, vtkPolyData* output,
  const std::function<int()>& work, vtkMultiProcessController* ranks)
{
  int done = 0;
  if (FailedUpstream(input))
  {
    // Only where the update reaches this filter anyway: a second update of a failed
    // pipeline, the failed output set as its input directly, or on ParaView's MPI server
    // below the scene reader (which passes a failed read on there).
    vtkErrorWithObjectMacro(self, << "Cannot run: the input is the output of a filter that failed (see that "
                                     "filter's error).");
  }
  else
  {
    const std::string failure = Caught([&]() {
      done = work() != 0 ? 1 : 0;
      return std::string();
    });
    if (!failure.empty())
    {
      vtkErrorWithObjectMacro(self, << "Failed: " << failure << ".");
    }
  }
  if (ranks)
  {
    int mine = done;
    ranks->AllReduce(&mine, &done, 1, vtkCommunicator::MIN_OP);
  }
  if (!done)
  {
    MarkFailed(output);
  }
  return done;
}

bool UpdateForWriting(vtkAlgorithm* writer)
{
  if (writer->GetNumberOfInputConnections(0) < 1)
  {
    vtkErrorWithObjectMacro(writer, << "Cannot write: no input (SetInputConnection or SetInputData first).");
    return false;
  }
  writer->Modified(); // a writer writes each time it is asked, changed or not
  auto* streaming = vtkStreamingDemandDrivenPipeline::SafeDownCast(writer->GetExecutive());
  const int updated = streaming ? streaming->UpdateWholeExtent() : writer->GetExecutive()->Update();
  if (!updated)
  {
    vtkErrorWithObjectMacro(writer, << "Cannot write: the update failed upstream (see the filter's error).");
  }
  return updated != 0;
}

void WarningList::Add(vtkObject* self, const std::string& message)
{
  if (!this->Quiet)
  {
    vtkWarningWithObjectMacro(self, << message);
  }
  this->Messages.push_back(message);
}

void WarningList::AddTo(vtkFieldData* fields, bool replaceRepeats) const
{
  vtkStringArray* upstream = vtkStringArray::SafeDownCast(fields->GetAbstractArray("Warnings"));
  const auto gist = [](const std::string& message) { return message.substr(0, std::min(message.find(':'), message.find(" ("))); };
  const auto kept = [&](vtkIdType i) {
    const std::string said = gist(upstream->GetValue(i));
    return !replaceRepeats ||
      std::none_of(this->Messages.begin(), this->Messages.end(), [&](const std::string& m) { return gist(m) == said; });
  };
  bool dropped = false;
  for (vtkIdType i = 0; upstream && i < upstream->GetNumberOfValues(); ++i)
  {
    dropped = dropped || !kept(i);
  }
  if (this->Messages.empty() && !dropped)
  {
    return;
  }
  vtkNew<vtkStringArray> all;
  all->SetName("Warnings");
  for (vtkIdType i = 0; upstream && i < upstream->GetNumberOfValues(); ++i)
  {
    if (kept(i))
    {
      all->InsertNextValue(upstream->GetValue(i));
    }
  }
  for (const std::string& message : this->Messages)
  {
    all->InsertNextValue(message);
  }
  fields->AddArray(all);
}

std::shared_ptr<const radiosity::WorkerPool> SharedPool()
{
  static std::mutex lock;
  static std::shared_ptr<const radiosity::WorkerPool> pool;
  static int threads = -1;
  const int now = Threads(0);
  std::lock_guard<std::mutex> hold(lock);
  if (!pool || now != threads)
  {
    pool = std::make_shared<const radiosity::WorkerPool>(now); // a caller still holds the old one
    threads = now;
  }
  return pool;
}

}
