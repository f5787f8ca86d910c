/**
 * @class   vtkRadiosityRelight
 * @brief   combines per-light radiosity solutions with user-set light colors
 *
 * Computes B_j = sum_i color_i * intensity_i * B_j,i (the paper's equation 1) from the
 * `Radiosity_<name>` point and cell arrays of vtkLightTaggedRadiosity, for the lights named
 * in the field array `LightNames` (or every `Radiosity_*` array if it is absent).
 * Changing a light re-executes only this filter, and this filter only combines: cost
 * O(n k), nothing upstream is recomputed.
 *
 * A light's default is the solver's field array `LightDefaultColors` (else the mean
 * `Emission` of its cells, else white): its largest channel is the default intensity and
 * the default color is the rest (largest channel 1), so an intensity set replaces the
 * lamp's strength and a color set keeps it. It is enabled.
 * With the solver's `Direct_<name>` arrays, IndirectScale scales indirect light alone:
 * B = Direct + IndirectScale * (Radiosity - Direct). Lights are addressed by index (SetLightColor
 * etc.) or by name (SetLightSetting, used by ParaView); index settings win.
 *
 * Moving lights (paper 2.4): an optional second input (port 1) of point lights, a
 * vtkPolyData whose points are the lights with point arrays `Color` (3, default white),
 * `Intensity` (radiant intensity, default 1) and optionally `Normal` (3: a small Lambertian
 * emitter facing it instead of an isotropic light). Each execution shoots their direct
 * light to every element (Embree shadow rays), sets each patch's emission to the light it
 * reflects and lets the solver's `PatchBasis` carry the interreflection:
 * B = direct + sum_q E_q basis_q, added to the static lights' combination. An optional
 * third input (port 2) holds dynamic objects that cast shadows of the moving lights'
 * direct light only. The pipeline's time reaches both inputs, so time-varying sources
 * animate the lights.
 *
 * Output: the input plus point and cell arrays `Radiosity` (3 components, linear exitance)
 * and `DisplayColors` (unsigned char RGB: Radiosity times Exposure, clamped, sRGB), the
 * latter active so a default mapper shows it directly, and the field arrays `Exposure`
 * (the one used: metered unless set), `LightColors` (each light's color x intensity) and
 * `LightEnabled` (on/off), which the glTF writer and the browser viewer start from.
 *
 * @sa vtkLightTaggedRadiosity
 */
#ifndef vtkRadiosityRelight_h
#define vtkRadiosityRelight_h

#include "vtkRadiosityAlgorithm.h"
#include "vtkRadiosityFiltersModule.h" // for export macro
#include "vtkRadiosityLights.h"        // for the shortcuts to the light settings
#include "vtkSmartPointer.h"             // for the info arrays

class vtkFloatArray;
class vtkStringArray;
class vtkRadiosityMovingScene;
class vtkRadiosityRelitInput;

#include <memory>  // for the internals
#include <string>  // for names
#include <vector>  // for names and weights

