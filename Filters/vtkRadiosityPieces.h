// The filters on ParaView's MPI server: every rank holds a piece of the scene. The solver
// sees the whole scene (gathered on rank 0) and each rank gets its own piece of the
// result; the mesher numbers patches across ranks. Not wrapped.
#ifndef vtkRadiosityPieces_h
#define vtkRadiosityPieces_h

#include "vtkSmartPointer.h"
#include "vtkType.h"

#include <functional>

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
/// it) on rank 0 with every rank's piece gathered there, and gives each rank its own
/// piece of the result in `output` and a copy of the table in `table`. One rank works, so
/// a time budget or an abort stops all alike. Returns 0 on every rank when the work fails.
int SolveOnRoot(vtkMultiProcessController* controller, vtkPolyData* piece, vtkPolyData* output, vtkTable* table,
  const std::function<int(vtkPolyData* whole, vtkPolyData* result, vtkTable* table)>& work);

/// The sum of `value` over the ranks, and the sum over the ranks before this one.
long long SumOverRanks(vtkMultiProcessController* controller, long long value, long long* before = nullptr);

}

#endif
