#include "vtkRadiosityPreparedScenes.h"
#include "vtkRadiosityAdapter.h"

#include "vtkCallbackCommand.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkFieldData.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkWeakPointer.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <mutex>
#include <set>
#include <vector>

namespace vtkRadiosityPreparedScenes
{
namespace
{

constexpr size_t MaximumKeys = 4;

/// 64-bit hash of raw bytes, eight at a time (splitmix64's mixer per word).
std::uint64_t HashBytes(const void* data, size_t bytes, std::uint64_t h)
{
  auto mix = [](std::uint64_t x) {
    x ^= x >> 30;
    x *= 0xbf58476d1ce4e5b9ULL;
    x ^= x >> 27;
    x *= 0x94d049bb133111ebULL;
    return x ^ (x >> 31);
  };
  const auto* p = static_cast<const unsigned char*>(data);
  size_t i = 0;
  for (; i + 8 <= bytes; i += 8)
  {
    std::uint64_t word;
    std::memcpy(&word, p + i, 8);
    h = mix(h ^ word) + 0x9e3779b97f4a7c15ULL;
  }
  std::uint64_t last = bytes;
  std::memcpy(&last, p + i, bytes - i);
  return mix(h ^ last);
}

/// An array's values hashed with its type and shape; through its tuples where its memory
/// is not one plain block.
std::uint64_t HashArray(vtkDataArray* array, std::uint64_t h)
{
  if (!array)
  {
    return HashBytes("none", 4, h);
  }
  const long long shape[3] = { array->GetDataType(), array->GetNumberOfComponents(), array->GetNumberOfTuples() };
  h = HashBytes(shape, sizeof(shape), h);
  if (array->HasStandardMemoryLayout() && array->GetDataType() != VTK_BIT)
  {
    return HashBytes(array->GetVoidPointer(0),
      static_cast<size_t>(array->GetNumberOfValues()) * static_cast<size_t>(array->GetDataTypeSize()), h);
  }
  std::vector<double> tuple(array->GetNumberOfComponents());
  for (vtkIdType t = 0; t < array->GetNumberOfTuples(); ++t)
  {
    array->GetTuple(t, tuple.data());
    h = HashBytes(tuple.data(), tuple.size() * sizeof(double), h);
  }
  return h;
}

struct Entry
{
  vtkWeakPointer<vtkPoints> Owner; ///< the points it was kept for: it goes with them
  MeshKey From;
  radiosity::PreparedScene Scene;
};

/// Most recently used first. Never destroyed: the observers below may fire while the
/// process exits, after static objects are gone.
struct Store
{
  std::mutex Lock;
  std::vector<Entry> Entries;
  vtkNew<vtkCallbackCommand> OnDelete;
};

Store& Kept()
{
  static Store* store = new Store;
  return *store;
}

/// Drops the entries whose points are gone or are `points` (being deleted), and those kept
/// for `points` whose mesh is no longer `now` (edited since: they would never match again,
/// and a new preparation is about to be built beside them).
void Drop(std::vector<Entry>& entries, vtkObject* points, const MeshKey* now = nullptr)
{
  entries.erase(std::remove_if(entries.begin(), entries.end(),
                  [&](const Entry& e) {
                    const bool mine = e.Owner.GetPointer() == points;
                    return !e.Owner || (mine && (!now || e.From.Mesh != now->Mesh));
                  }),
    entries.end());
}

/// A mesh's points are being deleted: its scenes go now, not at the next filter's call.
/// (Weak pointers to it still read it until its destructor runs.)
void PointsDeleted(vtkObject* points, unsigned long, void*, void*)
{
  Store& store = Kept();
  std::lock_guard<std::mutex> hold(store.Lock);
  Drop(store.Entries, points);
}

} // namespace

MeshKey KeyOf(vtkPolyData* data)
{
  MeshKey key;
  vtkCellArray* polygons = data->GetPolys();
  key.Mesh = HashArray(data->GetPoints() ? data->GetPoints()->GetData() : nullptr, 1);
  key.Mesh = HashArray(polygons ? polygons->GetOffsetsArray() : nullptr, key.Mesh);
  key.Mesh = HashArray(polygons ? polygons->GetConnectivityArray() : nullptr, key.Mesh);
  // The points' precision sets what counts as touching (MarkEnclosed), a part of the preparation.
  key.Mesh = HashArray(data->GetFieldData()->GetArray(vtkRadiosityAdapter::PointQuantumName), key.Mesh);
  return WithPatchesOf(key, data);
}

MeshKey WithPatchesOf(MeshKey key, vtkPolyData* data)
{
  key.Patches = HashArray(data->GetCellData()->GetArray("PatchId"), 2);
  return key;
}

radiosity::PreparedScene Find(vtkPolyData* data, const MeshKey& now, bool transport)
{
  Store& store = Kept();
  std::lock_guard<std::mutex> hold(store.Lock);
  Drop(store.Entries, data->GetPoints(), &now);
  radiosity::PreparedScene rays; // a rays-only match, where no transport one is kept
  for (auto entry = store.Entries.begin(); entry != store.Entries.end(); ++entry)
  {
    if (entry->From.Mesh != now.Mesh)
    {
      continue;
    }
    if (!transport || (entry->Scene.Geometry && entry->From.Patches == now.Patches))
    {
      std::rotate(store.Entries.begin(), entry, entry + 1);
      return store.Entries.front().Scene;
    }
    if (!rays.Rays)
    {
      rays = entry->Scene; // its rays (and sizes) serve; its geometry is for other patches
      rays.Geometry.reset();
      rays.SplitPatches = 0;
    }
  }
  return rays;
}

void Keep(vtkPolyData* data, const MeshKey& now, const radiosity::PreparedScene& scene)
{
  if (!data->GetPoints() || !data->GetPolys() || !scene.Rays)
  {
    return;
  }
  Store& store = Kept();
  std::lock_guard<std::mutex> hold(store.Lock);
  Drop(store.Entries, data->GetPoints(), &now);
  store.Entries.erase(std::remove_if(store.Entries.begin(), store.Entries.end(),
                        [&](const Entry& e) {
                          return e.Owner == data->GetPoints() && e.From.Patches == now.Patches;
                        }),
    store.Entries.end());
  store.Entries.insert(store.Entries.begin(), Entry{ data->GetPoints(), now, scene });
  if (store.Entries.size() > MaximumKeys)
  {
    store.Entries.resize(MaximumKeys);
  }
  store.OnDelete->SetCallback(PointsDeleted);
  if (!data->GetPoints()->HasObserver(vtkCommand::DeleteEvent, store.OnDelete))
  {
    data->GetPoints()->AddObserver(vtkCommand::DeleteEvent, store.OnDelete);
  }
}

void Clear()
{
  Store& store = Kept();
  std::lock_guard<std::mutex> hold(store.Lock);
  store.Entries.clear();
}

int Held()
{
  Store& store = Kept();
  std::lock_guard<std::mutex> hold(store.Lock);
  std::set<const radiosity::Visibility*> distinct; // dead ones too: the observer drops them
  for (const Entry& e : store.Entries)
  {
    distinct.insert(e.Scene.Rays.get());
  }
  return static_cast<int>(distinct.size());
}

}
