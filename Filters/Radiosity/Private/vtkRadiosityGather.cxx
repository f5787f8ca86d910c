#include "vtkRadiosityGather.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkLogger.h"
#include "vtkMultiProcessController.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <cstdlib>
#include <sstream>
#include <string>

namespace vtkRadiosityGather
{
namespace
{

/// One array a piece sends: where it goes, its type and shape.
struct ArrayEntry
{
  char Kind = 'P'; ///< P points, O/C offsets/connectivity of cell array Slot, D/E point/cell data
  int Slot = 0;
  int Type = 0;
  int Components = 1;
  int Active = 0; ///< bit t: the active attribute of type t (scalars, normals...)
  std::string Name;
};

/// A collective that failed on one rank leaves the others waiting in the next: ending the
/// job with the reason beats a hang.
[[noreturn]] void Fail(const std::string& why)
{
  vtkLogF(ERROR, "Gathering the scene's pieces failed: %s; ending the MPI job.", why.c_str());
  std::abort();
}

vtkCellArray* CellArray(vtkPolyData* data, int slot)
{
  switch (slot)
  {
    case 0:
      return data->GetVerts();
    case 1:
      return data->GetLines();
    case 2:
      return data->GetPolys();
    default:
      return data->GetStrips();
  }
}

void SetCellArray(vtkPolyData* data, int slot, vtkCellArray* cells)
{
  switch (slot)
  {
    case 0:
      data->SetVerts(cells);
      break;
    case 1:
      data->SetLines(cells);
      break;
    case 2:
      data->SetPolys(cells);
      break;
    default:
      data->SetStrips(cells);
  }
}

/// The arrays of `piece` in the order they are sent, or false where one cannot be sent raw
/// (a string array among the point or cell data, a bit array or one not laid out as one
/// block, a name with a line break).
bool ListArrays(vtkPolyData* piece, std::vector<vtkDataArray*>& arrays, std::vector<ArrayEntry>& entries)
{
  bool plain = true; // every array one block of memory of a type MPI can send
  auto add = [&](vtkDataArray* array, char kind, int slot, int active = 0) {
    plain = plain && array->HasStandardMemoryLayout() && array->GetDataType() != VTK_BIT;
    arrays.push_back(array);
    entries.push_back({ kind, slot, array->GetDataType(), array->GetNumberOfComponents(), active,
      array->GetName() ? array->GetName() : "" });
  };
  if (!piece || piece->GetNumberOfPoints() == 0)
  {
    return true;
  }
  add(piece->GetPoints()->GetData(), 'P', 0);
  for (int slot = 0; slot < 4; ++slot)
  {
    vtkCellArray* cells = CellArray(piece, slot);
    if (cells && cells->GetNumberOfCells() > 0)
    {
      add(cells->GetOffsetsArray(), 'O', slot);
      add(cells->GetConnectivityArray(), 'C', slot);
    }
  }
  for (char kind : { 'D', 'E' })
  {
    vtkDataSetAttributes* attributes = kind == 'D' ? static_cast<vtkDataSetAttributes*>(piece->GetPointData())
                                                   : static_cast<vtkDataSetAttributes*>(piece->GetCellData());
    for (int a = 0; a < attributes->GetNumberOfArrays(); ++a)
    {
      vtkAbstractArray* abstract = attributes->GetAbstractArray(a);
      vtkDataArray* array = vtkDataArray::SafeDownCast(abstract);
      if (!abstract->GetName())
      {
        continue; // the append drops unnamed arrays too
      }
      if (!array || std::string(abstract->GetName()).find('\n') != std::string::npos)
      {
        return false;
      }
      int active = 0;
      for (int type = 0; type < vtkDataSetAttributes::NUM_ATTRIBUTES; ++type)
      {
        active |= attributes->GetAbstractAttribute(type) == abstract ? 1 << type : 0;
      }
      add(array, kind, 0, active);
    }
  }
  return plain;
}

std::string Describe(const std::vector<ArrayEntry>& entries)
{
  std::ostringstream text;
  for (const ArrayEntry& e : entries)
  {
    text << e.Kind << ' ' << e.Slot << ' ' << e.Type << ' ' << e.Components << ' ' << e.Active << ' ' << e.Name << '\n';
  }
  return text.str();
}

std::vector<ArrayEntry> Parse(const std::string& text)
{
  std::vector<ArrayEntry> entries;
  std::istringstream lines(text);
  std::string line;
  while (std::getline(lines, line))
  {
    std::istringstream fields(line);
    ArrayEntry e;
    fields >> e.Kind >> e.Slot >> e.Type >> e.Components >> e.Active;
    fields.get(); // the space before the name, which may itself contain spaces
    std::getline(fields, e.Name);
    entries.push_back(e);
  }
  return entries;
}

/// Every rank's description of its arrays.
std::vector<std::string> AllDescriptions(vtkMultiProcessController* controller, const std::string& mine)
{
  const int ranks = controller->GetNumberOfProcesses();
  const long long length = static_cast<long long>(mine.size());
  std::vector<long long> lengths(ranks, 0);
  controller->AllGather(&length, lengths.data(), 1);
  std::vector<vtkIdType> counts(ranks), offsets(ranks);
  vtkIdType total = 0;
  for (int r = 0; r < ranks; ++r)
  {
    counts[r] = static_cast<vtkIdType>(lengths[r]);
    offsets[r] = total;
    total += counts[r];
  }
  std::string all(static_cast<size_t>(total), '\0');
  controller->AllGatherV(mine.data(), &all[0], static_cast<vtkIdType>(mine.size()), counts.data(), offsets.data());
  std::vector<std::string> descriptions;
  for (int r = 0; r < ranks; ++r)
  {
    descriptions.push_back(all.substr(static_cast<size_t>(offsets[r]), static_cast<size_t>(counts[r])));
  }
  return descriptions;
}

/// Rank `source`'s piece rebuilt from its broadcast arrays, with `header`'s field data.
vtkSmartPointer<vtkPolyData> Receive(
  vtkMultiProcessController* controller, int source, const std::vector<ArrayEntry>& entries, vtkPolyData* header)
{
  auto piece = vtkSmartPointer<vtkPolyData>::New();
  if (header)
  {
    piece->GetFieldData()->ShallowCopy(header->GetFieldData());
  }
  vtkSmartPointer<vtkDataArray> offsets;
  for (const ArrayEntry& e : entries)
  {
    vtkSmartPointer<vtkDataArray> array = vtk::TakeSmartPointer(vtkDataArray::CreateDataArray(e.Type));
    if (!array)
    {
      Fail("rank " + std::to_string(source) + " sent an array of unknown type " + std::to_string(e.Type));
    }
    array->SetNumberOfComponents(e.Components);
    if (!controller->Broadcast(array, source))
    {
      Fail("the array '" + e.Name + "' of rank " + std::to_string(source) + " did not arrive");
    }
    array->SetName(e.Name.empty() ? nullptr : e.Name.c_str());
    if (e.Kind == 'P')
    {
      vtkNew<vtkPoints> points;
      points->SetData(array);
      piece->SetPoints(points);
    }
    else if (e.Kind == 'O')
    {
      offsets = array;
    }
    else if (e.Kind == 'C')
    {
      vtkNew<vtkCellArray> cells;
      if (!offsets || !cells->SetData(offsets, array))
      {
        Fail("the cells of rank " + std::to_string(source) + " could not be rebuilt");
      }
      SetCellArray(piece, e.Slot, cells);
    }
    else
    {
      vtkDataSetAttributes* attributes = e.Kind == 'D' ? static_cast<vtkDataSetAttributes*>(piece->GetPointData())
                                                       : static_cast<vtkDataSetAttributes*>(piece->GetCellData());
      attributes->AddArray(array);
      for (int type = 0; type < vtkDataSetAttributes::NUM_ATTRIBUTES; ++type)
      {
        if (e.Active & (1 << type))
        {
          attributes->SetActiveAttribute(e.Name.c_str(), type);
        }
      }
    }
  }
  return piece;
}

} // namespace

bool AllGatherPieces(
  vtkMultiProcessController* controller, vtkPolyData* piece, std::vector<vtkSmartPointer<vtkPolyData>>& pieces)
{
  std::vector<vtkDataArray*> arrays;
  std::vector<ArrayEntry> entries;
  const bool raw = ListArrays(piece, arrays, entries);
  // "!" marks a piece that cannot go raw; then every rank falls back to VTK's gather.
  const std::vector<std::string> descriptions = AllDescriptions(controller, raw ? Describe(entries) : "!");
  bool allRaw = true;
  for (const std::string& d : descriptions)
  {
    allRaw = allRaw && d != "!";
  }
  // The field data (light names, the failure mark) is small and holds strings: it goes
  // the general way, in a piece without points.
  vtkNew<vtkPolyData> header;
  if (piece)
  {
    header->GetFieldData()->ShallowCopy(piece->GetFieldData());
  }
  std::vector<vtkSmartPointer<vtkDataObject>> objects;
  controller->AllGather(allRaw ? header.Get() : (piece ? static_cast<vtkDataObject*>(piece) : header.Get()), objects);
  const int me = controller->GetLocalProcessId();
  pieces.assign(descriptions.size(), nullptr);
  for (int r = 0; r < static_cast<int>(descriptions.size()); ++r)
  {
    auto* gathered = vtkPolyData::SafeDownCast(r < static_cast<int>(objects.size()) ? objects[r] : nullptr);
    if (!allRaw)
    {
      pieces[r] = r == me && piece ? piece : gathered;
    }
    else if (r == me)
    {
      for (vtkDataArray* array : arrays)
      {
        if (!controller->Broadcast(array, me))
        {
          Fail("could not send the array '" + std::string(array->GetName() ? array->GetName() : "") + "'");
        }
      }
      pieces[r] = piece ? piece : gathered;
    }
    else
    {
      pieces[r] = Receive(controller, r, Parse(descriptions[r]), gathered);
    }
  }
  return allRaw;
}

}
