// Which of two faces of one plane keeps what they share: the one rule that coincident copies
// (CoincidentCopies) and overlapping faces (OverlapCuts) both follow.
#ifndef RadiosityCore_KeepingOrder_h
#define RadiosityCore_KeepingOrder_h

#include "Mesh/TrianglePairs.h"

#include <cstddef>
#include <vector>

namespace radiosity
{

/// A lamp keeps before a face that is not one (a lamp panel drawn in the ceiling it hangs
/// from shines, and the ceiling gives way to it); else a face lying wholly on more faces of
/// other surfaces keeps (a poster, a rug, a pane drawn on an uncut wall: the detail is what
/// is seen, and the face under it gives way, whichever came first); else the earlier
/// polygon keeps. One total order for every pair, whatever their materials, so no point of
/// a plane is left to none of its faces and none to two (a rule made of pairwise choices,
/// the smaller of two materials against the earlier of one, made cycles and holes).
/// Coincident copies lie on each other alike, so for them the earlier keeps.
class KeepingOrder
{
public:
  /// `lamps`: per source id, 1 where it emits (empty: none does).
  KeepingOrder(const std::vector<char>& lamps, const PairedPolygons& polygons)
    : Lamps(lamps)
    , Polygons(polygons)
  {
  }

  /// Whether polygon `i` (a position in the polygons) emits.
  bool IsLamp(size_t i) const
  {
    const int source = this->Polygons.Source[i];
    return source < static_cast<int>(this->Lamps.size()) && this->Lamps[source];
  }

  /// Whether polygon `a`, lying wholly on `onA` other surfaces, keeps what it shares
  /// with polygon `b`, lying on `onB`.
  bool Before(size_t a, size_t b, int onA = 0, int onB = 0) const
  {
    const bool lampA = this->IsLamp(a), lampB = this->IsLamp(b);
    if (lampA != lampB)
    {
      return lampA;
    }
    return onA != onB ? onA > onB : a < b;
  }

private:
  const std::vector<char>& Lamps;
  const PairedPolygons& Polygons;
};

} // namespace radiosity

#endif
