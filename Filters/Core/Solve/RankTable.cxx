#include "Solve/RankTable.h"

namespace radiosity
{

void GatherOverRanks(Collective& ranks, Solution& out)
{
  static_assert(sizeof(Vec3) == 3 * sizeof(double), "Vec3 is summed as three doubles");
  SolverStatistics& stats = out.Statistics;
  stats.ShotCollectiveBytes = ranks.Bytes;
  ranks.Sum(reinterpret_cast<double*>(out.Radiosity.data()), 3 * out.Radiosity.size());
  ranks.Sum(reinterpret_cast<double*>(out.Direct.data()), 3 * out.Direct.size());
  double counts[] = { static_cast<double>(stats.RayCount), static_cast<double>(stats.RaysSkipped),
    static_cast<double>(stats.PairsUnblockable), static_cast<double>(stats.FormFactorCount),
    static_cast<double>(stats.PatchLinks), static_cast<double>(stats.ElementLinks), stats.LinkBytes,
    static_cast<double>(stats.VolumeLinks) };
  ranks.Sum(counts, 8);
  stats.RayCount = static_cast<long long>(counts[0]);
  stats.RaysSkipped = static_cast<long long>(counts[1]);
  stats.PairsUnblockable = static_cast<long long>(counts[2]);
  stats.FormFactorCount = static_cast<long long>(counts[3]);
  stats.PatchLinks = static_cast<long long>(counts[4]);
  stats.ElementLinks = static_cast<long long>(counts[5]);
  stats.LinkBytes = counts[6];
  stats.VolumeLinks = static_cast<long long>(counts[7]);
  stats.Ranks = ranks.Ranks();
  stats.Collectives = ranks.Calls;
  stats.CollectiveSeconds = ranks.Seconds;
  stats.CollectiveBytes = ranks.Bytes;
}

} // namespace radiosity
