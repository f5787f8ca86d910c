/**
 * @class   vtkSMRadiosityRelitRepresentationProxy
 * @brief   Relit Surface's client-side proxy: RelitLightSettings read back the data's lights
 *
 * After each view update, copies the settings in effect into the light settings as long
 * as nobody has set them (see vtkSMRadiosityRelightProxy::ShowDataLights).
 */
#ifndef vtkSMRadiosityRelitRepresentationProxy_h
#define vtkSMRadiosityRelitRepresentationProxy_h

#include "vtkRadiosityRepresentationModule.h" // for export macro
#include "vtkSMRepresentationProxy.h"

#include <string> // for members
#include <vector> // for members

class VTKRADIOSITYREPRESENTATION_EXPORT vtkSMRadiosityRelitRepresentationProxy : public vtkSMRepresentationProxy
{
public:
  static vtkSMRadiosityRelitRepresentationProxy* New();
  vtkTypeMacro(vtkSMRadiosityRelitRepresentationProxy, vtkSMRepresentationProxy);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  void ViewUpdated(vtkSMProxy* view) override;
  using Superclass::SaveXMLState;
  vtkPVXMLElement* SaveXMLState(vtkPVXMLElement* root, vtkSMPropertyIterator* iter) override;

protected:
  vtkSMRadiosityRelitRepresentationProxy();
  ~vtkSMRadiosityRelitRepresentationProxy() override;

private:
  vtkSMRadiosityRelitRepresentationProxy(const vtkSMRadiosityRelitRepresentationProxy&) = delete;
  void operator=(const vtkSMRadiosityRelitRepresentationProxy&) = delete;

  std::vector<std::string> Copied;
};

#endif