class VTKRADIOSITYFILTERS_EXPORT vtkRadiosityRelight : public vtkRadiosityAlgorithm
{
public:
  static vtkRadiosityRelight* New();
  vtkTypeMacro(vtkRadiosityRelight, vtkRadiosityAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The lights' settings (vtkRadiosityLights): color, intensity and on/off by index or by
  /// name, and the schedule. Give a GPU mapper the same object and both follow one set of
  /// settings. Never null; setting null is ignored.
  vtkRadiosityLights* GetLights() { return this->Lights; }
  void SetLights(vtkRadiosityLights* lights);
  ///@}

  ///@{
  /// Shortcuts to GetLights()'s settings (ParaView's properties call these).
  void SetLightColor(int light, double r, double g, double b) { this->Lights->SetLightColor(light, r, g, b); }
  void SetLightIntensity(int light, double intensity) { this->Lights->SetLightIntensity(light, intensity); }
  void SetLightEnabled(int light, bool enabled) { this->Lights->SetLightEnabled(light, enabled); }
  void SetLightSetting(const char* name, double r, double g, double b, double intensity, int enabled)
  {
    this->Lights->SetLightSetting(name, r, g, b, intensity, enabled);
  }
  void ClearLightSettings() { this->Lights->ClearLightSettings(); }
  void ResetLights() { this->Lights->ResetLights(); }
  ///@}

  /// Also changed when the lights' settings change.
  vtkMTimeType GetMTime() override;

  ///@{
  /**
   * A light schedule animates lights over time: keyframes (time, light, r, g, b,
   * intensity, enabled), the light given by name or by index. Between keyframes color and
   * intensity are interpolated linearly, `enabled` holds from the previous keyframe. With
   * a schedule the filter reports its keyframe times as time steps, so a time slider (or
   * UpdateTimeStep) relights. Entries come from AddScheduleEntry or from a CSV file
   * (ScheduleFileName: CSV, names quoted where they hold commas, an optional header whose
   * first column is "time", columns as above, enabled optional as true/false, on/off,
   * yes/no or 1/0; re-read when the file changes).
   * Precedence: defaults, then SetLightSetting, then the schedule, then index settings.
   */
  void AddScheduleEntry(double time, const char* light, double r, double g, double b, double intensity, int enabled)
  {
    this->Lights->AddScheduleEntry(time, light, r, g, b, intensity, enabled);
  }
  void AddScheduleRow(double time, const char* light, double r, double g, double b, double intensity, const char* enabled)
  {
    this->Lights->AddScheduleRow(time, light, r, g, b, intensity, enabled);
  }
  void ClearSchedule() { this->Lights->ClearSchedule(); }
  void SetScheduleFileName(const char* file) { this->Lights->SetScheduleFileName(file); }
  char* GetScheduleFileName() { return this->Lights->GetScheduleFileName(); }
  /// Light scenes (vtkRadiosityLights::SetLightScenesFileName, SetLightScene).
  void SetLightScenesFileName(const char* file) { this->Lights->SetLightScenesFileName(file); }
  char* GetLightScenesFileName() { return this->Lights->GetLightScenesFileName(); }
  void SetLightScene(const char* scene) { this->Lights->SetLightScene(scene); }
  const char* GetLightScene() { return this->Lights->GetLightScene(); }
  /// The scenes the file defines, once an update has read it.
  int GetNumberOfLightScenes() { return this->Lights->GetNumberOfLightScenes(); }
  const char* GetLightSceneName(int i) { return this->Lights->GetLightSceneName(i); }
  int GetNumberOfScheduleEntries() const { return this->Lights->GetNumberOfScheduleEntries(); }
  ///@}

  ///@{
  /// Multiplier applied before clamping to display colors. 0 (the default): metered as a
  /// camera would (radiosity::MeteredExposure: the brightest 1 % of the surfaces that do
  /// not emit at 80 % of white), once per input, on the scene with its lights at their
  /// defaults: a light turned up brightens the picture, an animation keeps one exposure
  /// (where the defaults light nothing, the result itself is metered); the value used is in the output's
  /// field array `Exposure` and GetExposureInUse. A negative or NaN one is an error at the
  /// update.
  vtkSetMacro(Exposure, double);
  static double GetExposureMinValue() { return 0.0; }
  static double GetExposureMaxValue() { return VTK_DOUBLE_MAX; }
  vtkGetMacro(Exposure, double);
  double GetExposureInUse() const { return this->ExposureInUse; }
  ///@}

  ///@{
  /// Factor on indirect light (needs the solver's SeparateDirect output). Default 1.
  vtkSetMacro(IndirectScale, double); // checked at the update as Exposure is
  static double GetIndirectScaleMinValue() { return 0.0; }
  static double GetIndirectScaleMaxValue() { return VTK_DOUBLE_MAX; }
  vtkGetMacro(IndirectScale, double);
  ///@}

  ///@{
  /// Work of the last execution for the moving lights: shadow rays and seconds (0 without).
  vtkGetMacro(LastMovingRays, long long);
  vtkGetMacro(LastMovingSeconds, double);
  /// True when the moving lights' ray scene and geometry were the solver's, kept for its
  /// output (vtkRadiosityPreparedScenes), rather than prepared again here.
  vtkGetMacro(LastMovingSceneReused, bool);
  ///@}

  ///@{
  /// The lights found by the last execution and their effective settings.
  int GetNumberOfLights() const;
  /// How many lights have a setting by name of their own (the rest keep their defaults).
  int GetNumberOfLightSettings() const;
  const char* GetLightName(int light) const;
  /// The names as a string array (ParaView's LightNamesInfo).
  vtkStringArray* GetLightNames();
  /// Six strings per light in the LightSettings layout (name, red, green, blue,
  /// intensity, enabled 1/0), with the values in effect: defaults included, so that
  /// ParaView's LightSettingsInfo reads back what the filter used.
  vtkStringArray* GetLightSettingsInfo();
  void GetLightColor(int light, double rgb[3]) const;
  double GetLightIntensity(int light) const;
  bool GetLightEnabled(int light) const;
  ///@}

protected:
  vtkRadiosityRelight();
  ~vtkRadiosityRelight() override;
  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int Execute(const Run& run) override;
  void BeforeRun(const Run& run) override;
  bool GuardsInput(const Run& run) override;
  int FillInputPortInformation(int port, vtkInformation* info) override;

private:
  vtkRadiosityRelight(const vtkRadiosityRelight&) = delete;
  void operator=(const vtkRadiosityRelight&) = delete;

  struct Internals;
  std::unique_ptr<Internals> Internal; ///< the lights the last execution resolved
  vtkSmartPointer<vtkRadiosityLights> Lights;
  vtkSmartPointer<vtkStringArray> NamesInfo;
  vtkSmartPointer<vtkStringArray> SettingsInfo;
  /// The field arrays LightColors (color x intensity) and LightEnabled, per light.
  void AddSettingsInUse(vtkPolyData* output);
  /// Relights `input` (with its moving lights and dynamic objects, either may be null)
  /// into `output`; 0 with the error reported when it cannot.
  int Relight(vtkPolyData* input, vtkPolyData* movers, vtkPolyData* dynamic, double time, vtkPolyData* output);
  vtkRadiosityMovingScene* Moving = nullptr; ///< scene and Embree shader, rebuilt only when inputs change
  /// The weights of the lights `relit` read at `time` (settings, schedule, defaults); "" or
  /// why they are invalid. Keeps the names and settings in effect for the Info properties.
  std::string ResolveWeights(const vtkRadiosityRelitInput& relit, double time, std::vector<double>& weights);
  /// The exposure metered on `input` with its lights at their defaults, once per input;
  /// `current` (the result, of the cells where `relit` has them) where they light nothing.
  double MeterAtDefaults(const vtkRadiosityRelitInput& relit, vtkPolyData* input, vtkFloatArray* current);
  /// The weighted sum of what `relit` read into `points` and `cells` (either may be null),
  /// plus the moving lights; "" or the problem.
  std::string Combine(const vtkRadiosityRelitInput& relit, vtkPolyData* input, vtkPolyData* movers,
    vtkPolyData* dynamic, const std::vector<double>& weights, vtkFloatArray* points, vtkFloatArray* cells);
  bool AddMovingLights(vtkPolyData* scene, vtkPolyData* lights, vtkPolyData* dynamic,
    vtkFloatArray* pointResult, vtkFloatArray* cellResult, std::string& error);
  long long LastMovingRays = 0;
  double LastMovingSeconds = 0;
  bool LastMovingSceneReused = false;
  double Exposure = 0.0;
  double ExposureInUse = 1.0;
  double IndirectScale = 1.0;
};

#endif
