// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkSIMLAAViewProperty
 * @brief   The server side of the antialiasing properties that the plugin adds to ParaView's
 *          RenderView proxy: they reach vtkMLAARenderView objects only.
 *
 * The plugin's XML extends the "RenderView" proxy, and every proxy defined on top of it inherits
 * the extension: ParaView's Eye-Dome Lighting, orthographic-slice and multi-slice views, and
 * other plugins' views, whose objects are not vtkMLAARenderView (the object-factory override
 * only changes what vtkPVRenderView::New() makes). An ordinary property would invoke its command
 * on those objects too, and ParaView stops on the "could not find requested method" error. This
 * int-vector property (the si_class of AntialiasingMethod, AntialiasingKeepAlpha,
 * MLAALineLengths and their information properties) pushes and pulls only when the proxy's
 * object is a vtkMLAARenderView, and is inert otherwise.
 *
 * It also connects the view to the settings: when it reads its XML (the proxy's sub-proxies exist
 * by then) it gives a vtkMLAARenderView the objects of the proxy's "MLAAOptions" and
 * "DLAAOptions" sub-proxies (SetMLAAOptions, SetDLAAOptions), which a SubProxy "command" would
 * also invoke on every class.
 *
 * @sa vtkMLAARenderView vtkSIIntVectorProperty
 */

#ifndef vtkSIMLAAViewProperty_h
#define vtkSIMLAAViewProperty_h

#include "vtkParaViewMLAAModule.h" // For export macro
#include "vtkSIIntVectorProperty.h"

class vtkMLAARenderView;

class VTKPARAVIEWMLAA_EXPORT vtkSIMLAAViewProperty : public vtkSIIntVectorProperty
{
public:
  static vtkSIMLAAViewProperty* New();
  vtkTypeMacro(vtkSIMLAAViewProperty, vtkSIIntVectorProperty);
  void PrintSelf(ostream& os, vtkIndent indent) override;

protected:
  vtkSIMLAAViewProperty() = default;
  ~vtkSIMLAAViewProperty() override = default;

  bool Push(vtkSMMessage* message, int offset) override;
  bool Pull(vtkSMMessage* message) override;
  bool ReadXMLAttributes(vtkSIProxy* proxyhelper, vtkPVXMLElement* element) override;

private:
  vtkSIMLAAViewProperty(const vtkSIMLAAViewProperty&) = delete;
  void operator=(const vtkSIMLAAViewProperty&) = delete;
};

#endif
