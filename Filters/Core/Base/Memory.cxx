#include "Base/Memory.h"

#include <cstdio>
#include <fstream>
#include <sstream>

namespace radiosity
{

double AvailableMemory()
{
  std::ifstream info("/proc/meminfo");
  std::string key;
  double kilobytes = 0;
  while (info >> key >> kilobytes)
  {
    if (key == "MemAvailable:")
    {
      return 1024.0 * kilobytes;
    }
    info.ignore(256, '\n');
  }
  return 0;
}

std::string CheckMemory(double bytes, const std::string& what)
{
  return CheckMemory(bytes, what, 0.0);
}

std::string CheckMemory(double bytes, const std::string& what, double limit)
{
  const double available = limit > 0 ? limit : AvailableMemory();
  if (available <= 0 || bytes <= (limit > 0 ? 1.0 : 0.9) * available)
  {
    return std::string();
  }
  char text[512];
  std::snprintf(text, sizeof(text), "%s needs about %.3g GB, more than the %.3g GB of memory %s", what.c_str(),
    bytes / 1073741824.0, available / 1073741824.0, limit > 0 ? "allowed (ClusterMemoryLimit)" : "available");
  return text;
}

} // namespace radiosity
