#include "Import/SceneImport.h"

#include "Geometry/Polygon.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <sstream>

namespace radiosity
{
namespace
{

bool Finite(const Vec3& v)
{
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

Vec3 Clamped(const Vec3& v)
{
  auto unit = [](double x) { return std::min(1.0, std::max(0.0, x)); };
  return { unit(v.x), unit(v.y), unit(v.z) };
}

bool InUnitRange(const Vec3& v)
{
  return v.x >= 0 && v.x <= 1 && v.y >= 0 && v.y <= 1 && v.z >= 0 && v.z <= 1;
}

std::string CheckMaterials(const std::vector<ImportMaterial>& materials)
{
  for (const ImportMaterial& m : materials)
  {
    if (!Finite(m.Diffuse) || !Finite(m.Emissive))
    {
      return "material '" + m.Name + "' has a color that is not a finite number";
    }
    if (m.Emissive.x < 0 || m.Emissive.y < 0 || m.Emissive.z < 0)
    {
      return "material '" + m.Name + "' has a negative emissive color";
    }
  }
  return std::string();
}

bool Emits(const ImportMaterial& m)
{
  return m.Emissive.x > 0 || m.Emissive.y > 0 || m.Emissive.z > 0;
}

/// Polygon i's point ids, a corner repeated in a row dropped (as some exporters write).
std::vector<int> CornerIds(const RawScene& raw, int i)
{
  std::vector<int> ids;
  for (int k = raw.Offsets[i]; k < raw.Offsets[i + 1]; ++k)
  {
    const int id = raw.Connectivity[k];
    if (ids.empty() || ids.back() != id)
    {
      ids.push_back(id);
    }
  }
  while (ids.size() > 1 && ids.front() == ids.back())
  {
    ids.pop_back();
  }
  return ids;
}

/// Drops points no polygon uses (files share vertex lists between meshes), renumbering.
void KeepUsedPoints(SceneMesh& mesh)
{
  std::vector<int> newId(mesh.Points.size(), -1);
  std::vector<Vec3> used;
  for (int& id : mesh.Connectivity)
  {
    if (newId[id] < 0)
    {
      newId[id] = static_cast<int>(used.size());
      used.push_back(mesh.Points[id]);
    }
    id = newId[id];
  }
  mesh.Points.swap(used);
}

/// A unique light name: the wanted one, or with " (2)", " (3)"... when taken.
std::string UniqueName(const std::string& wanted, std::set<std::string>& taken)
{
  std::string name = wanted.empty() ? "Light" : wanted;
  for (int n = 2; taken.count(name); ++n)
  {
    name = (wanted.empty() ? "Light" : wanted) + " (" + std::to_string(n) + ")";
  }
  taken.insert(name);
  return name;
}

/// Light ids per kept polygon: one light per emissive material (or per object and
/// emissive material), in order of first use; names from the material or object.
void AssignLights(const RawScene& raw, const std::vector<int>& kept, const ImportOptions& options,
  ImportedScene& out)
{
  std::map<std::pair<int, int>, int> lightOf;
  std::set<std::string> taken;
  for (size_t p = 0; p < kept.size(); ++p)
  {
    const int i = kept[p];
    const int m = raw.Material[i];
    if (m < 0 || !Emits(raw.Materials[m]))
    {
      out.Mesh.LightId.push_back(-1);
      out.Emission.push_back(Vec3());
      continue;
    }
    const int object = options.LightsPerObject ? raw.Object[i] : -1;
    auto found = lightOf.find({ object, m });
    if (found == lightOf.end())
    {
      const std::string& material = raw.Materials[m].Name;
      const std::string wanted = object >= 0 && object < static_cast<int>(raw.ObjectNames.size())
        ? raw.ObjectNames[object]
        : material;
      found = lightOf.emplace(std::make_pair(object, m), static_cast<int>(out.LightNames.size())).first;
      out.LightNames.push_back(UniqueName(wanted, taken));
    }
    out.Mesh.LightId.push_back(found->second);
    out.Emission.push_back(raw.Materials[m].Emissive);
  }
}

std::string Summarize(const ImportedScene& out)
{
  std::ostringstream text;
  text << out.Mesh.NumberOfPolygons() << " polygons, " << out.MaterialNames.size() << " materials, "
       << out.LightNames.size() << " lights, " << out.Dropped << " degenerate cells dropped";
  return text.str();
}

} // namespace

namespace
{
/// The raw scene's lists against each other and its numbers finite: the file said it.
std::string CheckRawScene(const RawScene& raw)
{
  const std::string error = CheckMaterials(raw.Materials);
  if (!error.empty())
  {
    return error;
  }
  const size_t polygons = static_cast<size_t>(raw.NumberOfPolygons());
  if (raw.Material.size() != polygons || raw.Object.size() != polygons || (!raw.Color.empty() && raw.Color.size() != polygons))
  {
    return "internal: material and object lists do not match the polygons";
  }
  for (int id : raw.Connectivity)
  {
    if (id < 0 || id >= static_cast<int>(raw.Points.size()))
    {
      return "a polygon refers to point " + std::to_string(id) + ", which does not exist";
    }
  }
  for (int m : raw.Material)
  {
    if (m >= static_cast<int>(raw.Materials.size()))
    {
      return "internal: a polygon refers to material " + std::to_string(m) + ", which does not exist";
    }
  }
  for (const Vec3& c : raw.Color)
  {
    if (!Finite(c))
    {
      return "a polygon color is not a finite number";
    }
  }
  for (size_t p = 0; p < raw.Points.size(); ++p)
  {
    if (!Finite(raw.Points[p]))
    {
      return "point " + std::to_string(p) + " has a coordinate that is not a finite number";
    }
  }
  return std::string();
}

/// The scaled points and every polygon that is not degenerate (their input indices in
/// `kept`; the others counted in out.Dropped).
void KeepPolygons(const RawScene& raw, double unitScale, ImportedScene& out, std::vector<int>& kept)
{
  out.Mesh.Points.reserve(raw.Points.size());
  for (const Vec3& p : raw.Points)
  {
    out.Mesh.Points.push_back(p * unitScale);
  }
  out.Mesh.PointQuantum = raw.PointQuantum * unitScale;
  for (int i = 0; i < raw.NumberOfPolygons(); ++i)
  {
    const std::vector<int> ids = CornerIds(raw, i);
    std::vector<Vec3> loop;
    for (int id : ids)
    {
      loop.push_back(out.Mesh.Points[id]);
    }
    if (ids.size() < 3 || !PolygonProblem(loop.data(), static_cast<int>(loop.size())).empty())
    {
      ++out.Dropped;
      continue;
    }
    kept.push_back(i);
    out.Mesh.AddPolygon(ids);
  }
}

/// Reflectance of the kept polygons from their materials (clamped into [0, 1]; 0.8 without
/// one), the material list, and a warning for each clamp or default.
void AssignMaterials(const RawScene& raw, const std::vector<int>& kept, ImportedScene& out)
{
  std::set<std::string> clamped;
  int unassigned = 0;
  for (int i : kept)
  {
    const int m = raw.Material[i];
    Vec3 diffuse = m >= 0 ? raw.Materials[m].Diffuse : Vec3{ 0.8, 0.8, 0.8 };
    if (!raw.Color.empty())
    {
      diffuse = { diffuse.x * raw.Color[i].x, diffuse.y * raw.Color[i].y, diffuse.z * raw.Color[i].z };
    }
    out.Mesh.Reflectance.push_back(Clamped(diffuse));
    if (m >= 0 && !InUnitRange(diffuse))
    {
      clamped.insert(raw.Materials[m].Name);
    }
    unassigned += m < 0;
    out.Material.push_back(m < 0 ? static_cast<int>(raw.Materials.size()) : m);
  }
  for (const ImportMaterial& m : raw.Materials)
  {
    out.MaterialNames.push_back(m.Name);
  }
  if (unassigned)
  {
    out.MaterialNames.push_back("(none)");
    out.Warnings.push_back(std::to_string(unassigned) + " polygons have no material: reflectance 0.8");
  }
  if (!clamped.empty())
  {
    std::string names;
    for (const std::string& name : clamped)
    {
      names += (names.empty() ? "'" : ", '") + name + "'";
    }
    out.Warnings.push_back("diffuse colors outside [0, 1] clamped for " + std::to_string(clamped.size()) +
      " materials: " + names);
  }
}
} // namespace

std::string BuildImportedScene(const RawScene& raw, const ImportOptions& options, ImportedScene& out)
{
  out = ImportedScene();
  if (!(options.UnitScale > 0) || !std::isfinite(options.UnitScale))
  {
    return "the unit scale must be a positive number";
  }
  const std::string error = CheckRawScene(raw);
  if (!error.empty())
  {
    return error;
  }
  std::vector<int> kept;
  KeepPolygons(raw, options.UnitScale, out, kept);
  if (kept.empty())
  {
    return raw.NumberOfPolygons() ? "every polygon is degenerate (zero area or collinear points)" : "no polygons";
  }
  KeepUsedPoints(out.Mesh);
  AssignMaterials(raw, kept, out);
  if (out.Dropped)
  {
    out.Warnings.push_back(std::to_string(out.Dropped) + " degenerate cells dropped (zero area, collinear points or crossing edges)");
  }
  AssignLights(raw, kept, options, out);
  if (out.LightNames.empty())
  {
    out.Warnings.push_back(NoLightsWarning);
  }
  out.Summary = Summarize(out);
  return std::string();
}

} // namespace radiosity
