#include "vtkRadiosityGLTFWriter.h"
#include "vtkRadiosityAdapter.h"
#include "vtkRadiosityCombine.h"
#include "vtkRadiosityLightDefaults.h"

#include "Base/AtomicFile.h"
#include "Base/Vec3.h"
#include "SceneFiles.h"
#include "Geometry/Polygon.h"

#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkErrorCode.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkInformation.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkStringArray.h"

#include <vtk_nlohmannjson.h>
#include VTK_NLOHMANN_JSON(json.hpp)

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <fstream>
#include <limits>
#include <set>
#include <stdexcept>

vtkStandardNewMacro(vtkRadiosityGLTFWriter);

namespace
{

using json = nlohmann::json;

constexpr int Float = 5126;       // glTF componentType FLOAT
constexpr int UnsignedInt = 5125; // glTF componentType UNSIGNED_INT

/// The binary chunk and the JSON that describes it, built up one accessor at a time.
struct GlbDocument
{
  std::string Binary;
  json Views = json::array();
  json Accessors = json::array();

  /// A float VEC3 accessor of `values` (3 per vertex), with bounds when `bounded`.
  int AddVec3(const std::vector<float>& values, bool bounded)
  {
    json accessor = { { "bufferView", this->AddView(values.data(), values.size() * sizeof(float), 34962) },
      { "componentType", Float }, { "count", values.size() / 3 }, { "type", "VEC3" } };
    if (bounded)
    {
      std::vector<float> lo(3, std::numeric_limits<float>::max()), hi(3, -std::numeric_limits<float>::max());
      for (size_t i = 0; i < values.size(); ++i)
      {
        lo[i % 3] = std::min(lo[i % 3], values[i]);
        hi[i % 3] = std::max(hi[i % 3], values[i]);
      }
      accessor["min"] = lo;
      accessor["max"] = hi;
    }
    this->Accessors.push_back(accessor);
    return static_cast<int>(this->Accessors.size()) - 1;
  }

  int AddIndices(const std::vector<std::uint32_t>& indices)
  {
    this->Accessors.push_back({ { "bufferView", this->AddView(indices.data(), indices.size() * 4, 34963) },
      { "componentType", UnsignedInt }, { "count", indices.size() }, { "type", "SCALAR" } });
    return static_cast<int>(this->Accessors.size()) - 1;
  }

  int AddView(const void* data, size_t bytes, int target)
  {
    this->Views.push_back({ { "buffer", 0 }, { "byteOffset", this->Binary.size() }, { "byteLength", bytes },
      { "target", target } });
    this->Binary.append(static_cast<const char*>(data), bytes);
    this->Binary.append((4 - this->Binary.size() % 4) % 4, '\0'); // views start 4-aligned
    return static_cast<int>(this->Views.size()) - 1;
  }
};

/// Triangles of every polygon (ear clipping where one is not convex), as point indices.
std::vector<std::uint32_t> Triangles(const radiosity::SceneMesh& mesh)
{
  std::vector<std::uint32_t> indices;
  for (int i = 0; i < mesh.NumberOfPolygons(); ++i)
  {
    const std::vector<radiosity::Vec3> loop = radiosity::GatherLoop(mesh.Points, mesh.Offsets, mesh.Connectivity, i);
    for (int corner : radiosity::Triangulate(loop.data(), static_cast<int>(loop.size())))
    {
      indices.push_back(static_cast<std::uint32_t>(mesh.Polygon(i)[corner]));
    }
  }
  return indices;
}

std::vector<float> Floats(vtkDataArray* array, double scale, bool clamp)
{
  std::vector<float> values(3 * static_cast<size_t>(array->GetNumberOfTuples()));
  // Serial: GetComponent is not promised thread-safe for every array type (an implicit
  // array may cache a tuple), and this runs once per export.
  for (vtkIdType t = 0; t < array->GetNumberOfTuples(); ++t)
  {
    for (int c = 0; c < 3; ++c)
    {
      const double v = array->GetComponent(t, c) * scale;
      values[3 * t + c] = static_cast<float>(clamp ? std::min(1.0, std::max(0.0, v)) : v);
    }
  }
  return values;
}

/// `_RADIOSITY_` and the name in upper case, other characters as '_', made unique.
std::string AttributeName(const std::string& light, std::set<std::string>& taken)
{
  std::string name = "_RADIOSITY_";
  for (char c : light)
  {
    name += std::isalnum(static_cast<unsigned char>(c)) ? static_cast<char>(std::toupper(static_cast<unsigned char>(c))) : '_';
  }
  std::string unique = name;
  for (int n = 2; taken.count(unique); ++n)
  {
    unique = name + "_" + std::to_string(n);
  }
  taken.insert(unique);
  return unique;
}

} // namespace

vtkRadiosityGLTFWriter::vtkRadiosityGLTFWriter() = default;

