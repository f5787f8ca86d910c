#include "vtkRadiosityMovingScene.h"
#include "vtkRadiosityAdapter.h"
#include "vtkRadiosityPreparedScenes.h"

#include "Base/WorkerPool.h"
#include "Geometry/PointAverages.h"
#include "Relight/LightRig.h"
#include "Relight/MovingLights.h"
#include "Lights/Luminaires.h"
#include "Solve/PatchBasis.h"

#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkStringArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkIntArray.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"

#include <algorithm>
#include <cmath>
#include <map>

struct vtkRadiosityMovingScene::State
{
  vtkMTimeType SceneTime = 0, DynamicTime = 0;
  radiosity::SceneMesh Scene, Dynamic;
  std::unique_ptr<radiosity::MovingLightShader> Shader;
  bool Reused = false; ///< the shader shades on the solver's kept preparation
};

vtkRadiosityMovingScene::vtkRadiosityMovingScene()
  : Kept(new State)
{
}

vtkRadiosityMovingScene::~vtkRadiosityMovingScene() = default;

bool vtkRadiosityMovingScene::Reused() const
{
  return this->Kept->Reused;
}

namespace
{
/// result += values, tuple by tuple, as VTK's SMP tools split it (ParaView's threads).
void AddTo(vtkFloatArray* result, const std::vector<radiosity::Vec3>& values)
{
  float* out = result->GetPointer(0);
  vtkSMPTools::For(0, static_cast<vtkIdType>(values.size()), [&](vtkIdType begin, vtkIdType end) {
    for (vtkIdType i = begin; i < end; ++i)
    {
      out[3 * i + 0] += static_cast<float>(values[i].x);
      out[3 * i + 1] += static_cast<float>(values[i].y);
      out[3 * i + 2] += static_cast<float>(values[i].z);
    }
  });
}

/// The solver's basis, per element (cell array) or per patch node (field array plus the
/// cell arrays that interpolate it), checked against the scene's patches.
bool ReadBasis(vtkPolyData* scene, int patches, radiosity::BasisView& basis, std::string& error)
{
  const vtkIdType cells = scene->GetNumberOfCells();
  auto* perElement = vtkFloatArray::SafeDownCast(scene->GetCellData()->GetArray("PatchBasis"));
  auto* perNode = vtkFloatArray::SafeDownCast(scene->GetFieldData()->GetArray("PatchBasis"));
  auto* nodes = vtkIntArray::SafeDownCast(scene->GetCellData()->GetArray("PatchBasisNodes"));
  auto* weights = vtkFloatArray::SafeDownCast(scene->GetCellData()->GetArray("PatchBasisWeights"));
  vtkFloatArray* values = perElement ? perElement : perNode;
  if (!values || (!perElement && (!nodes || !weights)))
  {
    error = "'PatchBasis' must be a float array: per cell, or in the field data with the int cell array "
            "'PatchBasisNodes' and the float cell array 'PatchBasisWeights'";
    return false;
  }
  if (values->GetNumberOfComponents() != 3 * patches || (perElement && values->GetNumberOfTuples() != cells))
  {
    error = "'PatchBasis' has " + std::to_string(values->GetNumberOfTuples()) + " tuples of " +
      std::to_string(values->GetNumberOfComponents()) + " components; the scene needs " +
      (perElement ? std::to_string(cells) : std::string("one per node")) + " of " + std::to_string(3 * patches) +
      " (" + std::to_string(patches) + " patches)";
    return false;
  }
  basis = { patches, static_cast<int>(values->GetNumberOfTuples()), values->GetPointer(0) };
  if (perElement)
  {
    return true;
  }
  if (nodes->GetNumberOfComponents() != 3 || weights->GetNumberOfComponents() != 3 ||
    nodes->GetNumberOfTuples() != cells || weights->GetNumberOfTuples() != cells)
  {
    error = "'PatchBasisNodes' and 'PatchBasisWeights' need 3 components per cell";
    return false;
  }
  const int* node = nodes->GetPointer(0);
  if (std::any_of(node, node + 3 * cells, [&](int k) { return k < 0 || k >= basis.Receivers; }))
  {
    error = "'PatchBasisNodes' refers to a node outside 'PatchBasis' (" + std::to_string(basis.Receivers) + " nodes)";
    return false;
  }
  basis.Node = node;
  basis.Weight = weights->GetPointer(0);
  return true;
}
}

