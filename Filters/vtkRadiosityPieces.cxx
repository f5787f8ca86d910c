#include "vtkRadiosityPieces.h"

#include "vtkAppendPolyData.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkInformation.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkMultiProcessController.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"

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

vtkSmartPointer<vtkPolyData> GatherAll(vtkMultiProcessController* controller, vtkPolyData* piece, Slice& slice)
{
  std::vector<vtkSmartPointer<vtkDataObject>> pieces;
  controller->AllGather(piece, pieces);
  vtkNew<vtkAppendPolyData> append;
  auto whole = vtkSmartPointer<vtkPolyData>::New();
  vtkPolyData* first = nullptr;
  const int me = controller->GetLocalProcessId();
  for (int rank = 0; rank < static_cast<int>(pieces.size()); ++rank)
  {
    auto* data = vtkPolyData::SafeDownCast(pieces[rank]);
    if (!data || data->GetNumberOfCells() == 0)
    {
      continue;
    }
    first = first ? first : data;
    append->AddInputData(data);
  }
  // Offsets: the cells and points of the non-empty pieces before this rank's.
  slice.FirstCell = 0;
  slice.FirstPoint = 0;
  for (int rank = 0; rank < me && rank < static_cast<int>(pieces.size()); ++rank)
  {
    if (auto* data = vtkPolyData::SafeDownCast(pieces[rank]))
    {
      slice.FirstCell += data->GetNumberOfCells();
      slice.FirstPoint += data->GetNumberOfCells() ? data->GetNumberOfPoints() : 0; // empty pieces add no points
    }
  }
  if (!first)
  {
    return whole;
  }
  append->Update();
  whole->ShallowCopy(append->GetOutput());
  whole->SetFieldData(first->GetFieldData());
  return whole;
}

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
