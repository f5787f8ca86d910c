#include "vtkSMRadiosityRelightProxy.h"

#include "vtkObjectFactory.h"
#include "vtkSMStringVectorProperty.h"

vtkStandardNewMacro(vtkSMRadiosityRelightProxy);

namespace
{
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
} // namespace

vtkSMRadiosityRelightProxy::vtkSMRadiosityRelightProxy() = default;

vtkSMRadiosityRelightProxy::~vtkSMRadiosityRelightProxy() = default;

namespace
{
bool Showing = true;
}

void vtkSMRadiosityRelightProxy::SetShowDataLights(bool show)
{
  Showing = show;
}

std::vector<std::string> vtkSMRadiosityRelightProxy::QuietSet(
  vtkSMProxy* proxy, const std::vector<std::string>& from, const std::vector<std::string>& to)
{
  auto* settings = vtkSMStringVectorProperty::SafeDownCast(proxy->GetProperty("LightSettings"));
  if (!settings || from.empty() || settings->GetElements() != from)
  {
    return {};
  }
  QuietProperty::Set(settings, to);
  return from;
}

vtkPVXMLElement* vtkSMRadiosityRelightProxy::SaveXMLState(vtkPVXMLElement* root, vtkSMPropertyIterator* iter)
{
  return SaveWithoutCopy(this, this->Copied, [&]() { return this->Superclass::SaveXMLState(root, iter); });
}

void vtkSMRadiosityRelightProxy::ShowDataLights(vtkSMProxy* proxy, std::vector<std::string>& copied)
{
  if (!Showing)
  {
    return;
  }
  auto* settings = vtkSMStringVectorProperty::SafeDownCast(proxy->GetProperty("LightSettings"));
  auto* info = settings ? vtkSMStringVectorProperty::SafeDownCast(settings->GetInformationProperty()) : nullptr;
  if (!info || settings->GetElements() != copied)
  {
    return; // the user's own settings stay as they are
  }
  proxy->UpdatePropertyInformation(info);
  if (info->GetElements() == copied)
  {
    return;
  }
  copied = info->GetElements();
  // Unannounced, so the proxy does not push the rows to the filter as settings of its own
  // (which would pin today's defaults) and the GUI does not ask for an Apply.
  QuietProperty::Set(settings, copied);
}

void vtkSMRadiosityRelightProxy::PostUpdateData(bool usingCache)
{
  this->Superclass::PostUpdateData(usingCache);
  ShowDataLights(this, this->Copied);
}

void vtkSMRadiosityRelightProxy::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Copied: " << this->Copied.size() / 6 << " light rows\n";
}
