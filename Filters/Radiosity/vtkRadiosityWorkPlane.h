/**
 * @class   vtkRadiosityWorkPlane
 * @brief   illuminance per light on a calculation grid in the air over a solved scene
 *
 * Lays a work plane Height above the scene's floor (the lowest plane along UpAxis), Border
 * in from its sides, its points at the centres of a grid at most Spacing apart (0:
 * EN 12464-1's p = 0.2 * 5^log10(d), d the longer side in metres), and gathers the
 * irradiance arriving at each from above: direct light from every lamp cell and luminaire
 * with shadow rays, reflected light along GatherRays cosine rays into the solver's element
 * solution. Input: the light-tagged solver's output (its Radiosity_<light> cell arrays, its
 * lights and luminaires). Output: a grid of quads through the points, with point arrays
 * Illuminance_<light> (RGB; lux for a luminaire where the scene is in metres) and
 * Illuminance (their sum at the lights' default colors, the mean of the channels), and
 * field arrays IlluminanceMean, IlluminanceMinimum, IlluminanceMaximum and Uniformity
 * (minimum over mean, U0) of Illuminance.
 *
 * @sa vtkLightTaggedRadiosity vtkRadiosityLightMarker
 */
#ifndef vtkRadiosityWorkPlane_h
#define vtkRadiosityWorkPlane_h

#include "vtkRadiosityAlgorithm.h"
#include "vtkRadiosityFiltersModule.h" // for export macro

class VTKRADIOSITYFILTERS_EXPORT vtkRadiosityWorkPlane : public vtkRadiosityAlgorithm
{
public:
  static vtkRadiosityWorkPlane* New();
  vtkTypeMacro(vtkRadiosityWorkPlane, vtkRadiosityAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The plane's height over the floor, in the scene's units. Default 0.8 (a desk, m).
  vtkSetClampMacro(Height, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(Height, double);
  ///@}

  ///@{
  /// How far in from the scene's sides the grid starts. Default 0.5 (EN 12464-1's border, m).
  vtkSetClampMacro(Border, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(Border, double);
  ///@}

  ///@{
  /// The largest distance between points; 0 (the default) takes EN 12464-1's for the area.
  vtkSetClampMacro(Spacing, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(Spacing, double);
  ///@}

  ///@{
  /// The scene's up axis (0 x, 1 y, 2 z); -1 (the default) takes its shortest side.
  vtkSetClampMacro(UpAxis, int, -1, 2);
  vtkGetMacro(UpAxis, int);
  ///@}

  ///@{
  /// The box to lay the plane in (xmin, xmax, ymin, ymax, zmin, zmax: a room's, its floor
  /// the lowest along UpAxis); all zero (the default) takes the scene's bounds.
  vtkSetVector6Macro(Area, double);
  vtkGetVector6Macro(Area, double);
  ///@}

  ///@{
  /// Cosine rays per point into the element solution for the reflected light. Default 256;
  /// 0: direct light alone.
  vtkSetClampMacro(GatherRays, int, 0, 65536);
  vtkGetMacro(GatherRays, int);
  ///@}

protected:
  vtkRadiosityWorkPlane() = default;
  ~vtkRadiosityWorkPlane() override = default;
  int Execute(const Run& run) override;
  /// Each rank lays its own piece's plane: no collective to agree in.
  bool AgreesAcrossRanks() const override { return false; }

private:
  vtkRadiosityWorkPlane(const vtkRadiosityWorkPlane&) = delete;
  void operator=(const vtkRadiosityWorkPlane&) = delete;

  double Height = 0.8;
  double Border = 0.5;
  double Spacing = 0;
  int UpAxis = -1;
  int GatherRays = 256;
  double Area[6] = { 0, 0, 0, 0, 0, 0 };
};

#endif
