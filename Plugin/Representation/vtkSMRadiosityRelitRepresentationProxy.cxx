#include "vtkSMRadiosityRelitRepresentationProxy.h"
#include "vtkSMRadiosityRelightProxy.h"

#include "vtkObjectFactory.h"

vtkStandardNewMacro(vtkSMRadiosityRelitRepresentationProxy);

vtkSMRadiosityRelitRepresentationProxy::vtkSMRadiosityRelitRepresentationProxy() = default;

vtkSMRadiosityRelitRepresentationProxy::~vtkSMRadiosityRelitRepresentationProxy() = default;

void vtkSMRadiosityRelitRepresentationProxy::ViewUpdated(vtkSMProxy* view)
{
  this->Superclass::ViewUpdated(view);
  vtkSMRadiosityRelightProxy::ShowDataLights(this, this->Copied);
}

vtkPVXMLElement* vtkSMRadiosityRelitRepresentationProxy::SaveXMLState(
  vtkPVXMLElement* root, vtkSMPropertyIterator* iter)
{
  return vtkSMRadiosityRelightProxy::SaveWithoutCopy(
    this, this->Copied, [&]() { return this->Superclass::SaveXMLState(root, iter); });
}

void vtkSMRadiosityRelitRepresentationProxy::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
