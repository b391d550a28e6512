// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * What the `mlaa` tool does when it cannot go on: the library messages it was holding back
 * reach the terminal, and the temporary output file goes away.
 *
 * While OpenImageIO reads or writes, the tool sends the process's stderr (file descriptor 2)
 * to an anonymous temporary file, so that what the format libraries print themselves (libpng,
 * libtiff, libjpeg, x265, ...) can be folded into one line. Should the library abort, crash,
 * call exit() or trip a sanitizer while stderr points there, that text would be lost with the
 * process. So:
 *
 * - fatal signals (SIGABRT, SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGSYS) have a handler, on its own
 *   stack, that puts the real stderr back, writes one "mlaa: FILE: ..." line naming what was
 *   going on and the signal, copies what was captured (control bytes escaped, the last 16 KB at
 *   most), removes the temporary output, and then lets the signal do what it would have done
 *   (the previous handler, AddressSanitizer's for instance, or the default: core, status 128+n);
 * - an AddressSanitizer/UndefinedBehaviorSanitizer report ends in the sanitizer's death
 *   callback, which does the same (the report itself is then part of what was captured);
 * - exit() called by a library (libjpeg's default error handler does that) runs an atexit
 *   handler that does the same;
 * - SIGINT, SIGTERM, SIGHUP and SIGQUIT remove the temporary output before the default action;
 *   in a batch (mlaaBatch.h), the parent first passes the signal on to the processes it runs the
 *   files in, which remove their own, and waits for them.
 *
 * A file rather than a pipe holds the messages because nothing has to drain it: a pipe needs a
 * reader thread, which dies with the process at the very moment its buffer matters, and a full
 * pipe would block the library. Everything the handlers do is async-signal-safe (no allocation,
 * only write/read/lseek/dup2/unlink on data prepared beforehand).
 */

#ifndef mlaaCrashReport_h
#define mlaaCrashReport_h

#include <string> // For std::string

namespace mlaa
{
/** Installs the handlers; call once, first thing in main. */
void InstallCrashReport();

/**
 * While one of these exists, stderr is captured (see the file comment) and a crash is reported
 * as "mlaa: FILE: crashed while DOING" followed by what was captured.
 */
class CapturedStderr
{
public:
  CapturedStderr(const std::string& file, const std::string& doing);
  ~CapturedStderr();

  /** Stops capturing; returns everything that was printed meanwhile (raw). */
  std::string Finish();

private:
  CapturedStderr(const CapturedStderr&) = delete;
  void operator=(const CapturedStderr&) = delete;
  void Restore();

  int CaptureFd = -1;
  int SavedStderr = -1;
};

/** The temporary output file to remove if the process dies ("" or nullptr: none). */
void SetTemporaryOutput(const char* path);

///@{
/**
 * A batch's child processes: a cleanup signal (SIGINT, SIGTERM, SIGHUP, SIGQUIT) that reaches
 * this process is sent on to each of them and waited for before this process goes (up to 1024
 * at a time). Block those signals from before fork() until the child is added.
 */
void AddChildProcess(int pid);
void RemoveChildProcess(int pid);
///@}

/**
 * In a child process just forked for one file of a batch: forgets the parent's children, makes
 * `stderrFd` the process's stderr (also for crash reports) and asks for SIGTERM should the
 * parent (`parentPid`) die first, so that nothing goes on writing after it.
 */
void BeginChildProcess(int stderrFd, int parentPid);

/** A new read-write file without a name in $TMPDIR or /tmp (close-on-exec), or -1. */
int CreateAnonymousFile();
} // namespace mlaa

#endif