namespace
{
/// The kinds of the moving lights where `lights` names them: the string point arrays Kind
/// and Parameters (a luminaire's "goniometric" and "file=...; lumens=..."), the point
/// arrays Aim and Rotation (degrees). Each kind made once, shared by the lights that give
/// it alike; false with `error` naming the first light that cannot be made.
bool ReadMovingKinds(vtkPolyData* lights, std::vector<radiosity::MovingLight>& movers, std::string& error)
{
  auto* kinds = vtkStringArray::SafeDownCast(lights->GetPointData()->GetAbstractArray("Kind"));
  auto* parameters = vtkStringArray::SafeDownCast(lights->GetPointData()->GetAbstractArray("Parameters"));
  vtkDataArray* aim = lights->GetPointData()->GetArray("Aim");
  vtkDataArray* rotation = lights->GetPointData()->GetArray("Rotation");
  std::map<std::pair<std::string, std::string>, std::shared_ptr<const radiosity::LightDistribution>> made;
  for (vtkIdType i = 0; i < lights->GetNumberOfPoints(); ++i)
  {
    radiosity::MovingLight& light = movers[i];
    if (aim && aim->GetNumberOfComponents() == 3 && aim->GetNumberOfTuples() == lights->GetNumberOfPoints())
    {
      double v[3];
      aim->GetTuple(i, v);
      light.Aim = { v[0], v[1], v[2] };
    }
    if (rotation && rotation->GetNumberOfTuples() == lights->GetNumberOfPoints())
    {
      light.Rotation = rotation->GetComponent(i, 0);
    }
    if (kinds && i < kinds->GetNumberOfValues())
    {
      const auto key = std::make_pair(kinds->GetValue(i),
        parameters && i < parameters->GetNumberOfValues() ? parameters->GetValue(i) : std::string());
      auto& distribution = made[key];
      radiosity::LuminaireRow row;
      row.Name = "moving light " + std::to_string(i);
      row.Kind = key.first;
      row.Parameters = key.second;
      radiosity::PointLight check;
      if (!distribution && !(error = radiosity::MakePointLight(row, check)).empty())
      {
        return false;
      }
      distribution = distribution ? distribution : check.Distribution;
      light.Distribution = distribution;
    }
    if (!(error = radiosity::PointLightProblem(light, "moving light " + std::to_string(i))).empty())
    {
      return false;
    }
  }
  return true;
}

/// The moving lights of `lights` (points with Color, Intensity and optional Normal, or a
/// Kind with its Parameters, Aim and Rotation); false with `error` naming the first bad one.
bool ReadMovingLights(vtkPolyData* lights, std::vector<radiosity::MovingLight>& movers, std::string& error)
{
  movers.assign(lights->GetNumberOfPoints(), radiosity::MovingLight());
  vtkDataArray* color = lights->GetPointData()->GetArray("Color");
  vtkDataArray* intensity = lights->GetPointData()->GetArray("Intensity");
  vtkDataArray* normal = lights->GetPointData()->GetArray("Normal");
  for (vtkDataArray* array : { color, intensity, normal })
  {
    if (array && array->GetNumberOfTuples() != lights->GetNumberOfPoints())
    {
      error = std::string("moving-light array '") + array->GetName() + "' needs one tuple per light";
      return false;
    }
  }
  for (vtkIdType i = 0; i < lights->GetNumberOfPoints(); ++i)
  {
    radiosity::MovingLight& light = movers[i];
    double v[3];
    lights->GetPoint(i, v);
    light.Position = { v[0], v[1], v[2] };
    if (color && color->GetNumberOfComponents() == 3)
    {
      color->GetTuple(i, v);
      light.Color = { v[0], v[1], v[2] };
    }
    if (intensity)
    {
      light.Intensity = intensity->GetComponent(i, 0);
    }
    if (normal && normal->GetNumberOfComponents() == 3)
    {
      normal->GetTuple(i, v);
      std::string unused;
      light.Aim = { v[0], v[1], v[2] };
      light.Distribution = radiosity::MakeLambertianLight({}, unused);
    }
    const radiosity::Vec3& p = light.Position;
    const std::string invalid = radiosity::InvalidLightValues(light.Intensity, light.Color);
    if (!std::isfinite(p.x + p.y + p.z) || !invalid.empty())
    {
      error = "moving light " + std::to_string(i) + (invalid.empty() ? " has a non-finite position" : " " + invalid);
      return false;
    }
    const radiosity::Vec3& n = light.Aim;
    if (normal && normal->GetNumberOfComponents() == 3 && !(std::isfinite(n.x + n.y + n.z) && radiosity::Norm(n) > 0))
    {
      error = "moving light " + std::to_string(i) + " has a zero or non-finite Normal; leave the array out for "
                                                    "an isotropic light";
      return false;
    }
  }
  return ReadMovingKinds(lights, movers, error);
}
}