vtkRadiosityGLTFWriter::~vtkRadiosityGLTFWriter()
{
  this->SetFileName(nullptr);
}

int vtkRadiosityGLTFWriter::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  return 1;
}

namespace
{
/// One vertex attribute per light (Radiosity_<name>) with its name and default color for
/// the extras; returns those light records.
json AddLightAttributes(vtkPolyData* input, GlbDocument& glb, json& attributes)
{
  const std::vector<std::string> names = vtkRadiosityLightNames(input->GetFieldData());
  vtkDataArray* defaults = input->GetFieldData()->GetArray("LightDefaultColors");
  vtkDataArray* inUse = input->GetFieldData()->GetArray("LightColors");
  vtkDataArray* enabled = input->GetFieldData()->GetArray("LightEnabled");
  json lights = json::array();
  std::set<std::string> taken;
  for (vtkIdType l = 0; l < static_cast<vtkIdType>(names.size()); ++l)
  {
    vtkDataArray* light = input->GetPointData()->GetArray(("Radiosity_" + names[l]).c_str());
    if (!light || light->GetNumberOfComponents() != 3)
    {
      continue;
    }
    const std::string attribute = AttributeName(names[l], taken);
    attributes[attribute] = glb.AddVec3(Floats(light, 1.0, false), false);
    double color[3] = { 1, 1, 1 };
    if (defaults && defaults->GetNumberOfComponents() == 3 && l < defaults->GetNumberOfTuples())
    {
      defaults->GetTuple(l, color);
    }
    json record = { { "name", names[l] }, { "attribute", attribute },
      { "defaultColor", { color[0], color[1], color[2] } } };
    // The relight filter's settings, where it made the input: a viewer starts from them.
    if (inUse && inUse->GetNumberOfComponents() == 3 && l < inUse->GetNumberOfTuples() && enabled &&
      l < enabled->GetNumberOfTuples())
    {
      inUse->GetTuple(l, color);
      record["color"] = { color[0], color[1], color[2] };
      record["enabled"] = enabled->GetComponent(l, 0) != 0;
    }
    lights.push_back(record);
  }
  return lights;
}

/// The relit radiosity of the points (`cells` false) or cells: the relight filter's
/// `Radiosity`, or for the solver's output every light at its default color, as the relight
/// filter starts. Null where neither is there.
vtkSmartPointer<vtkFloatArray> RelitRadiosity(vtkPolyData* input, bool cells)
{
  vtkDataSetAttributes* data = cells ? static_cast<vtkDataSetAttributes*>(input->GetCellData()) : input->GetPointData();
  vtkDataArray* relit = data->GetArray("Radiosity");
  if (relit && relit->GetNumberOfComponents() == 3)
  {
    vtkSmartPointer<vtkFloatArray> values = vtkFloatArray::SafeDownCast(relit); // the relight filter's is float
    if (!values)
    {
      values = vtkSmartPointer<vtkFloatArray>::New();
      values->DeepCopy(relit);
    }
    return values;
  }
  const std::vector<std::string> names = vtkRadiosityLightNames(input->GetFieldData());
  // The colors the relight filter starts from (vtkRadiosityRelight::ResolveWeights).
  const std::vector<double> weights =
    vtkRadiosityFlatColors(vtkRadiosityLightDefaultColors(input, static_cast<int>(names.size())));
  std::vector<std::string> arrays;
  for (const std::string& name : names)
  {
    arrays.push_back("Radiosity_" + name);
  }
  auto combined = vtkSmartPointer<vtkFloatArray>::New();
  std::string error;
  const vtkIdType tuples = cells ? input->GetNumberOfCells() : input->GetNumberOfPoints();
  if (arrays.empty() || !vtkRadiosityCombineSolutions(data, arrays, weights, tuples, combined, error))
  {
    return nullptr;
  }
  return combined;
}

/// Exposure 0 (the default): the relight filter's, from its field array Exposure, so the
/// file shows what the filter showed; else metered as it meters (on the cells where they
/// hold the solutions: they know which ones are lamps).
double ExposureFor(vtkPolyData* input, vtkFloatArray* relit, double set)
{
  vtkDataArray* used = input->GetFieldData()->GetArray("Exposure");
  if (set > 0 || (used && used->GetNumberOfTuples() > 0 && used->GetComponent(0, 0) > 0))
  {
    return set > 0 ? set : used->GetComponent(0, 0);
  }
  const vtkSmartPointer<vtkFloatArray> cells = RelitRadiosity(input, true);
  return cells ? vtkRadiosityMeteredExposure(input, cells, true)
               : relit ? vtkRadiosityMeteredExposure(input, relit, false) : 1.0;
}

json Document(const GlbDocument& glb, const json& primitive, const json& lights, double exposure)
{
  return { { "asset", { { "version", "2.0" }, { "generator", "RadiosityRelight" } } },
    { "extensionsUsed", { "KHR_materials_unlit" } }, { "scene", 0 }, { "scenes", { { { "nodes", { 0 } } } } },
    { "nodes", { { { "mesh", 0 } } } },
    { "meshes", { { { "primitives", { primitive } },
                  { "extras", { { "relight", { { "lights", lights }, { "exposure", exposure } } } } } } } },
    { "materials", { { { "name", "radiosity" }, { "doubleSided", true },
                     { "pbrMetallicRoughness", { { "baseColorFactor", { 1, 1, 1, 1 } } } },
                     { "extensions", { { "KHR_materials_unlit", json::object() } } } } } },
    { "buffers", { { { "byteLength", glb.Binary.size() } } } }, { "bufferViews", glb.Views },
    { "accessors", glb.Accessors } };
}

/// Writes `bytes` to `path` through a temporary file; "" or the problem.
std::string WriteBytes(const char* path, const std::string& bytes)
{
  try
  {
    return radiosity::WriteAtomically(path, [&](const char* temporary, bool& created) {
      std::ofstream out(temporary, std::ios::binary);
      if (!out)
      {
        throw std::runtime_error(std::string("cannot open ") + temporary);
      }
      created = true;
      out << bytes;
      if (!out.flush())
      {
        throw std::runtime_error("the disk refused the data");
      }
    });
  }
  catch (const std::exception& e)
  {
    return e.what();
  }
}
}

