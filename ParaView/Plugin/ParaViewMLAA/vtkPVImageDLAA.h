// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkPVImageDLAA
 * @brief   vtkImageDLAA on a chosen point array, for ParaView's DLAAAntialiasing filter.
 *
 * vtkImageDLAA antialiases the active point scalars of its input. ParaView's pipelines often
 * carry the array to antialias as a non-active one (a Calculator's result, a reader's second
 * array), and users pick arrays by name, so this subclass antialiases the point array chosen by
 * SetInputArrayToProcess(0, ...) (by default the active scalars, as vtkImageDLAA): it hands the
 * superclass a shallow copy of the input whose active scalars are that array, and announces the
 * array's type and components as the output's in RequestInformation. Everything else, options,
 * padding of the requested extent and checks included, is vtkImageDLAA's.
 *
 * @sa vtkImageDLAA vtkDLAAOptions
 */

#ifndef vtkPVImageDLAA_h
#define vtkPVImageDLAA_h

#include "vtkImageDLAA.h"
#include "vtkParaViewMLAAModule.h" // For export macro

class VTKPARAVIEWMLAA_EXPORT vtkPVImageDLAA : public vtkImageDLAA
{
public:
  static vtkPVImageDLAA* New();
  vtkTypeMacro(vtkPVImageDLAA, vtkImageDLAA);
  void PrintSelf(ostream& os, vtkIndent indent) override;

protected:
  vtkPVImageDLAA() = default;
  ~vtkPVImageDLAA() override = default;

  int RequestInformation(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;
  int RequestData(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

private:
  vtkPVImageDLAA(const vtkPVImageDLAA&) = delete;
  void operator=(const vtkPVImageDLAA&) = delete;
};

#endif