bool vtkRadiosityMovingScene::SwapDynamicObjects(vtkPolyData* dynamic, std::string& error)
{
  State& state = *this->Kept;
  const vtkMTimeType dynamicTime = dynamic ? dynamic->GetMTime() : 0;
  // Only the dynamic objects moved: swap them in the ray scene, keep the rest.
  state.Dynamic = radiosity::SceneMesh();
  if (dynamic && dynamic->GetNumberOfPolys() > 0 && !vtkRadiosityAdapter::CopyPolygons(dynamic, state.Dynamic, error))
  {
    error = "dynamic objects: " + error;
    state.DynamicTime = 0;
    return false;
  }
  bool swapped = false; // the objects' BVH is built on ParaView's threads
  vtkRadiosityAdapter::SharedPool()->Within([&] {
    swapped = state.Shader->SetDynamicObjects(state.Dynamic.NumberOfPolygons() > 0 ? &state.Dynamic : nullptr);
  });
  if (!swapped)
  {
    error = state.Shader->Error();
    state.Shader.reset();
    return false;
  }
  state.DynamicTime = dynamicTime;
  return true;
}

bool vtkRadiosityMovingScene::Rebuild(vtkPolyData* scene, vtkPolyData* dynamic, std::string& error)
{
  State& state = *this->Kept;
  state = State();
  std::vector<radiosity::Vec3> unused;
  int lightCount = 0;
  if (!vtkRadiosityAdapter::CopyPolygons(scene, state.Scene, error) ||
    !vtkRadiosityAdapter::ReadSceneArrays(scene, state.Scene, unused, error) ||
    !(error = radiosity::ValidateScene(state.Scene, lightCount, 1)).empty()) // the moving lights light it
  {
    return false;
  }
  if (dynamic && dynamic->GetNumberOfPolys() > 0 &&
    !vtkRadiosityAdapter::CopyPolygons(dynamic, state.Dynamic, error))
  {
    error = "dynamic objects: " + error;
    return false;
  }
  // The solver's preparation where it is kept (its patches are the basis's), else one
  // made here the same way and kept for the EXR writer.
  const vtkRadiosityPreparedScenes::MeshKey key = vtkRadiosityPreparedScenes::KeyOf(scene);
  radiosity::PreparedScene prepared = vtkRadiosityPreparedScenes::Find(scene, key, true);
  state.Reused = prepared.Geometry != nullptr;
  if (!prepared.Geometry &&
    !(error = radiosity::PrepareTransport(state.Scene, vtkRadiosityAdapter::Threads(0), {}, prepared)).empty())
  {
    return false;
  }
  vtkRadiosityPreparedScenes::Keep(scene, key, prepared);
  vtkRadiosityAdapter::SharedPool()->Within([&] {
    state.Shader.reset(new radiosity::MovingLightShader(
      state.Scene, prepared, state.Dynamic.NumberOfPolygons() > 0 ? &state.Dynamic : nullptr));
  });
  if (!state.Shader->Error().empty())
  {
    error = state.Shader->Error();
    state.Shader.reset();
    return false;
  }
  state.SceneTime = scene->GetMTime();
  state.DynamicTime = dynamic ? dynamic->GetMTime() : 0;
  return true;
}

bool vtkRadiosityMovingScene::Shade(vtkPolyData* scene, vtkPolyData* lights, vtkPolyData* dynamic,
  vtkFloatArray* pointResult, vtkFloatArray* cellResult, std::string& error)
{
  if (!scene->GetCellData()->GetArray("PatchBasis") && !scene->GetFieldData()->GetArray("PatchBasis"))
  {
    error = "moving lights need the solver's float array 'PatchBasis' (vtkLightTaggedRadiosity::PatchBasisOn())";
    return false;
  }
  State& state = *this->Kept;
  const vtkMTimeType sceneTime = scene->GetMTime();
  const vtkMTimeType dynamicTime = dynamic ? dynamic->GetMTime() : 0;
  if (state.Shader && state.SceneTime == sceneTime && state.DynamicTime != dynamicTime &&
    !this->SwapDynamicObjects(dynamic, error))
  {
    return false;
  }
  if ((!state.Shader || state.SceneTime != sceneTime || state.DynamicTime != dynamicTime) &&
    !this->Rebuild(scene, dynamic, error))
  {
    return false;
  }
  const radiosity::SceneGeometry& g = state.Shader->Geometry();
  radiosity::BasisView basis;
  std::vector<radiosity::MovingLight> movers;
  if (!ReadBasis(scene, static_cast<int>(g.PatchElements.size()), basis, error) ||
    !ReadMovingLights(lights, movers, error))
  {
    return false;
  }
  std::vector<radiosity::Vec3> direct, cells;
  const auto pool = vtkRadiosityAdapter::SharedPool();
  this->LastRays = state.Shader->Direct(movers, *pool, direct);
  radiosity::AddBasisInterreflection(g, direct, basis, *pool, cells);
  if (cellResult->GetNumberOfTuples() == static_cast<vtkIdType>(cells.size()))
  {
    AddTo(cellResult, cells);
  }
  if (pointResult->GetNumberOfTuples() == scene->GetNumberOfPoints())
  {
    AddTo(pointResult, radiosity::AverageToPoints(state.Scene, g, cells, 1));
  }
  return true;
}
