#include "Base/ProcessGroup.h"

#include <algorithm>


namespace radiosity
{

std::string AgreeOnFailure(const ProcessGroup& group, const std::string& mine, const std::string& otherwise)
{
  double failed = mine.empty() ? 0.0 : 1.0;
  Collective(group).Sum(&failed, 1);
  return !mine.empty() || failed == 0 ? mine : "another rank " + otherwise;
}

double LargestOverRanks(const ProcessGroup& group, double mine)
{
  if (!group.Distributed())
  {
    return mine;
  }
  std::vector<double> all(static_cast<size_t>(group.Ranks), 0.0);
  all[static_cast<size_t>(group.Rank)] = mine;
  Collective(group).Sum(all);
  return *std::max_element(all.begin(), all.end());
}

} // namespace radiosity
