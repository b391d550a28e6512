// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
// Tests of the `mlaa` command-line tool, one case per ctest test:
//
//   TestMLAATool CASE MLAA_EXECUTABLE SCRATCH_DIRECTORY RANDOM_CASES MLAA_TEST_HOOKS_EXECUTABLE
//   TestMLAATool --check-listed CASE...   fails unless CASE... are exactly the registered cases
//
// Each case writes its input images with OpenImageIO (row by row, with code of its own rather
// than the tool's), runs the tool as a child process, and checks the exit status, stdout,
// stderr and the files left behind. Antialiased images are compared exactly with vtkImageMLAA
// run here on the same pixels; the checks that antialiasing happened at all (edge pixels
// change, flat regions do not) are separate, as VTK's loose regression comparison cannot show
// it (see the project's ENVIRONMENT notes).
//
// The cases are in the TestMLAATool*.cxx files of this directory, by group, and register
// themselves by name (mlaaToolTestSupport.h); CMakeLists.txt lists the names once.
#include "mlaaToolTestSupport.h"

#include <cstdlib>
#include <iostream>

using namespace mlaaToolTest;

namespace
{
// The cases given (CMakeLists.txt's list) against the registered ones: each missing from
// either is named.
int CheckListed(int argc, char* argv[])
{
  const std::set<std::string> listed(argv + 2, argv + argc);
  int status = EXIT_SUCCESS;
  for (const auto& entry : Cases())
  {
    if (!listed.count(entry.first))
    {
      std::cerr << "case " << entry.first << " is registered but not listed in CMakeLists.txt"
                << std::endl;
      status = EXIT_FAILURE;
    }
  }
  for (const std::string& name : listed)
  {
    if (!Cases().count(name))
    {
      std::cerr << "case " << name << " is listed in CMakeLists.txt but not registered"
                << std::endl;
      status = EXIT_FAILURE;
    }
  }
  std::cout << Cases().size() << " cases registered, " << listed.size() << " listed" << std::endl;
  return status;
}
} // namespace

//------------------------------------------------------------------------------
int main(int argc, char* argv[])
{
  if (argc >= 2 && std::string(argv[1]) == "--check-listed")
  {
    return CheckListed(argc, argv);
  }
  if (argc != 6)
  {
    std::cerr << "Usage: " << argv[0]
              << " CASE MLAA_EXECUTABLE SCRATCH_DIRECTORY RANDOM_CASES MLAA_TEST_HOOKS_EXECUTABLE"
              << std::endl;
    return EXIT_FAILURE;
  }
  const auto found = Cases().find(argv[1]);
  if (found == Cases().end())
  {
    std::cerr << "Unknown case " << argv[1] << std::endl;
    return EXIT_FAILURE;
  }

  Where().Tool = argv[2];
  Where().RandomCases = std::atoi(argv[4]);
  Where().HookedTool = argv[5];
  const fs::path scratch = argv[3];
  Where().Work = scratch / "work";
  Where().Logs = scratch / "logs";
  fs::remove_all(scratch);
  fs::create_directories(Where().Work);
  fs::create_directories(Where().Logs);
  try
  {
    found->second();
  }
  catch (const SkippedCase& skipped)
  {
    std::cout << "skipped: " << skipped.what() << std::endl;
    if (!Failures())
    {
      return SkipStatus;
    }
  }
  catch (const std::exception& e)
  {
    std::cerr << "exception: " << e.what() << std::endl;
    ++Failures();
  }
  OIIO::geterror();
  return Result();
}
