// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkSIMLAAViewProperty.h"

#include "vtkDLAAOptions.h"
#include "vtkMLAAOptions.h"
#include "vtkMLAARenderView.h"
#include "vtkObjectFactory.h"
#include "vtkSIProxy.h"

vtkStandardNewMacro(vtkSIMLAAViewProperty);

namespace
{
// vtkSIProxy::GetSubSIProxy is protected (ParaView calls it for SubProxy commands only). A
// pointer to it taken in a class derived from vtkSIProxy may be called on any vtkSIProxy; this
// class is never instantiated.
class vtkSubProxyAccess : public vtkSIProxy
{
public:
  static vtkObjectBase* GetSubProxyObject(vtkSIProxy* proxy, const char* name)
  {
    vtkSIProxy* (vtkSIProxy::*get)(const char*) = &vtkSubProxyAccess::GetSubSIProxy;
    vtkSIProxy* sub = (proxy->*get)(name);
    return sub ? sub->GetVTKObject() : nullptr;
  }
};
}

//------------------------------------------------------------------------------
bool vtkSIMLAAViewProperty::ReadXMLAttributes(vtkSIProxy* proxyhelper, vtkPVXMLElement* element)
{
  auto* view = vtkMLAARenderView::SafeDownCast(proxyhelper->GetVTKObject());
  if (!view)
  {
    // The vector property's own reading pushes the default values: only the generic part.
    return this->vtkSIProperty::ReadXMLAttributes(proxyhelper, element);
  }
  if (!this->Superclass::ReadXMLAttributes(proxyhelper, element))
  {
    return false;
  }
  {
    // Setting the same objects again (each such property does it) changes nothing.
    if (auto* options = vtkMLAAOptions::SafeDownCast(
          vtkSubProxyAccess::GetSubProxyObject(proxyhelper, "MLAAOptions")))
    {
      view->SetMLAAOptions(options);
    }
    if (auto* options = vtkDLAAOptions::SafeDownCast(
          vtkSubProxyAccess::GetSubProxyObject(proxyhelper, "DLAAOptions")))
    {
      view->SetDLAAOptions(options);
    }
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkSIMLAAViewProperty::Push(vtkSMMessage* message, int offset)
{
  if (!vtkMLAARenderView::SafeDownCast(this->GetVTKObject()))
  {
    // A view of another class (derived from RenderView's proxy): it has no antialiasing of
    // ours. The value is kept in the property's state all the same.
    this->SaveValueToCache(message, offset);
    return true;
  }
  return this->Superclass::Push(message, offset);
}

//------------------------------------------------------------------------------
bool vtkSIMLAAViewProperty::Pull(vtkSMMessage* message)
{
  if (!vtkMLAARenderView::SafeDownCast(this->GetVTKObject()))
  {
    return true; // nothing to read: the information property keeps its default
  }
  return this->Superclass::Pull(message);
}

//------------------------------------------------------------------------------
void vtkSIMLAAViewProperty::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
