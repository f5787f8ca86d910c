// The weighted sum of a solution's light arrays, shared by the relight filter and the GPU
// mapper's CPU path (radiosity::CombineLights on the arrays' own memory, in parallel).
#ifndef vtkRadiosityCombine_h
#define vtkRadiosityCombine_h

#include "vtkRadiosityFiltersModule.h" // for export macro
#include "vtkType.h"                   // for vtkIdType

#include <memory> // for the reader's state
#include <string> // for the array names and errors
#include <vector> // for the weights

class vtkFieldData;
class vtkFloatArray;
class vtkPolyData;
namespace radiosity
{
struct Vec3;
}

/// What relighting reads of a solved data set, read once: its lights (LightNames, else the
/// names of its Radiosity_<name> arrays) and their default colors, and per kind of item
/// (points, cells) the per-light arrays, Radiosity_<name> and, where asked for,
/// Direct_<name> after them, as pointers into the arrays' own memory: the data set must
/// outlive it with those arrays unchanged. The relight filter resolves, combines and meters
/// from it; nothing is looked up twice. C++ only (Python relights through vtkRadiosityRelight).
#ifndef __VTK_WRAP__
class VTKRADIOSITYFILTERS_EXPORT vtkRadiosityRelitInput
{
public:
  vtkRadiosityRelitInput();
  ~vtkRadiosityRelitInput();
  /// The lights of `data` and their default colors; "" or why there are none to relight
  /// (no lights, one combined solution).
  std::string ReadLights(vtkPolyData* data);
  /// Then their arrays; "" or why they cannot be combined (an array of the wrong type or
  /// size, the direct parts asked for, `withDirect`, and missing).
  std::string ReadTables(vtkPolyData* data, bool withDirect = false);
  const std::vector<std::string>& GetNames() const;
  std::vector<radiosity::Vec3> GetDefaultColors() const;
  bool HasPoints() const;
  bool HasCells() const;
  /// `out` = the points' (or the cells') arrays weighted by `weights` (3 a light; 6 with
  /// the direct parts, as radiosity::LightWeights gives them); false, with `error` naming
  /// the item, where the sum is not finite.
  bool Combine(bool cells, const std::vector<double>& weights, vtkFloatArray* out, std::string& error) const;
  /// The points' (or the cells') solutions item by item, each item's lights side by side
  /// (3 floats a light, in GetNames order): what the GPU mapper's buffer holds.
  std::vector<float> Interleaved(bool cells) const;
  /// True where a value of the points' (or the cells') solutions is not finite: `item`
  /// and `light` (an index into GetNames) say the first.
  bool FindNonFinite(bool cells, size_t& item, size_t& light) const;
  /// The exposure a camera meters for `data` (the set read) with every light at its
  /// default: on the cells where they hold the solutions (they know which ones are lamps),
  /// else the points. 0 where that lights nothing.
  double MeterAtDefaults(vtkPolyData* data) const;

private:
  struct Internals;
  std::unique_ptr<Internals> Impl;
};
#endif

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