int vtkRadiosityGLTFWriter::Write()
{
  // Where it went through, WriteData has set the code.
  this->SetErrorCode(vtkRadiosityAdapter::UpdateForWriting(this) ? this->GetErrorCode() : vtkErrorCode::UserError);
  return this->GetErrorCode() == vtkErrorCode::NoError;
}

void vtkRadiosityGLTFWriter::WriteData()
{
  vtkPolyData* input = vtkPolyData::SafeDownCast(this->GetInput());
  radiosity::SceneMesh mesh;
  std::string error;
  if (!this->FileName || !*this->FileName)
  {
    vtkErrorMacro(<< "Cannot write: no FileName set.");
    this->SetErrorCode(vtkErrorCode::NoFileNameError);
    return;
  }
  if (!(this->Exposure >= 0 && this->Exposure <= VTK_DOUBLE_MAX))
  {
    error = "Exposure is " + std::to_string(this->Exposure) + "; it scales radiosity to colors: finite, not negative";
  }
  if (error.empty() && vtkRadiosityAdapter::FailedUpstream(input))
  {
    error = "a filter upstream failed (see its error)"; // a second Write of a failed pipeline
  }
  if (!error.empty() || !input ||
    !vtkRadiosityAdapter::CopyPolygons(input, mesh, error) || mesh.NumberOfPolygons() == 0)
  {
    vtkErrorMacro(<< "Cannot write glTF: " << (error.empty() ? "the input has no polygons" : error) << ".");
    this->SetErrorCode(vtkErrorCode::UserError);
    return;
  }
  GlbDocument glb;
  std::vector<float> positions;
  for (const radiosity::Vec3& p : mesh.Points)
  {
    positions.insert(positions.end(), { static_cast<float>(p.x), static_cast<float>(p.y), static_cast<float>(p.z) });
  }
  json attributes = { { "POSITION", glb.AddVec3(positions, true) } };
  const vtkSmartPointer<vtkFloatArray> relit = RelitRadiosity(input, false);
  const double exposure = ExposureFor(input, relit, this->Exposure);
  if (relit)
  {
    attributes["COLOR_0"] = glb.AddVec3(Floats(relit, exposure, true), false);
  }
  const json lights = AddLightAttributes(input, glb, attributes);
  if (lights.empty() && !input->GetPointData()->GetArray("Radiosity")) // StandardCombined writes this alone
  {
    vtkWarningMacro(<< "The input holds no radiosity (no Radiosity_<light> arrays): " << this->FileName
                    << " gets the geometry alone. Give the writer the solver's or the relight filter's output.");
  }
  const json primitive = { { "attributes", attributes }, { "indices", glb.AddIndices(Triangles(mesh)) },
    { "material", 0 }, { "mode", 4 } };
  std::string bytes;
  if (!SceneFiles::GlbBytes(Document(glb, primitive, lights, exposure).dump(), glb.Binary, bytes))
  {
    vtkErrorMacro(<< "Cannot write " << this->FileName << ": " << glb.Binary.size() / 1073741824.0
                  << " GiB of data is more than a .glb holds (4 GiB); write fewer lights or a coarser mesh.");
    this->SetErrorCode(vtkErrorCode::UserError);
    return;
  }
  if (!(error = WriteBytes(this->FileName, bytes)).empty())
  {
    vtkErrorMacro(<< "Cannot write " << this->FileName << ": " << error << ".");
    this->SetErrorCode(vtkErrorCode::CannotOpenFileError);
  }
}

void vtkRadiosityGLTFWriter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
  os << indent << "Exposure: " << this->Exposure << "\n";
}
