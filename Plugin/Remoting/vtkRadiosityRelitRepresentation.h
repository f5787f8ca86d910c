/**
 * @class   vtkRadiosityRelitRepresentation
 * @brief   ParaView's "Relit Surface": the light-tagged solutions relit on the GPU
 *
 * Shows the solver's output through vtkRadiosityRelightMapper. The light settings and
 * the exposure are display properties: a change renders the next frame with new
 * uniforms, without Apply, without running the pipeline and without sending the data
 * again.
 *
 * A light schedule, as the relight filter's, is evaluated at the view's time.
 *
 * With ComputedColors on ("Relit Colors", the relight filter's output) it shows the
 * input's DisplayColors as they are instead: the filter already relit and exposed them.
 */
#ifndef vtkRadiosityRelitRepresentation_h
#define vtkRadiosityRelitRepresentation_h

#include "vtkPVDataRepresentation.h"
#include "vtkRadiosityRemotingModule.h" // for export macro
#include "vtkSmartPointer.h"                    // for members

class vtkActor;
class vtkPolyData;
class vtkPolyDataMapper;
class vtkRadiosityRelightMapper;
class vtkStringArray;

class VTKRADIOSITYREMOTING_EXPORT vtkRadiosityRelitRepresentation : public vtkPVDataRepresentation
{
public:
  static vtkRadiosityRelitRepresentation* New();
  vtkTypeMacro(vtkRadiosityRelitRepresentation, vtkPVDataRepresentation);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The lights, as the relight filter's LightSettings (name, r, g, b, intensity, enabled).
  void SetLightSetting(const char* name, double r, double g, double b, double intensity, int enabled);
  void ClearLightSettings();
  ///@}

  ///@{
  /// The lights' schedule, as the relight filter's: keyframes one by one and a CSV file,
  /// evaluated at the view's time (a time step of the view relights the picture).
  void AddScheduleEntry(double time, const char* light, double r, double g, double b, double intensity, int enabled);
  void AddScheduleRow(double time, const char* light, double r, double g, double b, double intensity, const char* enabled);
  void ClearSchedule();
  void SetScheduleFileName(const char* file);
  /// Light scenes, as vtkRadiosityLights has them.
  void SetLightScenesFileName(const char* file);
  void SetLightScene(const char* scene);
  ///@}

  /// The view's time also sets the time of the lights' schedule.
  void SetUpdateTime(double time) override;

  /// Multiplier before the clamp to display colors.
  void SetRelightExposure(double exposure);

  /// Show the input's DisplayColors unchanged (unlit, not through a color map) rather
  /// than relight its solutions.
  void SetComputedColors(int computed);

  ///@{
  /// The lights of the shown data, and the settings in effect (a row per light, as LightSettings).
  vtkStringArray* GetLightNames();
  vtkStringArray* GetLightSettingsInfo();
  ///@}

  vtkRadiosityRelightMapper* GetMapper();

  int ProcessViewRequest(vtkInformationRequestKey* request, vtkInformation* inInfo, vtkInformation* outInfo) override;
  void SetVisibility(bool visible) override;

protected:
  vtkRadiosityRelitRepresentation();
  ~vtkRadiosityRelitRepresentation() override;
  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  bool AddToView(vtkView* view) override;
  bool RemoveFromView(vtkView* view) override;

private:
  vtkRadiosityRelitRepresentation(const vtkRadiosityRelitRepresentation&) = delete;
  void operator=(const vtkRadiosityRelitRepresentation&) = delete;

  vtkSmartPointer<vtkRadiosityRelightMapper> Mapper;
  vtkSmartPointer<vtkPolyDataMapper> ColorsMapper;
  vtkSmartPointer<vtkActor> Actor;
  vtkSmartPointer<vtkPolyData> Data; ///< the input as last updated, delivered to the view
  vtkSmartPointer<vtkStringArray> NamesInfo;
  vtkSmartPointer<vtkStringArray> SettingsInfo;
};

#endif
