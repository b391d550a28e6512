// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * Batches for the `mlaa` tool: `mlaa [options] --output-dir DIR INPUT...`.
 *
 * Each file of a batch is antialiased in a child process forked from the tool once it has
 * parsed its command line and built what every file shares (the area tables, OpenImageIO's
 * list of formats), so that files are processed side by side on every core without the start-up
 * of a new program per file, and everything the single-file tool promises holds per file
 * unchanged: the file's own stderr capture, its temporary output removed on a crash or a
 * signal, its one-line errors. A library that crashes on one file fails that file only.
 *
 * Each child's stderr goes to a file of its own, which the parent prints when the child is
 * done, in the order of the inputs, with the progress display (mlaaBatch.cxx): a bar that
 * updates in place on a terminal, one line per file otherwise, nothing with --quiet.
 */

#ifndef mlaaBatch_h
#define mlaaBatch_h

#include "mlaaError.h" // For mlaa::UsageError

#include <functional> // For std::function
#include <string>     // For std::string
#include <vector>     // For std::vector

namespace mlaa
{
/** One file of a batch. */
struct BatchFile
{
  std::string Input;
  std::string Output;
};

/**
 * The input files named by the INPUT arguments of a batch, in order. An argument that names an
 * existing file, or has no frame-number pattern, is that file. Otherwise it is a numbered
 * sequence in OpenImageIO's notation: `%04d` (printf), `#` (four digits) or `@` (one digit per
 * @), with the frames from a range in the name (`frame.1-100#.png`), from `frames` (`1-100`,
 * `1-100x2`, `1,5,9`), or else every existing file that matches, by frame number. Throws
 * UsageError for a malformed pattern or range, `frames` without a sequence argument, and a
 * sequence without any frame.
 */
std::vector<std::string> ExpandInputs(
  const std::vector<std::string>& arguments, const std::string& frames);

/**
 * The outputs of `inputs` in `outputDirectory`: the same file names there. Throws UsageError if
 * the directory does not exist or is not a directory, if an output would replace an input
 * (compared by real path), or if two inputs have the same name.
 */
std::vector<BatchFile> PlanBatch(
  const std::vector<std::string>& inputs, const std::string& outputDirectory);

/** The processors this process may run on (its CPU affinity), at least 1. */
int CountProcessors();

struct BatchSettings
{
  /** Files processed at the same time, at least 1. */
  int Jobs = 1;
  /** No progress display (errors and warnings still show). */
  bool Quiet = false;
  /**
   * Antialiases one file, in the child process; returns the exit status (0 on success) after
   * printing its own error line on stderr. Must not throw.
   */
  std::function<int(const BatchFile&)> ProcessFile;
};

/**
 * Runs settings.ProcessFile on every file, each in a child process, Jobs at a time, with the
 * progress display; returns how many files failed (a "N of M files failed" line is printed
 * then). Call with no other thread running: fork() copies only the calling thread.
 */
int RunBatch(const std::vector<BatchFile>& files, const BatchSettings& settings);
} // namespace mlaa

#endif
