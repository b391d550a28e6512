// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkPVImageMLAA
 * @brief   vtkImageMLAA on a chosen point array, for ParaView's MLAAAntialiasing filter.
 *
 * vtkImageMLAA antialiases the active point scalars of its input. ParaView's pipelines often
 * carry the array to antialias as a non-active one (a Calculator's result, a reader's second
 * array), and users pick arrays by name, so this subclass antialiases the point array chosen by
 * SetInputArrayToProcess(0, ...) (by default the active scalars, as vtkImageMLAA): it hands the
 * superclass a shallow copy of the input whose active scalars are that array, and announces the
 * array's type and components as the output's in RequestInformation. Everything else, options,
 * padding of the requested extent and checks included, is vtkImageMLAA's.
 *
 * The value range (vtkImageAntialiasingAlgorithm::SetValueRange) is given as two settings that
 * ParaView may push in either order: UseValueRange and ValueRangeSetting.
 *
 * @sa vtkImageMLAA vtkPVMLAAOptions
 */

#ifndef vtkPVImageMLAA_h
#define vtkPVImageMLAA_h

#include "vtkImageMLAA.h"
#include "vtkParaViewMLAAModule.h" // For export macro

class VTKPARAVIEWMLAA_EXPORT vtkPVImageMLAA : public vtkImageMLAA
{
public:
  static vtkPVImageMLAA* New();
  vtkTypeMacro(vtkPVImageMLAA, vtkImageMLAA);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * While UseValueRange is on (default off), the filter normalises values by ValueRangeSetting
   * (default [0, 1]) instead of its scalar type's default range (SetValueRange,
   * SetValueRangeToTypeDefault). A range that is not finite with lo < hi is reported as an
   * error when the filter runs.
   */
  void SetUseValueRange(bool use);
  vtkGetMacro(UseValueRange, bool);
  void SetValueRangeSetting(double lo, double hi);
  vtkGetVector2Macro(ValueRangeSetting, double);
  ///@}

protected:
  vtkPVImageMLAA() = default;
  ~vtkPVImageMLAA() override = default;

  int RequestInformation(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;
  int RequestData(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

private:
  bool UseValueRange = false;
  double ValueRangeSetting[2] = { 0.0, 1.0 };

  vtkPVImageMLAA(const vtkPVImageMLAA&) = delete;
  void operator=(const vtkPVImageMLAA&) = delete;
};

#endif
