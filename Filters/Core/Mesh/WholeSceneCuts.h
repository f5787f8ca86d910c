// Coincident copies and overlapping faces found over the whole scene where one process
// meshes a piece of it (MPI ranks): a panel on one rank doubled on another is left out or
// cut as in one process, where each rank alone would keep both and create energy.
#ifndef RadiosityCore_WholeSceneCuts_h
#define RadiosityCore_WholeSceneCuts_h

#include "Mesh/CoincidentCopies.h"
#include "Mesh/ContactCuts.h"
#include "Mesh/OverlapCuts.h"
#include "Mesh/TrianglePairs.h"

#include <vector>

namespace radiosity
{

/// What the copies and overlaps need of the whole scene besides its polygons: per whole
/// polygon its surface key (numbered over the whole scene, so the ranks agree) and whether
/// it emits, and where this piece's polygons begin among them (the pieces follow one
/// another in the whole, in rank order).
struct WholeSceneSurfaces
{
  std::vector<int> SurfaceKey;
  std::vector<char> Lamps;
  int FirstPolygon = 0;
};

/// This piece's `count` polygons after the copies and overlaps of `whole` are left out and
/// cut (DropCoincidentCopies, CutOverlaps; `tolerance` and `noise` as they take them, from
/// the whole scene), with Source numbered in the piece and Points the whole's and the cuts'
/// new corners. The reports keep what concerns this piece (a pair where its second polygon
/// is the piece's, so each is said by one rank), numbered in the whole scene.
PairedPolygons CutAsWhole(const PolygonArrays& whole, const WholeSceneSurfaces& surfaces, int count,
  double tolerance, double noise, CoincidentCopies* copies, OverlapCuts* overlaps);

} // namespace radiosity

#endif
