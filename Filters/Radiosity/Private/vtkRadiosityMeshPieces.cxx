#include "vtkRadiosityMeshPieces.h"
#include "vtkRadiosityPieces.h"

#include "vtkAbstractArray.h"
#include "vtkCellData.h"
#include "vtkDoubleArray.h"
#include "vtkMultiProcessController.h"
#include "vtkNew.h"
#include "vtkPolyData.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>

namespace vtkRadiosityMeshPieces
{

std::vector<int> SurfaceKeys(const radiosity::SceneMesh& mesh, const std::vector<radiosity::Vec3>& emission)
{
  std::map<std::tuple<double, double, double, int, double, double, double>, int> materials;
  std::vector<int> surfaceKey(mesh.NumberOfPolygons(), 0);
  for (int i = 0; i < mesh.NumberOfPolygons() && i < static_cast<int>(mesh.Reflectance.size()); ++i)
  {
    const radiosity::Vec3& r = mesh.Reflectance[i];
    const radiosity::Vec3 e = emission.empty() ? radiosity::Vec3() : emission[i];
    const int light = i < static_cast<int>(mesh.LightId.size()) ? mesh.LightId[i] : -1;
    const auto key = std::make_tuple(r.x, r.y, r.z, light, e.x, e.y, e.z);
    surfaceKey[i] = materials.emplace(key, static_cast<int>(materials.size())).first->second;
  }
  return surfaceKey;
}

std::vector<char> Lamps(const radiosity::SceneMesh& mesh, const std::vector<radiosity::Vec3>& emission)
{
  std::vector<char> lamps(mesh.NumberOfPolygons(), 0);
  for (size_t i = 0; i < lamps.size(); ++i)
  {
    const bool lit = i < emission.size() && (emission[i].x > 0 || emission[i].y > 0 || emission[i].z > 0);
    lamps[i] = lit || (i < mesh.LightId.size() && mesh.LightId[i] >= 0);
  }
  return lamps;
}

double OwnQuantum(vtkPolyData* input, bool upstream)
{
  if (upstream || !input || input->GetNumberOfPoints() == 0)
  {
    return 0.0;
  }
  double bounds[6];
  input->GetBounds(bounds);
  const double farthest = std::max({ std::fabs(bounds[0]), std::fabs(bounds[1]), std::fabs(bounds[2]),
    std::fabs(bounds[3]), std::fabs(bounds[4]), std::fabs(bounds[5]) });
  return vtkRadiosityAdapter::PointQuantum(input, farthest);
}

GatheredScene GatherWholeScene(vtkObject* self, vtkMultiProcessController* parallel, vtkPolyData* input,
  bool upstream, vtkRadiosityAdapter::WarningList& warnings)
{
  vtkNew<vtkPolyData> shape;
  if (!upstream && input)
  {
    shape->SetPoints(input->GetPoints());
    shape->SetPolys(input->GetPolys());
    // What tells the surfaces apart, and nothing more (a string array would make every
    // rank take VTK's slow way); Emission as zeros where a piece has none, since the
    // pieces' append keeps only the arrays all of them have.
    for (const char* name : { "Reflectance", "LightId", "Emission" })
    {
      if (vtkAbstractArray* array = input->GetCellData()->GetAbstractArray(name))
      {
        shape->GetCellData()->AddArray(array);
      }
    }
    if (!shape->GetCellData()->HasArray("Emission"))
    {
      vtkNew<vtkDoubleArray> none;
      none->SetName("Emission");
      none->SetNumberOfComponents(3);
      none->SetNumberOfTuples(shape->GetNumberOfCells());
      none->Fill(0.0);
      shape->GetCellData()->AddArray(none);
    }
  }
  vtkNew<vtkPolyData> gathered;
  vtkRadiosityPieces::AllGather(parallel, shape, gathered);
  long long first = 0;
  vtkRadiosityPieces::SumOverRanks(parallel, shape->GetNumberOfCells(), &first);
  GatheredScene whole;
  std::string ignored; // a rank's own piece reports its problems itself
  std::vector<radiosity::Vec3> emission;
  whole.HasSurfaces = vtkRadiosityAdapter::CopyPolygons(gathered, whole.Mesh, ignored) &&
    vtkRadiosityAdapter::ReadSceneArrays(gathered, whole.Mesh, emission, ignored);
  if (whole.HasSurfaces)
  {
    whole.Surfaces.SurfaceKey = SurfaceKeys(whole.Mesh, emission);
    whole.Surfaces.Lamps = Lamps(whole.Mesh, emission);
    whole.Surfaces.FirstPolygon = static_cast<int>(first);
  }
  else if (whole.Mesh.NumberOfPolygons() > 0 && parallel->GetLocalProcessId() == 0)
  {
    warnings.Add(self, "Coincident copies and overlapping faces are looked for within each piece only: the "
                       "pieces' Reflectance and LightId could not be read together");
  }
  return whole;
}

vtkRadiosityAdapter::WarningList EveryRanksWarnings(
  vtkMultiProcessController* parallel, const vtkRadiosityAdapter::WarningList& mine)
{
  vtkRadiosityAdapter::WarningList all(true);
  for (const std::string& message : vtkRadiosityPieces::AllGatherStrings(parallel, mine.GetMessages()))
  {
    const std::vector<std::string>& kept = all.GetMessages();
    if (std::find(kept.begin(), kept.end(), message) == kept.end()) // one said by every rank, once
    {
      all.Keep(message);
    }
  }
  return all;
}

std::string AgreeOnPieces(vtkMultiProcessController* parallel, const std::string& error, bool empty,
  vtkPolyData* input, const radiosity::MeshedPolygons& meshed, long long& firstPatch)
{
  const long long failures = vtkRadiosityPieces::SumOverRanks(parallel, error.empty() ? 0 : 1);
  const long long cells = vtkRadiosityPieces::SumOverRanks(parallel, empty ? 0 : input->GetNumberOfCells());
  vtkRadiosityPieces::SumOverRanks(parallel, error.empty() ? meshed.Patches : 0, &firstPatch);
  if (!error.empty())
  {
    return error;
  }
  if (failures)
  {
    return "another rank could not mesh its piece (see its error)";
  }
  return cells ? std::string() : std::string("the input has no polygons");
}

} // namespace vtkRadiosityMeshPieces
