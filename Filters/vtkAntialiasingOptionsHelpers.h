// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file   vtkAntialiasingOptionsHelpers.h
 * @brief  Helpers shared by the option classes vtkMLAAOptions and vtkDLAAOptions (internal).
 *
 * IndexOfName finds a name in a table of names (-1 if absent or null).
 *
 * vtkImageMLAA, vtkOpenGLMLAAPass, vtkImageDLAA and vtkOpenGLDLAAPass each own an options
 * object that is never null. AssignOwned makes `member` refer to `options` (registered to
 * `owner`), or to a fresh default object when `options` is null, releasing the previous one, and
 * returns true when `member` changed. Not installed.
 */
#ifndef vtkAntialiasingOptionsHelpers_h
#define vtkAntialiasingOptionsHelpers_h

#include "vtkObject.h"

#include <cstring>

namespace vtkAntialiasingInternal
{
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

template <typename T>
bool AssignOwned(vtkObject* owner, T*& member, T* options)
{
  if (options && options == member)
  {
    return false;
  }
  T* old = member;
  if (options)
  {
    options->Register(owner);
    member = options;
  }
  else
  {
    member = T::New(); // owned by `owner`: the reference New gives
  }
  if (old)
  {
    old->UnRegister(owner);
  }
  return true;
}
}

#endif
