#include "vtkMLAAOptions.h"

#include "vtkObjectFactory.h"

#include <cstring>

vtkStandardNewMacro(vtkMLAAOptions);

namespace
{
const char* const EdgeDetectionNames[] = { "luma", "color", "depth" };
const char* const DebugOutputNames[] = { "none", "edges", "weights" };

template <int N>
int IndexOfName(const char* const (&names)[N], const char* name)
{
  if (name)
  {
    for (int i = 0; i < N; ++i)
    {
      if (std::strcmp(names[i], name) == 0)
      {
        return i;
      }
    }
  }
  return -1;
}
}

//------------------------------------------------------------------------------
const char* vtkMLAAOptions::GetEdgeDetectionAsString(int mode)
{
  return (mode >= LUMA && mode <= DEPTH) ? EdgeDetectionNames[mode] : "unknown";
}

//------------------------------------------------------------------------------
int vtkMLAAOptions::GetEdgeDetectionFromString(const char* name)
{
  return IndexOfName(EdgeDetectionNames, name);
}

//------------------------------------------------------------------------------
const char* vtkMLAAOptions::GetDebugOutputAsString(int output)
{
  return (output >= NO_DEBUG_OUTPUT && output <= BLENDING_WEIGHTS) ? DebugOutputNames[output]
                                                                   : "unknown";
}

//------------------------------------------------------------------------------
int vtkMLAAOptions::GetDebugOutputFromString(const char* name)
{
  return IndexOfName(DebugOutputNames, name);
}

//------------------------------------------------------------------------------
void vtkMLAAOptions::DeepCopy(vtkMLAAOptions* other)
{
  if (!other || other == this)
  {
    return;
  }
  this->SetThreshold(other->Threshold);
  this->SetLocalContrastFactor(other->LocalContrastFactor);
  this->SetEdgeDetection(other->EdgeDetection);
  this->SetMaxSearchSteps(other->MaxSearchSteps);
  this->SetDebugOutput(other->DebugOutput);
  this->SetDiagonalDetection(other->DiagonalDetection);
  this->SetDominantDirectionBlending(other->DominantDirectionBlending);
  this->SetPremultipliedAlpha(other->PremultipliedAlpha);
}

//------------------------------------------------------------------------------
bool vtkMLAAOptions::Assign(vtkObject* owner, vtkMLAAOptions*& member, vtkMLAAOptions* options)
{
  if (options && options == member)
  {
    return false;
  }
  vtkMLAAOptions* old = member;
  if (options)
  {
    options->Register(owner);
    member = options;
  }
  else
  {
    member = vtkMLAAOptions::New(); // owned by `owner`: the reference New gives
  }
  if (old)
  {
    old->UnRegister(owner);
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkMLAAOptions::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Threshold: " << this->Threshold << "\n";
  os << indent << "LocalContrastFactor: " << this->LocalContrastFactor << "\n";
  os << indent << "EdgeDetection: " << GetEdgeDetectionAsString(this->EdgeDetection) << "\n";
  os << indent << "MaxSearchSteps: " << this->MaxSearchSteps << "\n";
  os << indent << "DebugOutput: " << GetDebugOutputAsString(this->DebugOutput) << "\n";
  os << indent << "DiagonalDetection: " << (this->DiagonalDetection ? "On" : "Off") << "\n";
  os << indent << "DominantDirectionBlending: " << (this->DominantDirectionBlending ? "On" : "Off")
     << "\n";
  os << indent << "PremultipliedAlpha: " << (this->PremultipliedAlpha ? "On" : "Off") << "\n";
}
