/**
 * @class   vtkRadiosityGLTFWriter
 * @brief   writes a solved scene as binary glTF 2.0 (.glb) that can be relit elsewhere
 *
 * For game engines, web viewers and other tools that change baked light without baking
 * again: the geometry (polygons triangulated), one float RGB vertex attribute per light
 * holding its unit-emission solution (`_RADIOSITY_<NAME>`, from the point arrays
 * `Radiosity_<name>`), and `COLOR_0` with the relit picture (the point array `Radiosity`
 * times Exposure, clamped to [0, 1]; for the solver's output every light at its default
 * color). The mesh's `extras.relight` lists each light's name, attribute and default color
 * (`LightDefaultColors`), where the relight filter made the input its color x intensity and
 * on/off as set there (`color`, `enabled`: a viewer starts from them), and the exposure, so
 * a viewer computes
 * `sum_i color_i * intensity_i * _RADIOSITY_i * exposure`. The material is unlit
 * (KHR_materials_unlit): the light is in the colors. Coordinates are written as they are
 * (glTF expects metres with +Y up).
 *
 * The file is written under a temporary name and renamed, so a failed write leaves an
 * older file whole.
 *
 * @sa vtkLightTaggedRadiosity vtkRadiosityRelight vtkRadiosityEXRWriter
 */
#ifndef vtkRadiosityGLTFWriter_h
#define vtkRadiosityGLTFWriter_h

#include "vtkRadiosityIOModule.h" // for export macro
#include "vtkWriter.h"

class VTKRADIOSITYIO_EXPORT vtkRadiosityGLTFWriter : public vtkWriter
{
public:
  static vtkRadiosityGLTFWriter* New();
  vtkTypeMacro(vtkRadiosityGLTFWriter, vtkWriter);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  vtkSetFilePathMacro(FileName);
  vtkGetFilePathMacro(FileName);

  ///@{
  /// Scale from radiosity to COLOR_0 (as the relight filter's Exposure). 0 (the default):
  /// the relight filter's own (its field array Exposure), else metered as it meters.
  vtkSetMacro(Exposure, double); // checked when writing: finite, not negative
  static double GetExposureMinValue() { return 0.0; }
  static double GetExposureMaxValue() { return VTK_DOUBLE_MAX; }
  vtkGetMacro(Exposure, double);
  ///@}

  /**
   * Writes the file, as vtkWriter does, but returns 0 with an error where a filter upstream
   * failed: the update stops there and this writer does not run (vtkWriter would return 1
   * with no file written); a second Write of the same failed pipeline reaches the writer,
   * which finds its input marked as failed and says so.
   */
  int Write() override;

protected:
  vtkRadiosityGLTFWriter();
  ~vtkRadiosityGLTFWriter() override;
  void WriteData() override;
  int FillInputPortInformation(int port, vtkInformation* info) override;

private:
  vtkRadiosityGLTFWriter(const vtkRadiosityGLTFWriter&) = delete;
  void operator=(const vtkRadiosityGLTFWriter&) = delete;

  char* FileName = nullptr;
  double Exposure = 0.0;
};

#endif
