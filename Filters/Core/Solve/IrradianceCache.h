// Sharing the final gather between neighbouring points (irradiance caching, Ward, Rubinstein
// & Clear 1988): interreflection changes slowly away from other surfaces, so a point's
// gathered light can be read from records gathered nearby. A record reaches a fraction of
// the harmonic mean distance its rays travelled (Ward's bound on how fast irradiance can
// change there), and never past the nearest surface its rays met: a wall between two points
// is nearer to either than the other is, so a record never reaches through it.
#ifndef RadiosityCore_IrradianceCache_h
#define RadiosityCore_IrradianceCache_h

#include "Base/Vec3.h"

#include <functional>
#include <utility>
#include <vector>

namespace radiosity
{

/// A gathered point others may read: where it is, and how far its value holds.
struct CacheRecord
{
  int Point = -1; ///< its index in the list PlaceRecords was given
  Vec3 Origin, Normal;
  double Reach = 0;    ///< 0: no other point reads it
  bool Hidden = false; ///< it saw mostly back faces (its value is mended from its neighbours')
};

/// What a record's rays found, for its reach: Accuracy (Ward's a) times the harmonic mean of
/// the hit distances (misses count as infinitely far), at most the nearest hit and at most
/// `largest` (a record whose rays met nothing, on a roof under the sky, would otherwise
/// reach every point facing as it does, those under the roof too).
double RecordReach(double accuracy, double inverseDistanceSum, int rays, double nearest, double largest);

/// The largest reach in a scene whose points span `diagonal`: a twentieth of it.
inline double LargestReach(double diagonal)
{
  return 0.05 * diagonal;
}

/// A record's Side x Side stratified cosine rays in its tangent frame (T, B, normal): cell
/// i * Side + j is stratum i of u = sin^2(theta) and stratum j of phi; each ray's u, the
/// cosine and sine of its phi (the gather has them for its direction), hit distance
/// (infinity for a miss) and what it brought back per solution (0 for a miss or a back
/// face), Values[cell * Solutions + m].
struct StratifiedRays
{
  void Reset(int side, int solutions);
  void SetPhi(size_t cell, double cosine, double sine)
  {
    CosPhi[cell] = cosine;
    SinPhi[cell] = sine;
  }
  int Side = 0, Solutions = 0;
  Vec3 T, B;
  std::vector<double> U, CosPhi, SinPhi, Distance;
  std::vector<Vec3> Values;
};

/// How the gathered irradiance (the mean of the values, per solution) changes as the point
/// moves, translation[m * 3 + c] the gradient of colour channel c of solution m, and as its
/// normal turns, E(n) = E + rotation[m * 3 + c] . (record normal x n) (Ward & Heckbert 1992,
/// "Irradiance gradients": the cells' boundaries move as the point does, by the nearer of
/// the two distances either side).
void IrradianceGradients(const StratifiedRays& rays, Vec3* translation, Vec3* rotation);

/// The records as a tree of their reach balls, asked which of them a point may read.
class IrradianceCache
{
public:
  explicit IrradianceCache(std::vector<CacheRecord> records);

  /// The records (index into Records(), weight in (0, 1]) that reach the point at `x` with
  /// `normal`, into `out`; returns the sum of the weights. The weight falls to 0 at a
  /// record's reach and at 20 degrees between the normals, and is 0 for a record standing
  /// in front of the point (a table top over a floor point).
  double Weights(const Vec3& x, const Vec3& normal, std::vector<std::pair<int, double>>& out) const;

  const std::vector<CacheRecord>& Records() const { return Items; }

private:
  struct Node
  {
    Vec3 Low, High;
    int First = 0, Count = 0; ///< a leaf's records
    int Left = -1, Right = -1; ///< an inner node's children
  };
  int Build(int first, int count);

  std::vector<CacheRecord> Items;
  std::vector<Node> Nodes;
};

/// Which of `origins` (with `normals`) gather for themselves: level by level over every
/// 256th, 64th, 16th, 4th point and then every point, those that the records of the levels
/// before do not cover (weights summing to under a fifth) are gathered, `gather(points)`
/// returning their records in that order; the last level leaves none uncovered. A level's
/// choice depends only on the levels before it, so the records are the same on any number
/// of threads. `inParallel(count, body)` runs body(begin, end) over [0, count) in parallel. Stops with
/// what it has where `gather` returns fewer records than asked (it was stopped).
std::vector<CacheRecord> PlaceRecords(const std::vector<Vec3>& origins, const std::vector<Vec3>& normals,
  const std::function<std::vector<CacheRecord>(const std::vector<int>&)>& gather,
  const std::function<void(int, const std::function<void(int, int)>&)>& inParallel);

} // namespace radiosity

#endif
