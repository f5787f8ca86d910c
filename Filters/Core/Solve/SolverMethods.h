// The table of solver methods: the one place a method is registered. The solver picks its
// SolveFunction here, the VTK filter its description here, and the tests check the VTK
// enum, the ParaView XML's enumeration and the docs against these names.
#ifndef RadiosityCore_SolverMethods_h
#define RadiosityCore_SolverMethods_h

#include "Solve/RadiositySolver.h"

#include <string>
#include <vector>

namespace radiosity
{

/// A setting a method owns that is set by name (vtkLightTaggedRadiosity::SetMethodSetting):
/// its range and where it goes.
struct MethodSetting
{
  const char* Name;
  double Default, Min, Max;
  void (*Set)(SolverOptions& options, double value);
};

struct MethodEntry
{
  SolverMethod Method;
  const char* Name; ///< as in the VTK enum, the XML and the field array SolverMethod
  SolveFunction Solve;
  /// What the method's transport held, from its statistics (the start of SolverMethod).
  std::string (*Describe)(const SolverStatistics& stats);
  /// The filter's settings this method alone reads, by name, space-separated: one set for
  /// a solve that another method ran is reported as unused (MethodOwning).
  const char* OwnSettings;
  /// Its settings set by name, which it alone reads too.
  std::vector<MethodSetting> Settings;
};

/// Every method, in the order of their SolverMethod values (Auto, which is a choice
/// between them, is not one).
const std::vector<MethodEntry>& SolverMethodTable();
/// The entry of `method`; null for Auto or a value no method has.
const MethodEntry* FindSolverMethod(SolverMethod method);
/// The method whose OwnSettings or Settings name `setting`; null where every method reads
/// it (or none).
const MethodEntry* MethodOwning(const std::string& setting);
/// Sets the method setting `name` to `value` in `options`; "" or why not (no method has
/// it, or the value is out of its range).
std::string ApplyMethodSetting(const std::string& name, double value, SolverOptions& options);
/// The method that ran, what its transport held, the face clusters and why it was chosen
/// (the field array SolverMethod), e.g. "Hierarchical: ...; chosen by Auto: ...".
std::string DescribeSolve(const SolverStatistics& stats);

} // namespace radiosity

#endif
