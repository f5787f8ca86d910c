// The mesher's steps over the pieces of a scene: what tells its surfaces apart (the keys
// that decide which cells share points, the lamps), how far its float points can be off,
// and on ParaView's MPI server the whole scene gathered on every rank, the ranks' verdict
// and their warnings. Not wrapped.
#ifndef vtkRadiosityMeshPieces_h
#define vtkRadiosityMeshPieces_h

#include "Geometry/Scene.h"
#include "Mesh/Mesher.h"
#include "vtkRadiosityAdapter.h"

#include <string>
#include <vector>

class vtkMultiProcessController;
class vtkObject;
class vtkPolyData;

namespace vtkRadiosityMeshPieces
{

/// Cells share points (and triangles pair into quads) only if reflectance, light and
/// emission all agree: one key per such material.
std::vector<int> SurfaceKeys(const radiosity::SceneMesh& mesh, const std::vector<radiosity::Vec3>& emission);

/// 1 for each cell that emits: of coincident copies in other materials the lamp is kept.
std::vector<char> Lamps(const radiosity::SceneMesh& mesh, const std::vector<radiosity::Vec3>& emission);

/// How far this rank's float points can be off their places (0 for none or double ones).
double OwnQuantum(vtkPolyData* input, bool upstream);

/// Every rank's polygons, in rank order: surfaces of other pieces that stand on this
/// piece's cut it (ContactCuts.h), and copies and overlaps are found across the pieces
/// (WholeSceneCuts.h), with surface keys numbered over the whole scene so the ranks agree.
struct GatheredScene
{
  radiosity::SceneMesh Mesh;
  radiosity::WholeSceneSurfaces Surfaces;
  bool HasSurfaces = false; ///< false where the whole's arrays could not be read
};
/// Where the whole's arrays cannot be read together, rank 0 says so in `warnings`.
GatheredScene GatherWholeScene(vtkObject* self, vtkMultiProcessController* parallel, vtkPolyData* input,
  bool upstream, vtkRadiosityAdapter::WarningList& warnings);

/// Every rank's warnings, this rank's printed as they came and the others' kept for the
/// output's Warnings array: the client shows one piece's field data, and a copy found on
/// another rank was missing from it.
vtkRadiosityAdapter::WarningList EveryRanksWarnings(
  vtkMultiProcessController* parallel, const vtkRadiosityAdapter::WarningList& mine);

/// The ranks' verdict on their pieces: this rank's error, another's, or none at all cells;
/// `firstPatch` receives the patches of the ranks before this one.
std::string AgreeOnPieces(vtkMultiProcessController* parallel, const std::string& error, bool empty,
  vtkPolyData* input, const radiosity::MeshedPolygons& meshed, long long& firstPatch);

} // namespace vtkRadiosityMeshPieces

#endif
