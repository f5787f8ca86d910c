// The exposure a camera's meter would pick for a relit picture, so that a scene shows
// neither black nor burnt out before anyone has chosen one.
#ifndef RadiosityCore_Exposure_h
#define RadiosityCore_Exposure_h

#include <cstddef>
#include <vector>

namespace radiosity
{

/// Where the meter puts the brightest surfaces: the 99th percentile of luminance, over the
/// items that do not emit (a lamp is meant to be white), at 80 % of white. A percentile
/// and not the mean: one bright wall must not burn out, and a dark room must not come out
/// as bright as a lit one's walls, only its lit part does.
constexpr double kMeteredPercentile = 0.99, kMeteredWhite = 0.8;

/// The exposure that shows `rgb` (count linear triples) so; `skip` (empty, or one flag per
/// item) marks the items to leave out; `area` (empty, or one per item) weighs them, as a
/// camera's pixels weigh surfaces: counted alike, many small bright parts (a BIM model's
/// fittings near a lamp) set the meter and the large walls burnt out. `unlit` where
/// nothing is lit.
double MeteredExposure(const float* rgb, std::size_t count, const std::vector<char>& skip, double unlit = 1.0,
  const std::vector<double>& area = {});

} // namespace radiosity

#endif
