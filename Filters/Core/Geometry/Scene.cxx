#include "Geometry/Scene.h"
#include "Geometry/Polygon.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

namespace radiosity
{

void SceneMesh::AddPolygon(const std::vector<int>& ids)
{
  Connectivity.insert(Connectivity.end(), ids.begin(), ids.end());
  Offsets.push_back(static_cast<int>(Connectivity.size()));
}

namespace
{
bool Finite(const Vec3& v)
{
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

std::vector<Vec3> Loop(const SceneMesh& mesh, int i)
{
  return GatherLoop(mesh.Points, mesh.Offsets, mesh.Connectivity, i);
}
} // namespace

std::string ReflectanceProblem(const Vec3& r, long long cell)
{
  for (int c = 0; c < 3; ++c)
  {
    if (!(r[c] >= 0.0 && r[c] <= 1.0))
    {
      std::ostringstream err;
      err << "Reflectance of cell " << cell << " is " << r[c] << " in component " << c
          << "; it must be a number in [0, 1]";
      return err.str();
    }
  }
  return "";
}

namespace
{
/// The array sizes and the points; "" or the first problem.
std::string ArraysProblem(const SceneMesh& mesh)
{
  const int n = mesh.NumberOfPolygons();
  if (n <= 0)
  {
    return "the input has no polygons";
  }
  if (static_cast<int>(mesh.Reflectance.size()) != n || static_cast<int>(mesh.LightId.size()) != n)
  {
    return "Reflectance and LightId must have one tuple per polygon";
  }
  if (!mesh.PatchId.empty() && static_cast<int>(mesh.PatchId.size()) != n)
  {
    return "PatchId must have one tuple per polygon";
  }
  for (size_t p = 0; p < mesh.Points.size(); ++p)
  {
    if (!Finite(mesh.Points[p]))
    {
      return "point " + std::to_string(p) + " has a non-finite coordinate";
    }
  }
  return "";
}

/// Cell i's shape, reflectance and LightId; "" or the problem.
std::string CellProblem(const SceneMesh& mesh, int i)
{
  const int n = mesh.NumberOfPolygons();
  const int size = mesh.PolygonSize(i);
  std::ostringstream err;
  if (size < 3)
  {
    err << "cell " << i << " has " << size << " points; polygons need at least 3";
    return err.str();
  }
  for (int v = 0; v < size; ++v)
  {
    const int id = mesh.Polygon(i)[v];
    if (id < 0 || id >= static_cast<int>(mesh.Points.size()))
    {
      err << "cell " << i << " refers to missing point " << id;
      return err.str();
    }
  }
  const std::vector<Vec3> loop = Loop(mesh, i);
  const std::string problem = PolygonProblem(loop.data(), size);
  if (!problem.empty())
  {
    return "cell " + std::to_string(i) + " " + problem;
  }
  const std::string reflectance = ReflectanceProblem(mesh.Reflectance[i], i);
  if (!reflectance.empty())
  {
    return reflectance;
  }
  if (mesh.LightId[i] >= n)
  {
    err << "LightId of cell " << i << " is " << mesh.LightId[i] << "; there are only " << n
        << " cells, so ids must be -1 or 0..k-1 with k <= " << n;
    return err.str();
  }
  if (mesh.LightId[i] < -1)
  {
    err << "LightId of cell " << i << " is " << mesh.LightId[i] << "; use -1 or 0..k-1";
    return err.str();
  }
  return "";
}

/// The light ids 0..maxLight all used; "" or the first gap.
std::string LightGap(const SceneMesh& mesh, int maxLight)
{
  std::vector<char> seen(maxLight + 1, 0);
  for (int id : mesh.LightId)
  {
    if (id >= 0)
    {
      seen[id] = 1;
    }
  }
  for (int l = 0; l <= maxLight; ++l)
  {
    if (!seen[l])
    {
      return "LightId has a gap: no cell has id " + std::to_string(l) + " but ids go up to " +
        std::to_string(maxLight) + "; ids must be 0..k-1";
    }
  }
  return "";
}
}

std::string ValidateScene(const SceneMesh& mesh, int& numberOfLights, int pointLights)
{
  std::string problem = ArraysProblem(mesh);
  int maxLight = -1;
  for (int i = 0; i < mesh.NumberOfPolygons() && problem.empty(); ++i)
  {
    problem = CellProblem(mesh, i);
    maxLight = std::max(maxLight, mesh.LightId[i]);
  }
  if (!problem.empty())
  {
    return problem;
  }
  if (maxLight < 0 && pointLights == 0)
  {
    return "no cell has a LightId >= 0 and there are no luminaires: the scene has no lights (k = 0); add lamps "
           "(Mark Lights in ParaView, relight.mark_lights with relight.area_light or relight.luminaire in Python)";
  }
  if (!(problem = LightGap(mesh, maxLight)).empty())
  {
    return problem;
  }
  numberOfLights = maxLight + 1;
  return std::string();
}

double ElementRadius(const SceneMesh& mesh, const SceneGeometry& g, int e)
{
  double radius = 0;
  const int* ids = mesh.Polygon(e);
  for (int i = 0; i < mesh.PolygonSize(e); ++i)
  {
    radius = std::max(radius, Norm(mesh.Points[ids[i]] - g.Centroid[e]));
  }
  return radius;
}

SceneGeometry::SceneGeometry(const SceneMesh& mesh)
{
  const int n = mesh.NumberOfPolygons();
  Normal.resize(n);
  Area.resize(n);
  Centroid.resize(n);
  ElementPatch.resize(n);
  // Patches numbered in the order of their ids, not of their first elements: the solver's
  // PatchId output (split patches last) then numbers them as the solver did, however the
  // cells are ordered (ranks append their pieces in another order than one process).
  std::map<int, int> compact;
  for (int i = 0; i < n; ++i)
  {
    compact.emplace(mesh.PatchId.empty() ? i : mesh.PatchId[i], 0);
  }
  int next = 0;
  for (auto& id : compact)
  {
    id.second = next++;
  }
  PatchElements.assign(compact.size(), {});
  PatchArea.assign(compact.size(), 0.0);
  for (int i = 0; i < n; ++i)
  {
    const std::vector<Vec3> loop = Loop(mesh, i);
    const Vec3 newell = NewellVector(loop.data(), static_cast<int>(loop.size()));
    Normal[i] = Normalized(newell);
    Area[i] = 0.5 * Norm(newell);
    Centroid[i] = PolygonCentroid(loop.data(), static_cast<int>(loop.size()));
    const int patch = compact[mesh.PatchId.empty() ? i : mesh.PatchId[i]];
    ElementPatch[i] = patch;
    PatchElements[patch].push_back(i);
    PatchArea[patch] += Area[i];
  }
  SceneDiagonal = Bounds(mesh.Points).Diagonal();
  RayLift = std::max(1e-6 * SceneDiagonal, 4.0 * mesh.PointQuantum);
  Enclosed.assign(n, 0);
  Sheltered.assign(n, 0);
  PatchOpenArea = PatchArea;
}

} // namespace radiosity
