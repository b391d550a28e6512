// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
// What the gallery examples that antialias files share (AntialiasImage.cxx, BatchDirectory.cxx):
// reading and writing image files with VTK's own readers and writers, and the --preset
// argument. The `mlaa` tool reads and writes with OpenImageIO instead, for more formats and
// hostile files.
#ifndef GalleryImageFiles_h
#define GalleryImageFiles_h

#include "vtkBMPWriter.h"
#include "vtkAlgorithmOutput.h"
#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkImageReader2.h"
#include "vtkImageReader2Factory.h"
#include "vtkImageWriter.h"
#include "vtkJPEGWriter.h"
#include "vtkMLAAOptions.h"
#include "vtkPNGWriter.h"
#include "vtkPNMWriter.h"
#include "vtkSmartPointer.h"
#include "vtksys/SystemTools.hxx"

#include <cstdio>
#include <iostream>
#include <string>

namespace gallery
{
// Applies the preset `name` (low, medium, high, ultra, max) to `options`; false (and a message)
// for an unknown name.
inline bool SetPreset(vtkMLAAOptions* options, const char* name)
{
  const int preset = vtkMLAAOptions::GetPresetFromString(name);
  if (preset < 0)
  {
    std::cerr << name << ": not a preset (low, medium, high, ultra, max)\n";
    return false;
  }
  options->SetPreset(preset);
  return true;
}

// The reader that recognises the file's contents (PNG, JPEG, BMP, PNM, ...) and its extension,
// or null. Both, because some readers cannot tell their format from the contents (a TGA file
// has no signature, so VTK's TGA reader claims any file).
inline vtkSmartPointer<vtkImageReader2> ReaderFor(const std::string& path)
{
  vtkSmartPointer<vtkImageReader2> reader;
  reader.TakeReference(vtkImageReader2Factory::CreateImageReader2(path.c_str()));
  if (!reader)
  {
    return nullptr;
  }
  const std::string ext =
    vtksys::SystemTools::LowerCase(vtksys::SystemTools::GetFilenameLastExtension(path));
  const std::string known = vtksys::SystemTools::LowerCase(reader->GetFileExtensions());
  if (ext.empty() || (" " + known + " ").find(" " + ext + " ") == std::string::npos)
  {
    return nullptr;
  }
  reader->SetFileName(path.c_str());
  return reader;
}

// A writer for the file name's extension (.png, .jpg/.jpeg, .bmp, .pnm/.ppm/.pgm), or null.
// Not TIFF: VTK 9.1's TIFF reader does not return what its TIFF writer wrote (rows come back
// in another order), so a TIFF would not survive the trip; the `mlaa` tool handles TIFF.
inline vtkSmartPointer<vtkImageWriter> WriterFor(const std::string& path)
{
  const std::string ext =
    vtksys::SystemTools::LowerCase(vtksys::SystemTools::GetFilenameLastExtension(path));
  if (ext == ".png")
    return vtkSmartPointer<vtkPNGWriter>::New();
  if (ext == ".jpg" || ext == ".jpeg")
    return vtkSmartPointer<vtkJPEGWriter>::New();
  if (ext == ".bmp")
    return vtkSmartPointer<vtkBMPWriter>::New();
  if (ext == ".pnm" || ext == ".ppm" || ext == ".pgm")
    return vtkSmartPointer<vtkPNMWriter>::New();
  return nullptr;
}

// VTK algorithms report errors as ErrorEvent (and print them), they do not throw; and some
// writers only warn when they write nothing (vtkPNGWriter given float pixels). An ErrorCounter
// observes the objects given to Watch and counts their errors and warnings, so that a program
// can tell that an update failed.
class ErrorCounter
{
public:
  ErrorCounter()
  {
    this->Callback->SetClientData(this);
    this->Callback->SetCallback([](vtkObject*, unsigned long, void* self, void* message) {
      ++static_cast<ErrorCounter*>(self)->Count;
      std::cerr << static_cast<const char*>(message) << "\n";
    });
  }
  void Watch(vtkObject* object)
  {
    object->AddObserver(vtkCommand::ErrorEvent, this->Callback);
    object->AddObserver(vtkCommand::WarningEvent, this->Callback);
  }
  int Count = 0;

private:
  vtkSmartPointer<vtkCallbackCommand> Callback = vtkSmartPointer<vtkCallbackCommand>::New();
};

// Writes the output of `port` to `path` in the format of its extension, through a temporary
// file in the same directory that is renamed when complete, so that a failure never leaves a
// half-written `path` (nor replaces an existing one). Returns false (and reports why) on failure.
inline bool WriteImage(vtkAlgorithmOutput* port, const std::string& path, ErrorCounter& errors)
{
  vtkSmartPointer<vtkImageWriter> writer = WriterFor(path);
  if (!writer)
  {
    std::cerr << path << ": unknown extension (use .png, .jpg, .bmp or .pnm)\n";
    return false;
  }
  const std::string directory = vtksys::SystemTools::GetFilenamePath(path);
  // The temporary name keeps the extension (some writers look at it).
  const std::string temporary = (directory.empty() ? "" : directory + "/") + "." +
    vtksys::SystemTools::GetFilenameName(path) + ".partial" +
    vtksys::SystemTools::GetFilenameLastExtension(path);
  const int errorsBefore = errors.Count;
  errors.Watch(writer);
  writer->SetInputConnection(port);
  writer->SetFileName(temporary.c_str());
  writer->Write(); // updates the pipeline upstream: read, antialias, write
  if (errors.Count == errorsBefore && writer->GetErrorCode() == 0 &&
    std::rename(temporary.c_str(), path.c_str()) == 0)
  {
    return true;
  }
  vtksys::SystemTools::RemoveFile(temporary);
  std::cerr << path << ": not written\n";
  return false;
}
} // namespace gallery

#endif
