// The weighted sum of a solution's light arrays, shared by the relight filter and the GPU
// mapper's CPU path (radiosity::CombineLights on the arrays' own memory, in parallel).
#ifndef vtkRadiosityCombine_h
#define vtkRadiosityCombine_h

#include "vtkRadiosityFiltersModule.h" // for export macro
#include "vtkType.h"                   // for vtkIdType

#include <string> // for the array names and errors
#include <vector> // for the weights

class vtkFieldData;
class vtkFloatArray;
class vtkPolyData;

/// out = sum over i of weights[3i .. 3i+2] times the RGB array `arrays[i]` of `data`, for
/// `tuples` tuples. The arrays must all be float or all double, 3 components, `tuples`
/// long. False, with `error` naming the array or the item, on a bad array or a sum that is
/// not finite.
VTKRADIOSITYFILTERS_EXPORT bool vtkRadiosityCombineSolutions(vtkFieldData* data,
  const std::vector<std::string>& arrays, const std::vector<double>& weights, vtkIdType tuples, vtkFloatArray* out,
  std::string& error);

/// The exposure a camera would meter for `relit`, the relit values of `data`'s cells
/// (`cells` true) or points (radiosity::MeteredExposure): those of cells with a `LightId`
/// of 0 or more emit and are left out. `unlit` where nothing is lit.
VTKRADIOSITYFILTERS_EXPORT double vtkRadiosityMeteredExposure(
  vtkPolyData* data, vtkFloatArray* relit, bool cells, double unlit = 1.0);

/// The first tuple of a 3-component array holding a value that is not finite, or -1.
VTKRADIOSITYFILTERS_EXPORT vtkIdType vtkRadiosityFirstNonFinite(vtkFloatArray* values);

#endif
