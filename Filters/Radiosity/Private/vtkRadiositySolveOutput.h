// The light-tagged solver filter's steps on either side of the core's solve: the input
// read once into the core's types, and the result written as arrays, field data and the
// convergence table. Private to the module.
#ifndef vtkRadiositySolveOutput_h
#define vtkRadiositySolveOutput_h

#include "vtkRadiosityAdapter.h"
#include "vtkRadiosityPreparedScenes.h"

#include "Solve/LightSolutions.h"
#include "Solve/RadiositySolver.h"

#include <string>
#include <vector>

class vtkAlgorithm;
class vtkFieldData;
class vtkPolyData;
class vtkTable;

namespace vtkRadiositySolveOutput
{
/// The scene as the core reads it, with its lights named and grouped.
struct SceneInput
{
  radiosity::SceneMesh Mesh;
  std::vector<radiosity::Vec3> Emission;
  std::vector<std::string> LightNames; ///< one per light, from the field array LightNames
  radiosity::LightGrouping Grouping;
  int Lights = 0;
  /// The luminaires (field arrays Luminaire*), each a solution after the grouping's.
  std::vector<radiosity::PointLight> PointLights;
  std::vector<std::string> PointLightNames;
  /// The input mesh's content, hashed once per solve: the preparation is found and kept
  /// under it, for the input and for the output that shares the input's points.
  vtkRadiosityPreparedScenes::MeshKey Key;
};

/// Converts and checks the input, groups its lights (field arrays LightBanks and
/// StaticLights) and makes its luminaires (reading their photometric files); "" or the
/// problem.
std::string ReadInput(vtkPolyData* input, radiosity::EffectMode separation, SceneInput& scene);

/// "" when every rank has the memory for `solutions` solutions of the scene, else the
/// problem with what to do about it; all ranks agree before the solve's first sum.
std::string CheckSolveMemory(
  const SceneInput& scene, int solutions, bool separateDirect, const radiosity::ProcessGroup& group);

/// The names of the output's solutions: a light's own, or its bank's members joined by
/// '+'; one empty name for a combined solve.
std::vector<std::string> SolutionNames(const SceneInput& scene, bool combined);

/// The solution arrays (cells and points, Radiosity_<name>, Illuminance_<name> and
/// Direct_<name>) and the
/// split patches' PatchId on `output`, a shallow copy of the input.
void AddSolutionArrays(vtkPolyData* output, const SceneInput& scene, const radiosity::RadiositySolver& solver,
  const radiosity::Solution& result, const std::vector<std::string>& names, bool combined);

/// LightNames and LightDefaultColors, warning about lights that have no color.
void AddLightFields(vtkAlgorithm* self, vtkFieldData* fields, const SceneInput& scene,
  const std::vector<std::string>& names, vtkRadiosityAdapter::WarningList& warnings);

/// Effects, EffectDecisions, EffectReasons, SolverMethod, SolverStatus, SolveSeconds (what
/// the solve took, beside the estimate in SolverMethod) and UnshotHistory.
void AddStatusFields(vtkFieldData* fields, const std::vector<radiosity::EffectDecision>& effects,
  const radiosity::SolverStatistics& stats, bool aborted, double seconds);

/// The convergence table: Shot, Time, Remaining and Remaining_<name> per solution.
void FillHistory(vtkTable* history, const radiosity::SolverStatistics& stats, const std::vector<std::string>& names,
  int columns, bool combined);

/// Why a solve stopped short of convergence, for a warning; empty if it converged.
std::string DescribeEarlyStop(const radiosity::SolverStatistics& stats, double budget, double threshold);

/// The solve's one line in the log (and each rank's share where several solved).
void LogSolve(const radiosity::SolverStatistics& stats, double seconds, int elements, int rank,
  const std::vector<radiosity::EffectDecision>& effects);
}

#endif
