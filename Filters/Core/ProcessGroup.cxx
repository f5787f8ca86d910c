#include "ProcessGroup.h"
#include "Scene.h"

#include <algorithm>

namespace radiosity
{

std::string AgreeOnFailure(const ProcessGroup& group, const std::string& mine, const std::string& otherwise)
{
  double failed = mine.empty() ? 0.0 : 1.0;
  Collective(group).Sum(&failed, 1);
  return !mine.empty() || failed == 0 ? mine : "another rank " + otherwise;
}

std::vector<char> OwnedPatches(const SceneGeometry& geometry, int rank, int ranks)
{
  const size_t patches = geometry.patchElements.size();
  if (ranks <= 1)
  {
    return std::vector<char>(patches, 1);
  }
  std::vector<char> owned(patches, 0);
  std::vector<size_t> load(ranks, 0);
  for (size_t p = 0; p < patches; ++p)
  {
    const auto least = std::min_element(load.begin(), load.end()); // the first on ties
    owned[p] = least - load.begin() == rank ? 1 : 0;
    *least += std::max<size_t>(geometry.patchElements[p].size(), 1);
  }
  return owned;
}

} // namespace radiosity
