#include "vtkRadiosityPreparedScenes.h"

#include "vtkCallbackCommand.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkWeakPointer.h"

#include <algorithm>
#include <mutex>
#include <set>
#include <vector>

namespace vtkRadiosityPreparedScenes
{
namespace
{

constexpr size_t MaximumKeys = 4;

/// What a preparation was made from, by identity and modification time: a freed object
/// reads null, so a new one at its address is never taken for it.
struct Key
{
  vtkWeakPointer<vtkPoints> Points;
  vtkWeakPointer<vtkCellArray> Polygons;
  vtkWeakPointer<vtkDataArray> PatchIds;
  bool HasPatchIds = false;
  vtkMTimeType PointsTime = 0, PolygonsTime = 0, PatchIdsTime = 0;

  static Key Of(vtkPolyData* data)
  {
    Key key;
    key.Points = data->GetPoints();
    key.Polygons = data->GetPolys();
    vtkDataArray* ids = data->GetCellData()->GetArray("PatchId");
    key.PatchIds = ids;
    key.HasPatchIds = ids != nullptr;
    key.PointsTime = data->GetPoints() ? data->GetPoints()->GetMTime() : 0;
    key.PolygonsTime = data->GetPolys() ? data->GetPolys()->GetMTime() : 0;
    key.PatchIdsTime = ids ? ids->GetMTime() : 0;
    return key;
  }
  bool Alive() const { return this->Points && this->Polygons && (!this->HasPatchIds || this->PatchIds); }
  bool SameMesh(const Key& other) const
  {
    return this->Points && this->Points == other.Points && this->Polygons == other.Polygons &&
      this->PointsTime == other.PointsTime && this->PolygonsTime == other.PolygonsTime;
  }
  bool SamePatches(const Key& other) const
  {
    return this->HasPatchIds == other.HasPatchIds && this->PatchIds == other.PatchIds &&
      this->PatchIdsTime == other.PatchIdsTime;
  }
};

struct Entry
{
  Key From;
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

void DropDead(std::vector<Entry>& entries)
{
  entries.erase(std::remove_if(entries.begin(), entries.end(), [](const Entry& e) { return !e.From.Alive(); }),
    entries.end());
}

/// A mesh's points are being deleted: its scenes go now, not at the next filter's call.
/// (Weak pointers to it still read it until its destructor runs.)
void PointsDeleted(vtkObject* points, unsigned long, void*, void*)
{
  Store& store = Kept();
  std::lock_guard<std::mutex> hold(store.Lock);
  store.Entries.erase(std::remove_if(store.Entries.begin(), store.Entries.end(),
                        [&](const Entry& e) { return !e.From.Alive() || e.From.Points.GetPointer() == points; }),
    store.Entries.end());
}

} // namespace

radiosity::PreparedScene Find(vtkPolyData* data, bool transport)
{
  Store& store = Kept();
  std::lock_guard<std::mutex> hold(store.Lock);
  DropDead(store.Entries);
  const Key key = Key::Of(data);
  for (auto entry = store.Entries.begin(); entry != store.Entries.end(); ++entry)
  {
    if (entry->From.SameMesh(key) && (!transport || (entry->Scene.Geometry && entry->From.SamePatches(key))))
    {
      std::rotate(store.Entries.begin(), entry, entry + 1);
      return store.Entries.front().Scene;
    }
  }
  return radiosity::PreparedScene();
}

void Keep(vtkPolyData* data, const radiosity::PreparedScene& scene)
{
  if (!data->GetPoints() || !data->GetPolys() || !scene.Rays)
  {
    return;
  }
  Store& store = Kept();
  std::lock_guard<std::mutex> hold(store.Lock);
  DropDead(store.Entries);
  const Key key = Key::Of(data);
  store.Entries.erase(std::remove_if(store.Entries.begin(), store.Entries.end(),
                        [&](const Entry& e) { return e.From.SameMesh(key) && e.From.SamePatches(key); }),
    store.Entries.end());
  store.Entries.insert(store.Entries.begin(), Entry{ key, scene });
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

int Held()
{
  Store& store = Kept();
  std::lock_guard<std::mutex> hold(store.Lock);
  DropDead(store.Entries);
  std::set<const radiosity::Visibility*> distinct;
  for (const Entry& e : store.Entries)
  {
    distinct.insert(e.Scene.Rays.get());
  }
  return static_cast<int>(distinct.size());
}

}
