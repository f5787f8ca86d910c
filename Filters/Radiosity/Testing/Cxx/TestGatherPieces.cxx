// Run as `mpiexec -np 3 RadiosityParallelTests TestGatherPieces`: every rank builds a
// different piece (rank 2 none at all), gathers them raw, and checks each against the piece
// that rank built, array by array: type, name, values, active attributes, the four cell
// arrays in 32- and 64-bit storage, the field data. Then with rank 0's piece reduced to
// points (no cells), and with a string or a bit array in rank 1's cell data, which must
// send everything the general way (a bit array sent raw would overrun its buffer).
#include "vtkRadiosityGather.h"

#include "vtkBitArray.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkIdList.h"
#include "vtkIntArray.h"
#include "vtkMPIController.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkStringArray.h"
#include "vtkUnsignedCharArray.h"

#include <cstdio>
#include <string>

namespace
{

/// The piece rank `rank` holds: null for rank 2, otherwise points and cells whose values
/// say which rank made them.
enum class Extra
{
  None,
  PointsOnly,
  Strings,
  Bits
};

vtkSmartPointer<vtkPolyData> MakePiece(int rank, Extra extra)
{
  if (rank == 2)
  {
    return nullptr;
  }
  auto piece = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  points->SetDataType(rank == 0 ? VTK_DOUBLE : VTK_FLOAT);
  const int n = 5 + rank;
  for (int i = 0; i < n; ++i)
  {
    points->InsertNextPoint(i + 0.25 * rank, 0.5 * i * i, -1.0 * rank);
  }
  piece->SetPoints(points);
  vtkNew<vtkCellArray> polys, verts, lines;
  if (rank == 1)
  {
    polys->Use32BitStorage();
  }
  polys->InsertNextCell({ 0, 1, 2, 3 });
  polys->InsertNextCell({ 1, 2, 4 });
  verts->InsertNextCell({ n - 1 });
  piece->SetPolys(polys);
  piece->SetVerts(verts);
  if (rank == 0)
  {
    lines->InsertNextCell({ 0, 4 });
    piece->SetLines(lines);
  }
  vtkNew<vtkDoubleArray> radiosity;
  radiosity->SetName("Radiosity of light 0");
  radiosity->SetNumberOfComponents(3);
  for (int i = 0; i < n; ++i)
  {
    radiosity->InsertNextTuple3(i, 10.0 * rank, 1e-300 * i);
  }
  piece->GetPointData()->SetScalars(radiosity);
  vtkNew<vtkIntArray> patch;
  patch->SetName("PatchId");
  vtkNew<vtkUnsignedCharArray> unnamed; // the append drops unnamed arrays: so does the gather
  for (vtkIdType c = 0; c < piece->GetNumberOfCells(); ++c)
  {
    patch->InsertNextValue(100 * rank + static_cast<int>(c));
    unnamed->InsertNextValue(7);
  }
  piece->GetCellData()->AddArray(patch);
  piece->GetCellData()->AddArray(unnamed);
  vtkNew<vtkStringArray> names;
  names->SetName("LightNames");
  names->InsertNextValue("lamp of rank " + std::to_string(rank));
  piece->GetFieldData()->AddArray(names);
  if (extra == Extra::Strings && rank == 1)
  {
    vtkNew<vtkStringArray> labels;
    labels->SetName("Label");
    for (vtkIdType c = 0; c < piece->GetNumberOfCells(); ++c)
    {
      labels->InsertNextValue("cell " + std::to_string(c));
    }
    piece->GetCellData()->AddArray(labels);
  }
  if (extra == Extra::Bits && rank == 1)
  {
    vtkNew<vtkBitArray> flags;
    flags->SetName("Flag");
    for (vtkIdType c = 0; c < piece->GetNumberOfCells(); ++c)
    {
      flags->InsertNextValue(static_cast<int>(c % 2));
    }
    piece->GetCellData()->AddArray(flags);
  }
  if (extra == Extra::PointsOnly && rank == 0)
  {
    piece->SetPolys(nullptr);
    piece->SetVerts(nullptr);
    piece->SetLines(nullptr);
    piece->GetCellData()->Initialize();
  }
  return piece;
}

int failures = 0;

void Expect(bool ok, int rank, int from, const char* what)
{
  if (!ok)
  {
    std::fprintf(stderr, "rank %d, piece of rank %d: %s\n", rank, from, what);
    ++failures;
  }
}

bool SameCells(vtkCellArray* a, vtkCellArray* b)
{
  if (a->GetNumberOfCells() != b->GetNumberOfCells())
  {
    return false;
  }
  vtkNew<vtkIdList> x, y;
  for (vtkIdType c = 0; c < a->GetNumberOfCells(); ++c)
  {
    a->GetCellAtId(c, x);
    b->GetCellAtId(c, y);
    if (x->GetNumberOfIds() != y->GetNumberOfIds())
    {
      return false;
    }
    for (vtkIdType i = 0; i < x->GetNumberOfIds(); ++i)
    {
      if (x->GetId(i) != y->GetId(i))
      {
        return false;
      }
    }
  }
  return true;
}

bool SameArray(vtkDataArray* a, vtkDataArray* b)
{
  if (!a || !b || a->GetDataType() != b->GetDataType() || a->GetNumberOfTuples() != b->GetNumberOfTuples() ||
    a->GetNumberOfComponents() != b->GetNumberOfComponents())
  {
    return false;
  }
  for (vtkIdType i = 0; i < a->GetNumberOfValues(); ++i)
  {
    if (a->GetComponent(i / a->GetNumberOfComponents(), static_cast<int>(i % a->GetNumberOfComponents())) !=
      b->GetComponent(i / a->GetNumberOfComponents(), static_cast<int>(i % a->GetNumberOfComponents())))
    {
      return false;
    }
  }
  return true;
}

void Compare(vtkPolyData* got, vtkPolyData* want, int rank, int from, bool raw)
{
  if (!want)
  {
    Expect(!got || got->GetNumberOfPoints() == 0, rank, from, "an empty piece arrived with points");
    return;
  }
  Expect(got != nullptr, rank, from, "no piece");
  if (!got)
  {
    return;
  }
  Expect(got->GetPoints() && SameArray(got->GetPoints()->GetData(), want->GetPoints()->GetData()), rank, from,
    "points differ");
  if (!got->GetPoints())
  {
    return;
  }
  Expect(SameCells(got->GetPolys(), want->GetPolys()), rank, from, "polygons differ");
  Expect(SameCells(got->GetVerts(), want->GetVerts()), rank, from, "vertices differ");
  Expect(SameCells(got->GetLines(), want->GetLines()), rank, from, "lines differ");
  Expect(got->GetStrips()->GetNumberOfCells() == 0, rank, from, "strips appeared");
  Expect(SameArray(got->GetPointData()->GetScalars(), want->GetPointData()->GetScalars()), rank, from,
    "the active scalars differ");
  if (want->GetNumberOfCells() > 0)
  {
    Expect(SameArray(got->GetCellData()->GetArray("PatchId"), want->GetCellData()->GetArray("PatchId")), rank,
      from, "PatchId differs");
  }
  if (raw && from != rank && want->GetNumberOfCells() > 0) // a rank's own entry is its piece itself
  {
    Expect(got->GetCellData()->GetNumberOfArrays() == 1, rank, from, "unexpected cell arrays");
  }
  auto* names = vtkStringArray::SafeDownCast(got->GetFieldData()->GetAbstractArray("LightNames"));
  Expect(names && names->GetValue(0) == "lamp of rank " + std::to_string(from), rank, from, "LightNames differ");
  if (!raw && from == 1)
  {
    Expect(got->GetCellData()->GetAbstractArray("Label") != nullptr ||
        SameArray(got->GetCellData()->GetArray("Flag"), want->GetCellData()->GetArray("Flag")),
      rank, from, "the string or bit array was lost");
  }
}

void Round(vtkMPIController* controller, Extra extra)
{
  const int rank = controller->GetLocalProcessId();
  vtkSmartPointer<vtkPolyData> mine = MakePiece(rank, extra);
  std::vector<vtkSmartPointer<vtkPolyData>> pieces;
  const bool raw = vtkRadiosityGather::AllGatherPieces(controller, mine, pieces);
  const bool general = extra == Extra::Strings || extra == Extra::Bits;
  Expect(raw != general, rank, rank, general ? "a string or bit array went raw" : "plain arrays did not go raw");
  Expect(static_cast<int>(pieces.size()) == controller->GetNumberOfProcesses(), rank, rank, "wrong count");
  for (int from = 0; from < static_cast<int>(pieces.size()); ++from)
  {
    vtkSmartPointer<vtkPolyData> want = MakePiece(from, extra);
    Compare(pieces[from], want, rank, from, raw);
  }
}

} // namespace

int TestGatherPieces(int argc, char* argv[])
{
  vtkNew<vtkMPIController> controller;
  controller->Initialize(&argc, &argv);
  if (controller->GetNumberOfProcesses() != 3)
  {
    std::fprintf(stderr, "run on 3 ranks\n");
    controller->Finalize();
    return 1;
  }
  for (Extra extra : { Extra::None, Extra::PointsOnly, Extra::Strings, Extra::Bits })
  {
    Round(controller, extra);
  }
  int mine = failures, all = 0;
  controller->AllReduce(&mine, &all, 1, vtkCommunicator::SUM_OP);
  controller->Finalize();
  return all == 0 ? 0 : 1;
}
