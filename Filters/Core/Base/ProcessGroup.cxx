#include "Base/ProcessGroup.h"


namespace radiosity
{

std::string AgreeOnFailure(const ProcessGroup& group, const std::string& mine, const std::string& otherwise)
{
  double failed = mine.empty() ? 0.0 : 1.0;
  Collective(group).Sum(&failed, 1);
  return !mine.empty() || failed == 0 ? mine : "another rank " + otherwise;
}

} // namespace radiosity
