// The filters on ParaView's MPI server: every rank holds a piece of the scene. The solver
// sees the whole scene on every rank, each rank computes the transport to its share of the
// receivers, and each rank gets its own piece of the result; the mesher numbers patches
// across ranks. Not wrapped.
#ifndef vtkRadiosityPieces_h
#define vtkRadiosityPieces_h

#include "Base/ProcessGroup.h"

#include "vtkPolyData.h" // for the kept whole scene
#include "vtkSmartPointer.h"
#include "vtkType.h"

#include <functional>
#include <string>
#include <vector>

class vtkInformation;
class vtkMultiProcessController;
class vtkPolyData;
class vtkTable;

namespace vtkRadiosityPieces
{

/// The global controller when this execution is one piece of a distributed pipeline (as
/// on ParaView's MPI server: as many pieces requested as there are processes), else null.
/// A plain VTK pipeline in one process of an MPI job asks for one piece and works alone:
/// collectives there would wait for ranks that never come.
vtkMultiProcessController* Parallel(vtkInformation* outputInformation);

/// Runs `work` (whole scene in, whole result and table out; 0 on failure, reported by
/// it) on every rank with the whole scene (the pieces gathered and broadcast), and gives
/// each rank its own piece of the result in `output`. The ranks must share the work through
/// collectives inside `work` (the solver's ProcessGroup), so every rank's `work` reaches
/// the same calls. Returns 0 on every rank when the work fails on any.
/// The whole scene a caller keeps between runs of SolveTogether: gathered again only when
/// some rank's piece changed, so work that caches on the whole's MTime stays cached.
struct GatheredScene
{
  vtkSmartPointer<vtkPolyData> Whole;
  vtkMTimeType PieceTime = 0;
  int FailedRank = -1;
};

int SolveTogether(vtkMultiProcessController* controller, vtkPolyData* piece, vtkPolyData* output, vtkTable* table,
  const std::function<int(vtkPolyData* whole, vtkPolyData* result, vtkTable* table)>& work,
  GatheredScene* kept = nullptr);

/// Every rank's `piece` (null for none) appended in rank order, on every rank, with the
/// field data of the first piece with points.
void AllGather(vtkMultiProcessController* controller, vtkPolyData* piece, vtkPolyData* whole);

/// The solver's process group for the ranks of `controller` (one process where null): its
/// sum is the controller's AllReduce.
radiosity::ProcessGroup Group(vtkMultiProcessController* controller);

/// The sum of `value` over the ranks, and the sum over the ranks before this one.
long long SumOverRanks(vtkMultiProcessController* controller, long long value, long long* before = nullptr);

/// The largest `value` of any rank.
double MaxOverRanks(vtkMultiProcessController* controller, double value);

/// Every rank's `mine`, in rank order, on every rank.
std::vector<std::string> AllGatherStrings(vtkMultiProcessController* controller, const std::vector<std::string>& mine);

}

#endif
