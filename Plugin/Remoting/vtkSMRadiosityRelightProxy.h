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
 * colors, and the copy follows it. (Not for Relit Surface's RelitLightSettings: the
 * display's state is saved by ParaView's representation, which would keep the copy.)
 *
 * Not in the GUI, whose lights panel shows the settings in effect itself and stores only
 * what the user changes (the plugin's GUI part turns the copy off); and a copy is not
 * saved in a state file (it would come back as settings of the user's).
 */
#ifndef vtkSMRadiosityRelightProxy_h
#define vtkSMRadiosityRelightProxy_h

#include "vtkRadiosityRemotingModule.h" // for export macro
#include "vtkSMSourceProxy.h"

#include <string> // for members
#include <vector> // for members

class VTKRADIOSITYREMOTING_EXPORT vtkSMRadiosityRelightProxy : public vtkSMSourceProxy
{
public:
  static vtkSMRadiosityRelightProxy* New();
  vtkTypeMacro(vtkSMRadiosityRelightProxy, vtkSMSourceProxy);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Whether the data's lights are copied (on by default; the GUI turns it off).
  static void SetShowDataLights(bool show);

  /// Saves the state without Light Settings where they still hold only the copy.
  using Superclass::SaveXMLState;
  vtkPVXMLElement* SaveXMLState(vtkPVXMLElement* root, vtkSMPropertyIterator* iter) override;

protected:
  vtkSMRadiosityRelightProxy();
  ~vtkSMRadiosityRelightProxy() override;

  /// Copies LightSettingsInfo into Light Settings unless they differ from the last copy
  /// (anything else is the user's), without telling the filter.
  void PostUpdateData(bool usingCache) override;

private:
  vtkSMRadiosityRelightProxy(const vtkSMRadiosityRelightProxy&) = delete;
  void operator=(const vtkSMRadiosityRelightProxy&) = delete;

  /// What was last copied from the data: Light Settings still equal to it are not the user's.
  std::vector<std::string> Copied;
};

#endif
