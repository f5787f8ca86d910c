/**
 * @class   vtkLightTaggedRadiosity
 * @brief   solves one radiosity solution per light in a single progressive pass
 *
 * The modified progressive refinement of Nielsen & Christensen (Fig. 2) with
 * substructuring: patches (cell array `PatchId`, else every cell) shoot, elements (the
 * cells) receive. Each shot picks the patch with the largest unshot power summed over
 * lights, evaluates its form factors to every element once (Lambert's exact
 * point-to-polygon formula times the fraction of unblocked Embree shadow rays) and
 * distributes the unshot energy of all k lights with them.
 *
 * Input: polygons with cell arrays `Reflectance` (3), `LightId` (integer, -1 or 0..k-1),
 * optional `Emission` (3), `PatchId`, and field array `LightNames`. Light m's solution is
 * for unit exitance on its cells.
 *
 * Output: the input plus, for each light, point and cell arrays `Radiosity_<name>`
 * (3 components, float, exitance), field arrays `LightNames` and `UnshotHistory`
 * (remaining unshot power / initial after each shot). In StandardCombined mode one array
 * `Radiosity` instead, with every light at its `Emission`.
 *
 * Solves stop at MaximumShots or when the remaining unshot power falls below
 * ConvergenceThreshold times the initial power. Work is spread over all hardware threads;
 * results do not depend on the thread count.
 *
 * @sa vtkRadiosityMesher vtkRadiosityRelight
 */
#ifndef vtkLightTaggedRadiosity_h
#define vtkLightTaggedRadiosity_h

#include "vtkPolyDataAlgorithm.h"
#include "vtkRadiosityFiltersModule.h" // for export macro

class VTKRADIOSITYFILTERS_EXPORT vtkLightTaggedRadiosity : public vtkPolyDataAlgorithm
{
public:
  static vtkLightTaggedRadiosity* New();
  vtkTypeMacro(vtkLightTaggedRadiosity, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum SolutionModes
  {
    LIGHT_TAGGED = 0,
    STANDARD_COMBINED = 1,
    STANDARD_SEPARATE = 2
  };

  ///@{
  /// LightTagged (default): k solutions in one pass. StandardCombined: one ordinary
  /// solution with the lights' Emission. StandardSeparate: k ordinary solutions one after
  /// the other (the paper's comparison, same output as LightTagged).
  vtkSetClampMacro(SolutionMode, int, LIGHT_TAGGED, STANDARD_SEPARATE);
  vtkGetMacro(SolutionMode, int);
  void SetSolutionModeToLightTagged() { this->SetSolutionMode(LIGHT_TAGGED); }
  void SetSolutionModeToStandardCombined() { this->SetSolutionMode(STANDARD_COMBINED); }
  void SetSolutionModeToStandardSeparate() { this->SetSolutionMode(STANDARD_SEPARATE); }
  ///@}

  ///@{
  /// Upper bound on shots (per solve). Default 2000.
  vtkSetClampMacro(MaximumShots, int, 0, VTK_INT_MAX);
  vtkGetMacro(MaximumShots, int);
  ///@}

  ///@{
  /// Stop when remaining unshot power / initial power drops below this. Default 1e-3.
  vtkSetClampMacro(ConvergenceThreshold, double, 0.0, 1.0);
  vtkGetMacro(ConvergenceThreshold, double);
  ///@}

  ///@{
  /// Shadow rays per receiver and shot (stratified over the shooter); 0 ignores
  /// occlusion. Default 16.
  vtkSetClampMacro(ShadowRays, int, 0, 4096);
  vtkGetMacro(ShadowRays, int);
  ///@}

  ///@{
  /// Threads for the form factors; 0 (default) uses every hardware thread.
  vtkSetClampMacro(NumberOfThreads, int, 0, 1024);
  vtkGetMacro(NumberOfThreads, int);
  ///@}

  ///@{
  /// Statistics of the last solve.
  vtkGetMacro(LastShots, int);
  vtkGetMacro(LastConverged, bool);
  vtkGetMacro(LastShadowRays, long long);
  vtkGetMacro(LastSolveSeconds, double);
  ///@}

protected:
  vtkLightTaggedRadiosity();
  ~vtkLightTaggedRadiosity() override = default;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

private:
  vtkLightTaggedRadiosity(const vtkLightTaggedRadiosity&) = delete;
  void operator=(const vtkLightTaggedRadiosity&) = delete;

  int SolutionMode = LIGHT_TAGGED;
  int MaximumShots = 2000;
  double ConvergenceThreshold = 1e-3;
  int ShadowRays = 16;
  int NumberOfThreads = 0;
  int LastShots = 0;
  bool LastConverged = false;
  long long LastShadowRays = 0;
  double LastSolveSeconds = 0;
};

#endif
