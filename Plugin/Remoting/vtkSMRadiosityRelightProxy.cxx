#include "vtkSMRadiosityRelightProxy.h"

#include "vtkObjectFactory.h"
#include "vtkSMStringVectorProperty.h"

vtkStandardNewMacro(vtkSMRadiosityRelightProxy);

namespace
{
bool Showing = true;

/// Sets a property's values without its ModifiedEvent. ParaView keeps the switch for its
/// own classes (protected); a member pointer taken through a subclass may call it.
struct QuietProperty : vtkSMStringVectorProperty
{
  static void Set(vtkSMStringVectorProperty* property, const std::vector<std::string>& values)
  {
    bool (vtkSMProperty::*block)(bool) = &QuietProperty::SetBlockModifiedEvents;
    const bool blocked = (property->*block)(true);
    property->SetElements(values);
    (property->*block)(blocked);
  }
};

vtkSMStringVectorProperty* Settings(vtkSMProxy* proxy)
{
  return vtkSMStringVectorProperty::SafeDownCast(proxy->GetProperty("LightSettings"));
}
} // namespace

vtkSMRadiosityRelightProxy::vtkSMRadiosityRelightProxy() = default;

vtkSMRadiosityRelightProxy::~vtkSMRadiosityRelightProxy() = default;

void vtkSMRadiosityRelightProxy::SetShowDataLights(bool show)
{
  Showing = show;
}

vtkPVXMLElement* vtkSMRadiosityRelightProxy::SaveXMLState(vtkPVXMLElement* root, vtkSMPropertyIterator* iter)
{
  vtkSMStringVectorProperty* settings = Settings(this);
  const bool copy = settings && !this->Copied.empty() && settings->GetElements() == this->Copied;
  if (copy)
  {
    QuietProperty::Set(settings, {});
  }
  vtkPVXMLElement* saved = this->Superclass::SaveXMLState(root, iter);
  if (copy)
  {
    QuietProperty::Set(settings, this->Copied);
  }
  return saved;
}

void vtkSMRadiosityRelightProxy::PostUpdateData(bool usingCache)
{
  this->Superclass::PostUpdateData(usingCache);
  vtkSMStringVectorProperty* settings = Settings(this);
  auto* info = settings ? vtkSMStringVectorProperty::SafeDownCast(settings->GetInformationProperty()) : nullptr;
  if (!Showing || !info || settings->GetElements() != this->Copied)
  {
    return; // the user's own settings stay as they are
  }
  this->UpdatePropertyInformation(info);
  if (info->GetElements() == this->Copied)
  {
    return;
  }
  this->Copied = info->GetElements();
  // Unannounced, so the proxy does not push the rows to the filter as settings of its own
  // (which would pin today's defaults) and the GUI does not ask for an Apply.
  QuietProperty::Set(settings, this->Copied);
}

void vtkSMRadiosityRelightProxy::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Copied: " << this->Copied.size() << " strings of light settings\n";
}
