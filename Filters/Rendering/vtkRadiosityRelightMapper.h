/**
 * @class   vtkRadiosityRelightMapper
 * @brief   renders the light-tagged solutions relit on the GPU: a light change costs a frame
 *
 * Give it the solver's output (point arrays `Radiosity_<name>`, field arrays LightNames
 * and LightDefaultColors). The k solutions are uploaded once, as 32-bit floats in a
 * texture buffer (any k, no quantisation); the vertex shader sums them with each light's
 * color x intensity (zero when off), then applies Exposure, the clamp and the sRGB curve
 * of vtkRadiosityRelight's DisplayColors, and the surface is drawn unlit with that color.
 *
 * Light settings (GetLights(), the relight filter's vtkRadiosityLights) have the filter's
 * meaning and precedence (defaults, by name, the schedule at Time, by index), but changing
 * them does not modify the mapper: no pipeline execution, no upload, only the uniforms of
 * the next Render(). New input data is
 * uploaded again on the next render.
 *
 * @sa vtkRadiosityRelight vtkLightTaggedRadiosity
 */
#ifndef vtkRadiosityRelightMapper_h
#define vtkRadiosityRelightMapper_h

#include "vtkOpenGLPolyDataMapper.h"
#include "vtkRadiosityRenderingModule.h" // for export macro

class vtkRadiosityLights;

#include <memory> // for the internals
#include <vector> // for the weights

class vtkFloatArray;
class vtkStringArray;
class vtkUnsignedCharArray;

class VTKRADIOSITYRENDERING_EXPORT vtkRadiosityRelightMapper : public vtkOpenGLPolyDataMapper
{
public:
  static vtkRadiosityRelightMapper* New();
  vtkTypeMacro(vtkRadiosityRelightMapper, vtkOpenGLPolyDataMapper);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The lights' settings (vtkRadiosityLights: color, intensity, on/off by index or by
  /// name, the schedule), read at each Render(): a change costs no pipeline execution and
  /// no upload. Give it the relight filter's (SetLights(filter->GetLights())) and both
  /// follow the same settings. Never null; setting null is ignored.
  vtkRadiosityLights* GetLights();
  void SetLights(vtkRadiosityLights* lights);
  ///@}

  ///@{
  /// The time at which the lights' schedule is evaluated.
  void SetTime(double time);
  double GetTime() const;
  ///@}

  ///@{
  /// Multiplier before the clamp to display colors, as the relight filter's: 0 (the
  /// default) meters it once per input, with the lights at their defaults (a sum on the
  /// CPU), so that changing a light changes the picture; GetExposureInUse says the value
  /// drawn with.
  void SetExposure(double exposure);
  double GetExposure() const;
  double GetExposureInUse();
  ///@}

  /// The lights of `data` (the solver's output) and their settings in effect at Time:
  /// `names` gets one name per light, `settings` one row per light (the columns of
  /// vtkRadiosityLights::GetSettingRowColumnName), as vtkRadiosityRelight's LightSettingsInfo.
  void DescribeLights(vtkPolyData* data, vtkStringArray* names, vtkStringArray* settings);

  ///@{
  /// Relight on the GPU (default) or on the CPU: the CPU sums the solutions into display
  /// colors after each change and uploads them, as the relight filter would. The mapper
  /// also falls back to the CPU by itself, and says so once, where this OpenGL cannot hold
  /// the solutions in a texture buffer or the weights in uniforms.
  void SetUseGPU(bool use);
  bool GetUseGPU() const;
  /// True when the last render relit on the CPU (asked for, or fallen back to).
  bool GetRelitOnCPU() const;
  ///@}

  /// The number of lights of the data last uploaded (0 before the first render).
  int GetNumberOfLights() const;

  /// How many times the solutions were uploaded: stays put while only lights change.
  int GetUploadCount() const;

  /// Why the last render could not relight (empty when it did): missing arrays, an
  /// invalid light setting, too much data for a texture buffer. The surface is then drawn
  /// black, and the reason is also reported once as an error.
  const char* GetLastProblem() const;

  void ReleaseGraphicsResources(vtkWindow* window) override;

protected:
  vtkRadiosityRelightMapper();
  ~vtkRadiosityRelightMapper() override;
  void RenderPieceStart(vtkRenderer* ren, vtkActor* act) override;
  void RenderPieceFinish(vtkRenderer* ren, vtkActor* act) override;
  bool GetNeedToRebuildShaders(vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act) override;
  void ReplaceShaderValues(
    std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act) override;
  void SetMapperShaderParameters(vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act) override;
  /// The CPU path's colors are on the data drawn (CurrentInput), not on the input.
  vtkUnsignedCharArray* MapScalars(double alpha) override;
  vtkUnsignedCharArray* MapScalars(double alpha, int& cellFlag) override;

private:
  vtkRadiosityRelightMapper(const vtkRadiosityRelightMapper&) = delete;
  void operator=(const vtkRadiosityRelightMapper&) = delete;

  /// Uploads the solutions when the input changed since the last upload (or decides that
  /// the CPU must relight).
  void UploadIfNeeded(vtkRenderer* ren);
  /// The lights' weights now (3 per light), zero with the error reported once when a
  /// setting is invalid.
  std::vector<float> CurrentWeights();
  /// The input with display colors summed on the CPU, made again only after a change.
  vtkPolyData* CpuColored();
  /// The weighted sum of the uploaded data's solutions, on the CPU.
  void SumOnCpu(const std::vector<float>& weights, vtkFloatArray* linear);

  struct Internals;
  std::unique_ptr<Internals> Internal;
};

#endif
