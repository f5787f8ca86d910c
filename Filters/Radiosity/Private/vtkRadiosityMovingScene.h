// The relight filter's moving lights (paper 2.4): the scene, the dynamic objects and the
// Embree shader kept between frames, rebuilt (or the dynamic objects swapped) only when an
// input changes, and a frame's direct light plus the patch basis's interreflection. Not
// wrapped.
#ifndef vtkRadiosityMovingScene_h
#define vtkRadiosityMovingScene_h

#include <memory>
#include <string>

class vtkFloatArray;
class vtkPolyData;

class vtkRadiosityMovingScene
{
public:
  vtkRadiosityMovingScene();
  ~vtkRadiosityMovingScene();
  vtkRadiosityMovingScene(const vtkRadiosityMovingScene&) = delete;
  vtkRadiosityMovingScene& operator=(const vtkRadiosityMovingScene&) = delete;

  /// Adds the light of the points `lights` (with Color, Intensity and optional Normal) to
  /// `points` and `cells` of the solved `scene` (its PatchBasis carries their
  /// interreflection), shadowed by the polygons of `dynamic` (may be null); false with
  /// `error` naming the problem.
  bool Shade(vtkPolyData* scene, vtkPolyData* lights, vtkPolyData* dynamic, vtkFloatArray* points,
    vtkFloatArray* cells, std::string& error);
  /// Shadow rays of the last Shade.
  long long Rays() const { return this->LastRays; }
  /// Whether the shader shades on the solver's kept preparation (not one made here).
  bool Reused() const;

private:
  /// Where only the dynamic objects changed: swaps them in the shader's ray scene and
  /// keeps the rest; false with `error` where they cannot be read or built.
  bool SwapDynamicObjects(vtkPolyData* dynamic, std::string& error);
  /// Reads the scene and the dynamic objects anew and makes the shader, on the solver's
  /// preparation where it is kept; false with `error` where they cannot be read or prepared.
  bool Rebuild(vtkPolyData* scene, vtkPolyData* dynamic, std::string& error);

  struct State;
  std::unique_ptr<State> Kept;
  long long LastRays = 0;
};

#endif
