// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
// What vtkPVImageMLAA and vtkPVImageDLAA share: running an antialiasing filter of the main
// project, which reads the active point scalars, on the point array chosen with
// SetInputArrayToProcess(0, ...), and the ValueRange properties. Internal to the plugin.
#ifndef vtkPVChosenArray_h
#define vtkPVChosenArray_h

#include <functional>

class vtkAlgorithm;
class vtkImageAntialiasingAlgorithm;
class vtkInformation;
class vtkInformationVector;

namespace vtkPVChosenArray
{
// For RequestInformation, after the filter's own: announces the chosen array's type and
// components as the output's scalars (when an array is chosen by name and its information is
// known).
void AnnounceScalars(
  vtkAlgorithm* algorithm, vtkInformationVector** inputVector, vtkInformationVector* outputVector);

// For RequestData: calls `requestData` with the input information vectors, in which port 0's
// image is replaced, when an array other than the active scalars is chosen, by a shallow copy
// whose active scalars are that array. Returns what `requestData` returns, or 0 after an error
// (no point array of the chosen name).
int RequestData(vtkAlgorithm* algorithm, vtkInformationVector** inputVector,
  vtkInformationVector* outputVector,
  const std::function<int(vtkInformationVector**)>& requestData);

// The UseValueRange and ValueRange properties, which ParaView sets in either order: the filter's
// ValueRange becomes `range` while `use` is on and its type's default range otherwise.
void ApplyValueRange(vtkImageAntialiasingAlgorithm* filter, bool use, const double range[2]);
}

#endif
