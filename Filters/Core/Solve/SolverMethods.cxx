#include "Solve/SolverMethods.h"
#include "Solve/ClusteredRadiosity.h"
#include "Solve/HierarchicalRadiosity.h"
#include "Solve/ProgressiveRadiosity.h"

#include <cstdio>
#include <sstream>

namespace radiosity
{

namespace
{
std::string DescribeProgressive(const SolverStatistics& stats)
{
  return "ProgressiveRefinement: " + std::to_string(stats.FormFactorCount) + " form factors";
}

std::string DescribeHierarchical(const SolverStatistics& stats)
{
  char text[256];
  std::snprintf(text, sizeof(text),
    "Hierarchical: %lld patch links, %lld element links, %lld volume links, %.1f MB of links", stats.PatchLinks,
    stats.ElementLinks, stats.VolumeLinks, stats.LinkBytes / 1048576.0);
  return text;
}

std::string DescribeClustered(const SolverStatistics& stats)
{
  char text[256];
  std::snprintf(text, sizeof(text), "Clustered: %lld cluster links, %lld element links, %.1f MB of links",
    stats.VolumeLinks, stats.ElementLinks, stats.LinkBytes / 1048576.0);
  return text;
}
} // namespace

const std::vector<MethodEntry>& SolverMethodTable()
{
  static const std::vector<MethodEntry> table = {
    { SolverMethod::ProgressiveRefinement, "ProgressiveRefinement", SolveProgressive, DescribeProgressive,
      "FormFactorMethod", {} },
    { SolverMethod::Hierarchical, "Hierarchical", SolveHierarchical, DescribeHierarchical, "",
      { { "RefinementThreshold", HierarchicalSettings{}.RefinementThreshold, 0.0, 1.0,
        [](SolverOptions& o, double v) { o.Hierarchical.RefinementThreshold = v; } } } },
    { SolverMethod::Clustered, "Clustered", SolveClustered, DescribeClustered, "ClusterSeparation",
      { { "ClusterMemoryLimit", ClusteredSettings{}.MemoryLimit, 0.0, 1e18,
        [](SolverOptions& o, double v) { o.Clustered.MemoryLimit = v; } } } },
  };
  return table;
}

const MethodEntry* FindSolverMethod(SolverMethod method)
{
  for (const MethodEntry& entry : SolverMethodTable())
  {
    if (entry.Method == method)
    {
      return &entry;
    }
  }
  return nullptr;
}

const MethodEntry* MethodOwning(const std::string& setting)
{
  for (const MethodEntry& entry : SolverMethodTable())
  {
    std::istringstream names(entry.OwnSettings);
    for (std::string name; names >> name;)
    {
      if (name == setting)
      {
        return &entry;
      }
    }
    for (const MethodSetting& own : entry.Settings)
    {
      if (setting == own.Name)
      {
        return &entry;
      }
    }
  }
  return nullptr;
}

std::string ApplyMethodSetting(const std::string& name, double value, SolverOptions& options)
{
  std::string known;
  for (const MethodEntry& entry : SolverMethodTable())
  {
    for (const MethodSetting& own : entry.Settings)
    {
      if (name != own.Name)
      {
        known += (known.empty() ? "" : ", ") + std::string(own.Name) + " (" + entry.Name + ")";
        continue;
      }
      if (!(value >= own.Min && value <= own.Max))
      {
        char text[160];
        std::snprintf(text, sizeof(text), " is %g; it is from %g to %g", value, own.Min, own.Max);
        return name + text;
      }
      own.Set(options, value);
      return "";
    }
  }
  return "no method has a setting '" + name + "'; the methods' settings by name are " + known;
}

std::string DescribeSolve(const SolverStatistics& stats)
{
  const MethodEntry* entry = FindSolverMethod(stats.SolverMethod);
  std::string described = entry ? entry->Describe(stats) : "no method";
  if (stats.FaceClusters > 0)
  {
    described += "; " + std::to_string(stats.FaceClusters) + " face clusters";
  }
  return stats.MethodReason.empty() ? described : described + "; " + stats.MethodReason;
}

} // namespace radiosity
