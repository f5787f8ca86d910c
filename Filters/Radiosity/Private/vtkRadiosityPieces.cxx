#include "vtkRadiosityPieces.h"
#include "vtkRadiosityAdapter.h"

#include "vtkRadiosityAppendPieces.h"
#include "vtkRadiosityGather.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkInformation.h"
#include "vtkCommunicator.h"
#include "vtkLogger.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkMultiProcessController.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkTable.h"

#include <cstdlib>
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
    part->InsertTuples(0, count, first, array);
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
  for (int type = 0; type < vtkDataSetAttributes::NUM_ATTRIBUTES; ++type)
  {
    // Coloring follows the whole's active arrays (the relight filter's DisplayColors).
    vtkAbstractArray* point = whole->GetPointData()->GetAbstractAttribute(type);
    vtkAbstractArray* cell = whole->GetCellData()->GetAbstractAttribute(type);
    if (point && point->GetName() && piece->GetNumberOfCells() > 0)
    {
      output->GetPointData()->SetActiveAttribute(point->GetName(), type);
    }
    if (cell && cell->GetName() && piece->GetNumberOfCells() > 0)
    {
      output->GetCellData()->SetActiveAttribute(cell->GetName(), type);
    }
  }
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

namespace
{
/// The whole on every rank: the pieces with cells (`byCells`) or points appended in rank
/// order, with the field data of the first of them. Empty where none has any. `failedRank`:
/// the first rank whose piece failed upstream, else -1.
void GatherWhole(vtkMultiProcessController* controller, vtkPolyData* piece, vtkPolyData* whole, int& failedRank,
  bool byCells = true)
{
  std::vector<vtkSmartPointer<vtkPolyData>> pieces;
  vtkRadiosityGather::AllGatherPieces(controller, piece, pieces);
  failedRank = -1;
  vtkNew<vtkRadiosityAppendPieces> append;
  for (size_t rank = 0; rank < pieces.size(); ++rank)
  {
    vtkPolyData* data = pieces[rank];
    if (failedRank < 0 && vtkRadiosityAdapter::FailedUpstream(pieces[rank]))
    {
      failedRank = static_cast<int>(rank);
    }
    if (data && (byCells ? data->GetNumberOfCells() : data->GetNumberOfPoints()) > 0)
    {
      append->AddInputData(data);
    }
  }
  if (append->GetNumberOfInputConnections(0) > 0)
  {
    append->Update();
    whole->ShallowCopy(append->GetOutput());
  }
}
} // namespace

int SolveTogether(vtkMultiProcessController* controller, vtkPolyData* piece, vtkPolyData* output, vtkTable* table,
  const std::function<int(vtkPolyData* whole, vtkPolyData* result, vtkTable* table)>& work, GatheredScene* kept)
{
  const bool cells = piece->GetNumberOfCells() > 0;
  Slice slice; // where this rank's cells and points lie in the appended whole
  SumOverRanks(controller, cells ? piece->GetNumberOfCells() : 0, &slice.FirstCell);
  SumOverRanks(controller, cells ? piece->GetNumberOfPoints() : 0, &slice.FirstPoint);
  vtkNew<vtkPolyData> solved;
  vtkSmartPointer<vtkPolyData> whole = kept ? kept->Whole : nullptr;
  int failedRank = kept ? kept->FailedRank : -1;
  int stale = !whole || kept->PieceTime != piece->GetMTime() ? 1 : 0, anyStale = 1;
  controller->AllReduce(&stale, &anyStale, 1, vtkCommunicator::MAX_OP);
  if (anyStale)
  {
    whole = vtkSmartPointer<vtkPolyData>::New();
    vtkLogScopeF(TRACE, "gather the whole scene");
    GatherWhole(controller, piece, whole, failedRank);
    if (kept)
    {
      *kept = GatheredScene{ whole, piece->GetMTime(), failedRank };
    }
  }
  // Every rank sees the same whole scene, so they all pass or fail the same checks; a piece
  // that failed upstream fails them all (that filter said why).
  int ok = 0;
  std::string error = failedRank >= 0 ? "the piece of rank " + std::to_string(failedRank) + " failed upstream" : "";
  if (error.empty())
  {
    error = vtkRadiosityAdapter::Caught([&]() {
      ok = work(whole, solved, table);
      return std::string();
    });
    if (!error.empty())
    {
      // Thrown part-way (out of memory, say): the other ranks wait in a sum this rank will
      // never join. Ending the job with the reason beats leaving it hanging.
      vtkLogF(ERROR, "Rank %d failed inside the shared solve (%s); ending the MPI job.",
        controller->GetLocalProcessId(), error.c_str());
      std::abort();
    }
  }
  if (!error.empty() && failedRank != 0)
  {
    vtkLogF(ERROR, "Cannot solve: %s.", error.c_str());
  }
  int all = 0;
  controller->AllReduce(&ok, &all, 1, vtkCommunicator::MIN_OP);
  if (all)
  {
    vtkLogScopeF(TRACE, "cut this rank's piece");
    CutPiece(solved, slice, piece, output);
  }
  if (controller->GetLocalProcessId() == 0)
  {
    vtkLogF(INFO, "Radiosity on %d ranks: %.2f MB of scene on every rank", controller->GetNumberOfProcesses(),
      whole->GetActualMemorySize() / 1024.0);
  }
  return all;
}

void AllGather(vtkMultiProcessController* controller, vtkPolyData* piece, vtkPolyData* whole)
{
  int failedRank = -1;
  GatherWhole(controller, piece, whole, failedRank, false);
}

radiosity::ProcessGroup Group(vtkMultiProcessController* controller)
{
  radiosity::ProcessGroup group;
  if (!controller || controller->GetNumberOfProcesses() < 2)
  {
    return group;
  }
  group.Rank = controller->GetLocalProcessId();
  group.Ranks = controller->GetNumberOfProcesses();
  group.SumAll = [controller](double* values, std::size_t count) {
    const std::vector<double> mine(values, values + count); // MPI sends and receives apart
    controller->AllReduce(mine.data(), values, static_cast<vtkIdType>(count), vtkCommunicator::SUM_OP);
  };
  return group;
}

double MaxOverRanks(vtkMultiProcessController* controller, double value)
{
  double largest = value;
  controller->AllReduce(&value, &largest, 1, vtkCommunicator::MAX_OP);
  return largest;
}

std::vector<std::string> AllGatherStrings(vtkMultiProcessController* controller, const std::vector<std::string>& mine)
{
  std::vector<char> sent; // each string ended by a zero
  for (const std::string& text : mine)
  {
    sent.insert(sent.end(), text.begin(), text.end());
    sent.push_back('\0');
  }
  const int ranks = controller->GetNumberOfProcesses();
  std::vector<vtkIdType> lengths(ranks, 0), offsets(ranks, 0);
  const vtkIdType length = static_cast<vtkIdType>(sent.size());
  controller->AllGather(&length, lengths.data(), 1);
  for (int rank = 1; rank < ranks; ++rank)
  {
    offsets[rank] = offsets[rank - 1] + lengths[rank - 1];
  }
  std::vector<char> received(static_cast<size_t>(offsets.back() + lengths.back()) + 1, '\0');
  controller->AllGatherV(sent.data(), received.data(), length, lengths.data(), offsets.data());
  std::vector<std::string> all;
  for (size_t at = 0; at + 1 < received.size(); at += all.back().size() + 1)
  {
    all.emplace_back(received.data() + at);
  }
  return all;
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
