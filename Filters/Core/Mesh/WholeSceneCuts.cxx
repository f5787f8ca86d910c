#include "Mesh/WholeSceneCuts.h"

#include <algorithm>
#include <utility>

namespace radiosity
{
namespace
{
using PairList = std::vector<std::pair<int, int>>;

template <typename Keep>
std::vector<int> Kept(const std::vector<int>& cells, Keep own)
{
  std::vector<int> kept;
  std::copy_if(cells.begin(), cells.end(), std::back_inserter(kept), own);
  return kept;
}

template <typename Keep>
PairList KeptPairs(const PairList& pairs, Keep own)
{
  PairList kept;
  std::copy_if(pairs.begin(), pairs.end(), std::back_inserter(kept), [&](const std::pair<int, int>& p) { return own(p.second); });
  return kept;
}
} // namespace

PairedPolygons CutAsWhole(const PolygonArrays& whole, const WholeSceneSurfaces& surfaces, int count,
  double tolerance, double noise, CoincidentCopies* copies, OverlapCuts* overlaps)
{
  PairedPolygons all;
  all.Offsets = whole.Offsets;
  all.Connectivity = whole.Connectivity;
  for (size_t i = 0; i + 1 < whole.Offsets.size(); ++i)
  {
    all.Source.push_back(static_cast<int>(i));
  }
  const CoincidentCopies found = DropCoincidentCopies(whole.Points, surfaces.SurfaceKey, surfaces.Lamps, tolerance, all);
  const OverlapCuts cuts = CutOverlaps(whole.Points, surfaces.SurfaceKey, surfaces.Lamps, noise, all);
  const int first = surfaces.FirstPolygon;
  const auto own = [&](int source) { return source >= first && source < first + count; };
  PairedPolygons piece;
  piece.Points = PointsOf(all, whole.Points);
  for (size_t i = 0; i < all.Source.size(); ++i)
  {
    if (own(all.Source[i]))
    {
      piece.Connectivity.insert(
        piece.Connectivity.end(), all.Connectivity.begin() + all.Offsets[i], all.Connectivity.begin() + all.Offsets[i + 1]);
      piece.Offsets.push_back(static_cast<int>(piece.Connectivity.size()));
      piece.Source.push_back(all.Source[i] - first);
    }
  }
  if (copies)
  {
    copies->Dropped = Kept(found.Dropped, own);
    copies->Differing = KeptPairs(found.Differing, own);
    copies->LampsKept = KeptPairs(found.LampsKept, own);
  }
  if (overlaps)
  {
    overlaps->Trimmed = Kept(cuts.Trimmed, own);
    overlaps->Covered = Kept(cuts.Covered, own);
    overlaps->Differing = KeptPairs(cuts.Differing, own);
    overlaps->OnTop = KeptPairs(cuts.OnTop, own);
    overlaps->LampsKept = KeptPairs(cuts.LampsKept, own);
  }
  return piece;
}

} // namespace radiosity
