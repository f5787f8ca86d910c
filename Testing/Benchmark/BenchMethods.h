// The benches' short method names ("progressive", "hierarchical", "clustered", as their
// --method flags and CSV columns spell them), taken from the solver's method table so a
// method added there is known to every bench at once.
#ifndef RadiosityBench_BenchMethods_h
#define RadiosityBench_BenchMethods_h

#include "Solve/SolverMethods.h"

#include <cctype>
#include <string>

namespace radiosity_bench
{

/// The table's name up to its second word, in lower case ("ProgressiveRefinement" ->
/// "progressive"); "auto" for Auto.
inline std::string ShortMethodName(radiosity::SolverMethod method)
{
  const radiosity::MethodEntry* entry = radiosity::FindSolverMethod(method);
  const std::string name = entry ? entry->Name : "Auto";
  std::string shortName;
  for (size_t i = 0; i < name.size() && (i == 0 || !std::isupper(static_cast<unsigned char>(name[i]))); ++i)
  {
    shortName += static_cast<char>(std::tolower(static_cast<unsigned char>(name[i])));
  }
  return shortName;
}

/// The method a --method value names; Auto for any other value.
inline radiosity::SolverMethod MethodNamed(const std::string& value)
{
  for (const radiosity::MethodEntry& entry : radiosity::SolverMethodTable())
  {
    if (ShortMethodName(entry.Method) == value)
    {
      return entry.Method;
    }
  }
  return radiosity::SolverMethod::Auto;
}

} // namespace radiosity_bench

#endif
