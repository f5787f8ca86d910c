#include "vtkRadiosityPieces.h"
#include "vtkRadiosityAdapter.h"

#include "vtkAppendPolyData.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkInformation.h"
#include "vtkLogger.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkMultiProcessController.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkTable.h"

#include <string>
#include <vector>

namespace vtkRadiosityPieces
{
namespace
{

/// Sets every named array of `whole` on `target`, tuples [first, first + count).
void CutArrays(vtkDataSetAttributes* whole, vtkIdType first, vtkIdType count, vtkDataSetAttributes* target)
{
  for (int a = 0; a < whole->GetNumberOfArrays(); ++a)
  {
    vtkAbstractArray* array = whole->GetAbstractArray(a);
    if (!array || !array->GetName())
    {
      continue;
    }
    vtkSmartPointer<vtkAbstractArray> part = vtk::TakeSmartPointer(array->NewInstance());
    part->SetName(array->GetName());
    part->SetNumberOfComponents(array->GetNumberOfComponents());
    part->SetNumberOfTuples(count);
    for (vtkIdType t = 0; t < count; ++t)
    {
      part->SetTuple(t, first + t, array);
    }
    target->AddArray(part);
  }
}

/// Where one rank's piece lies in the whole scene.
struct Slice
{
  vtkIdType FirstCell = 0;
  vtkIdType FirstPoint = 0;
};

/// A rank's piece of a result computed on the whole scene: the rank's input with every
/// point and cell array of `whole` cut to its slice (the whole's win, e.g. PatchId
/// renumbered by the solver), and the whole's field data.
void CutPiece(vtkPolyData* whole, const Slice& slice, vtkPolyData* piece, vtkPolyData* output)
{
  output->ShallowCopy(piece);
  if (piece->GetNumberOfCells() > 0)
  {
    CutArrays(whole->GetCellData(), slice.FirstCell, piece->GetNumberOfCells(), output->GetCellData());
    CutArrays(whole->GetPointData(), slice.FirstPoint, piece->GetNumberOfPoints(), output->GetPointData());
  }
  vtkNew<vtkFieldData> fields;
  fields->ShallowCopy(whole->GetFieldData());
  output->SetFieldData(fields);
}

} // namespace

vtkMultiProcessController* Parallel(vtkInformation* outputInformation)
{
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  const int processes = controller ? controller->GetNumberOfProcesses() : 1;
  const int pieces = outputInformation && outputInformation->Has(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES())
    ? outputInformation->Get(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES())
    : 1;
  return processes > 1 && pieces == processes ? controller : nullptr;
}

int SolveOnRoot(vtkMultiProcessController* controller, vtkPolyData* piece, vtkPolyData* output, vtkTable* table,
  const std::function<int(vtkPolyData* whole, vtkPolyData* result, vtkTable* table)>& work)
{
  constexpr int ResultTag = 7841, TableTag = 7842;
  const int me = controller->GetLocalProcessId();
  std::vector<vtkSmartPointer<vtkDataObject>> pieces;
  controller->Gather(piece, pieces, 0);
  int ok = 0;
  if (me == 0)
  {
    // The whole scene: the pieces with cells, appended in rank order; the field data of
    // the first of them. Each rank's slice starts after the cells and points before it.
    vtkNew<vtkAppendPolyData> append;
    std::vector<Slice> slices(pieces.size());
    Slice next;
    vtkPolyData* first = nullptr;
    for (size_t rank = 0; rank < pieces.size(); ++rank)
    {
      auto* data = vtkPolyData::SafeDownCast(pieces[rank]);
      slices[rank] = next;
      if (data && data->GetNumberOfCells() > 0)
      {
        append->AddInputData(data);
        first = first ? first : data;
        next.FirstCell += data->GetNumberOfCells();
        next.FirstPoint += data->GetNumberOfPoints();
      }
    }
    vtkNew<vtkPolyData> whole, solved;
    if (first)
    {
      append->Update();
      whole->ShallowCopy(append->GetOutput());
      whole->SetFieldData(first->GetFieldData());
    }
    // A piece that failed upstream fails the whole solve (that filter said why); an
    // exception on rank 0 must not skip the sends the other ranks wait for.
    int failedRank = -1;
    for (size_t rank = 0; rank < pieces.size() && failedRank < 0; ++rank)
    {
      failedRank = vtkRadiosityAdapter::FailedUpstream(pieces[rank]) ? static_cast<int>(rank) : -1;
    }
    bool worked = false;
    std::string error = failedRank >= 0 ? std::string() : vtkRadiosityAdapter::Caught([&]() {
      worked = work(whole, solved, table) != 0; // a failing work reports its own error
      return std::string();
    });
    error = failedRank > 0 ? "the piece of rank " + std::to_string(failedRank) + " failed upstream" : error;
    ok = worked;
    if (!error.empty())
    {
      vtkLogF(ERROR, "Cannot solve: %s.", error.c_str());
    }
    unsigned long gathered = 0, sent = 0; // KiB, for the log: what a run costs in traffic
    for (const auto& received : pieces)
    {
      gathered += received ? received->GetActualMemorySize() : 0;
    }
    for (int rank = static_cast<int>(pieces.size()) - 1; rank >= 0; --rank)
    {
      auto* data = vtkPolyData::SafeDownCast(pieces[rank]);
      vtkNew<vtkPolyData> cut;
      if (ok && data)
      {
        CutPiece(solved, slices[rank], data, cut);
      }
      if (rank == 0)
      {
        output->ShallowCopy(cut);
      }
      else
      {
        controller->Send(cut, rank, ResultTag);
        controller->Send(table, rank, TableTag);
        sent += cut->GetActualMemorySize();
      }
    }
    vtkLogF(INFO, "Radiosity on %d ranks: %.2f MB of scene gathered on rank 0, %.2f MB of results sent",
      static_cast<int>(pieces.size()), gathered / 1024.0, sent / 1024.0);
  }
  else
  {
    controller->Receive(output, 0, ResultTag);
    controller->Receive(table, 0, TableTag);
  }
  controller->Broadcast(&ok, 1, 0);
  return ok;
}

long long SumOverRanks(vtkMultiProcessController* controller, long long value, long long* before)
{
  std::vector<long long> all(controller->GetNumberOfProcesses(), 0);
  controller->AllGather(&value, all.data(), 1);
  long long sum = 0;
  for (int rank = 0; rank < static_cast<int>(all.size()); ++rank)
  {
    if (before && rank == controller->GetLocalProcessId())
    {
      *before = sum;
    }
    sum += all[rank];
  }
  return sum;
}

}
