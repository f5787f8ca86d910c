/**
 * @class   vtkSMRadiosityRelightProxy
 * @brief   Radiosity Relight's client-side proxy: Light Settings read back the data's lights
 *
 * The relight filter keeps a light at its default (the solver's emission) until a row of
 * Light Settings names it. A script that reads `relight.LightSettings` after an update
 * wants the lights it is looking at, as a reader's array list does. After each update
 * this proxy copies the settings in effect (LightSettingsInfo) into Light Settings, as
 * long as nobody has set that property. The copy is not sent back to the filter, so the
 * lights stay at their defaults there: a new solve with new emission still shows its own
 * colors, and the copy follows it. vtkSMRadiosityRelitRepresentationProxy does the same for
 * Relit Surface's RelitLightSettings.
 */
#ifndef vtkSMRadiosityRelightProxy_h
#define vtkSMRadiosityRelightProxy_h

#include "vtkRadiosityRepresentationModule.h" // for export macro
#include "vtkSMSourceProxy.h"

#include <string> // for members
#include <vector> // for members

class VTKRADIOSITYREPRESENTATION_EXPORT vtkSMRadiosityRelightProxy : public vtkSMSourceProxy
{
public:
  static vtkSMRadiosityRelightProxy* New();
  vtkTypeMacro(vtkSMRadiosityRelightProxy, vtkSMSourceProxy);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Copies `proxy`'s LightSettingsInfo into its LightSettings unless they differ from
  /// `copied` (the last copy: anything else is the user's), without telling the filter.
  static void ShowDataLights(vtkSMProxy* proxy, std::vector<std::string>& copied);

protected:
  vtkSMRadiosityRelightProxy();
  ~vtkSMRadiosityRelightProxy() override;

  void PostUpdateData(bool usingCache) override;

private:
  vtkSMRadiosityRelightProxy(const vtkSMRadiosityRelightProxy&) = delete;
  void operator=(const vtkSMRadiosityRelightProxy&) = delete;

  /// What was last copied from the data: Light Settings still equal to it are not the user's.
  std::vector<std::string> Copied;
};

#endif
