// The filters on ParaView's MPI server: every rank holds a piece of the scene. The solver
// sees the whole scene (gathered on every rank) and each rank keeps its own piece of the
// result; the mesher numbers patches across ranks. Not wrapped.
#ifndef vtkRadiosityPieces_h
#define vtkRadiosityPieces_h

#include "vtkSmartPointer.h"
#include "vtkType.h"

class vtkInformation;
class vtkMultiProcessController;
class vtkPolyData;

namespace vtkRadiosityPieces
{

/// The global controller when this execution is one piece of a distributed pipeline (as
/// on ParaView's MPI server: as many pieces requested as there are processes), else null.
/// A plain VTK pipeline in one process of an MPI job asks for one piece and works alone:
/// collectives there would wait for ranks that never come.
vtkMultiProcessController* Parallel(vtkInformation* outputInformation);

/// Where this rank's piece lies in the whole scene (GatherAll's order).
struct Slice
{
  vtkIdType FirstCell = 0;
  vtkIdType FirstPoint = 0;
};

/// Every rank's piece appended in rank order, the same on every rank (empty pieces are
/// left out; the field data is that of the first piece with cells). `slice` tells where
/// this rank's cells and points are in it.
vtkSmartPointer<vtkPolyData> GatherAll(vtkMultiProcessController* controller, vtkPolyData* piece, Slice& slice);

/// This rank's piece of a result computed on the whole scene: `piece` (this rank's input)
/// with every point and cell array of `whole` cut to its slice (the whole's win over the
/// piece's, e.g. PatchId renumbered by the solver), and `whole`'s field data.
void CutPiece(vtkPolyData* whole, const Slice& slice, vtkPolyData* piece, vtkPolyData* output);

/// The sum of `value` over the ranks, and the sum over the ranks before this one.
long long SumOverRanks(vtkMultiProcessController* controller, long long value, long long* before = nullptr);

}

#endif
