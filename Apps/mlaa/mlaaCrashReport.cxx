// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
#include "mlaaCrashReport.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>

// The sanitizers' death callback, present only when the tool is built with a sanitizer.
extern "C" void __sanitizer_set_death_callback(void (*callback)(void)) __attribute__((weak));

namespace mlaa
{
namespace
{
// Everything the handlers read is prepared here beforehand, in fixed buffers.
int RealStderr = -1;                  // a duplicate of the original stderr, open all along
volatile sig_atomic_t ActiveCaptureFd = -1; // the file stderr goes to while capturing, or -1
char Doing[1024];                     // "mlaa: FILE: crashed while DOING", or ""
char TemporaryOutput[4096];           // the temporary output to remove, or ""
volatile sig_atomic_t Reported = 0;
// The processes a batch runs files in (0: a free slot), stopped and waited for on Ctrl-C.
constexpr int MaxChildren = 1024;
volatile sig_atomic_t Children[MaxChildren];
volatile sig_atomic_t InChildProcess = 0; // a process forked for one file of a batch

const int FatalSignals[] = { SIGABRT, SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGSYS };
const int CleanupSignals[] = { SIGINT, SIGTERM, SIGHUP, SIGQUIT };
struct sigaction Previous[NSIG];

void WriteAll(int fd, const char* data, size_t size)
{
  while (size > 0)
  {
    const ssize_t n = write(fd, data, size);
    if (n < 0 && errno == EINTR)
    {
      continue;
    }
    if (n <= 0)
    {
      return;
    }
    data += n;
    size -= static_cast<size_t>(n);
  }
}

void WriteText(int fd, const char* text)
{
  WriteAll(fd, text, std::strlen(text));
}

// Copies what was captured to `fd`, control bytes other than newline and tab as \xNN; at most
// the last 16 KB (a sanitizer report's end says the most).
void CopyCaptured(int from, int fd)
{
  const off_t size = lseek(from, 0, SEEK_END);
  if (size <= 0)
  {
    return;
  }
  const off_t keep = 16384;
  const off_t start = size > keep ? size - keep : 0;
  if (start > 0)
  {
    WriteText(fd, "[... earlier messages left out ...]\n");
  }
  lseek(from, start, SEEK_SET);
  char in[512];
  char out[4 * sizeof(in)];
  char last = '\n';
  ssize_t n;
  while ((n = read(from, in, sizeof(in))) > 0)
  {
    size_t o = 0;
    for (ssize_t i = 0; i < n; ++i)
    {
      const unsigned char c = static_cast<unsigned char>(in[i]);
      if ((c < 0x20 && c != '\n' && c != '\t') || c == 0x7f)
      {
        const char* hex = "0123456789abcdef";
        out[o++] = '\\';
        out[o++] = 'x';
        out[o++] = hex[c >> 4];
        out[o++] = hex[c & 15];
      }
      else
      {
        out[o++] = static_cast<char>(c);
      }
    }
    WriteAll(fd, out, o);
    last = in[n - 1];
  }
  if (last != '\n')
  {
    WriteText(fd, "\n");
  }
}

// The one thing every way of dying does: messages out, temporary file away. `why` is
// appended to the "crashed while" line (a signal name, say).
void Report(const char* why)
{
  if (Reported)
  {
    return;
  }
  Reported = 1;
  const int capture = ActiveCaptureFd;
  if (capture >= 0 && RealStderr >= 0)
  {
    ActiveCaptureFd = -1;
    dup2(RealStderr, STDERR_FILENO);
    if (Doing[0])
    {
      WriteText(STDERR_FILENO, Doing);
      WriteText(STDERR_FILENO, why);
      WriteText(STDERR_FILENO, "; what the library printed follows\n");
    }
    CopyCaptured(capture, STDERR_FILENO);
  }
  else if (Doing[0] && why[0])
  {
    WriteText(STDERR_FILENO, Doing);
    WriteText(STDERR_FILENO, why);
    WriteText(STDERR_FILENO, "\n");
  }
  if (TemporaryOutput[0])
  {
    unlink(TemporaryOutput);
    TemporaryOutput[0] = '\0';
  }
}

const char* SignalName(int sig)
{
  switch (sig)
  {
    case SIGABRT:
      return " (SIGABRT: the library aborted)";
    case SIGSEGV:
      return " (SIGSEGV: invalid memory access)";
    case SIGBUS:
      return " (SIGBUS: invalid memory access)";
    case SIGFPE:
      return " (SIGFPE: arithmetic error)";
    case SIGILL:
      return " (SIGILL: illegal instruction)";
    case SIGSYS:
      return " (SIGSYS: bad system call)";
    default:
      return " (killed by a signal)";
  }
}

void OnFatalSignal(int sig, siginfo_t* info, void*)
{
  const int savedErrno = errno;
  Report(SignalName(sig));
  // Then what would have happened without us: the previous handler (AddressSanitizer's
  // reports a SEGV) or the default action.
  sigaction(sig, &Previous[sig], nullptr);
  errno = savedErrno;
  const bool sent = info && (info->si_code == SI_USER || info->si_code == SI_TKILL ||
                              info->si_code == SI_QUEUE);
  if (sent || sig == SIGABRT)
  {
    raise(sig); // delivered when this handler returns
  }
  // A fault: returning runs the faulting instruction again, which now meets the previous action.
}

void OnCleanupSignal(int sig)
{
  // A batch's children get the signal too and remove their own temporary outputs; waiting for
  // them means none is left once this process is gone.
  for (int i = 0; i < MaxChildren; ++i)
  {
    if (Children[i] > 0)
    {
      kill(static_cast<pid_t>(Children[i]), sig);
    }
  }
  for (int i = 0; i < MaxChildren; ++i)
  {
    if (Children[i] > 0)
    {
      while (waitpid(static_cast<pid_t>(Children[i]), nullptr, 0) < 0 && errno == EINTR)
      {
      }
      Children[i] = 0;
    }
  }
  if (TemporaryOutput[0])
  {
    unlink(TemporaryOutput);
    TemporaryOutput[0] = '\0';
  }
  signal(sig, SIG_DFL);
  raise(sig);
}

void OnSanitizerDeath()
{
  Report(" (a sanitizer found an error)");
}

void OnExit()
{
  // Only reached with something pending when a library called exit() while we captured.
  if (ActiveCaptureFd >= 0)
  {
    Report(" (a library called exit())");
  }
  else if (TemporaryOutput[0])
  {
    unlink(TemporaryOutput);
    TemporaryOutput[0] = '\0';
  }
  // In a batch's child, what exit() would run next belongs to the parent: the destructors of
  // its static objects, among them a logging library's that joins threads only the parent has
  // (log4cplus, loaded with OpenImageIO's DICOM support), which would wait forever.
  if (InChildProcess)
  {
    _exit(1);
  }
}

void CopyInto(char* buffer, size_t size, const std::string& text)
{
  const size_t n = text.size() < size - 1 ? text.size() : size - 1;
  std::memcpy(buffer, text.data(), n);
  buffer[n] = '\0';
}
} // namespace

//------------------------------------------------------------------------------
void InstallCrashReport()
{
  RealStderr = fcntl(STDERR_FILENO, F_DUPFD_CLOEXEC, 3);

  // Handlers run on a stack of their own, so that a stack overflow is reported too.
  static char alternateStack[64 * 1024];
  stack_t stack;
  stack.ss_sp = alternateStack;
  stack.ss_size = sizeof(alternateStack);
  stack.ss_flags = 0;
  sigaltstack(&stack, nullptr);

  for (int sig : FatalSignals)
  {
    struct sigaction action;
    std::memset(&action, 0, sizeof(action));
    action.sa_sigaction = &OnFatalSignal;
    action.sa_flags = SA_SIGINFO | SA_ONSTACK;
    sigemptyset(&action.sa_mask);
    sigaction(sig, &action, &Previous[sig]);
  }
  for (int sig : CleanupSignals)
  {
    struct sigaction action;
    std::memset(&action, 0, sizeof(action));
    action.sa_handler = &OnCleanupSignal;
    sigemptyset(&action.sa_mask);
    struct sigaction previous;
    sigaction(sig, nullptr, &previous);
    if (previous.sa_handler != SIG_IGN) // keep nohup's choice
    {
      sigaction(sig, &action, nullptr);
    }
  }
  if (__sanitizer_set_death_callback)
  {
    __sanitizer_set_death_callback(&OnSanitizerDeath);
  }
  std::atexit(&OnExit);
}

void SetTemporaryOutput(const char* path)
{
  CopyInto(TemporaryOutput, sizeof(TemporaryOutput), path ? path : "");
}

void AddChildProcess(int pid)
{
  for (int i = 0; i < MaxChildren; ++i)
  {
    if (Children[i] == 0)
    {
      Children[i] = pid;
      return;
    }
  }
}

void RemoveChildProcess(int pid)
{
  for (int i = 0; i < MaxChildren; ++i)
  {
    if (Children[i] == pid)
    {
      Children[i] = 0;
    }
  }
}

void BeginChildProcess(int stderrFd, int parentPid)
{
  InChildProcess = 1;
  for (int i = 0; i < MaxChildren; ++i)
  {
    Children[i] = 0;
  }
  // Stopped with SIGTERM (whose handler removes the temporary output) if the parent dies
  // first, however it dies; and if it is already gone, stop now.
  prctl(PR_SET_PDEATHSIG, SIGTERM);
  if (getppid() != parentPid)
  {
    raise(SIGTERM);
  }
  if (stderrFd >= 0 && dup2(stderrFd, STDERR_FILENO) >= 0)
  {
    close(stderrFd);
    if (RealStderr >= 0)
    {
      close(RealStderr);
    }
    RealStderr = fcntl(STDERR_FILENO, F_DUPFD_CLOEXEC, 3);
  }
}

int CreateAnonymousFile()
{
  // O_TMPFILE: a file without a name, gone with the process whatever happens.
  const char* directory = std::getenv("TMPDIR");
  int fd = open(directory && *directory ? directory : "/tmp", O_TMPFILE | O_RDWR | O_CLOEXEC, 0600);
  if (fd < 0)
  {
    std::FILE* file = std::tmpfile();
    fd = file ? fcntl(fileno(file), F_DUPFD_CLOEXEC, 3) : -1;
    if (file)
    {
      std::fclose(file);
    }
  }
  return fd;
}

//------------------------------------------------------------------------------
CapturedStderr::CapturedStderr(const std::string& file, const std::string& doing)
{
  std::fflush(stderr);
  CopyInto(Doing, sizeof(Doing), "mlaa: " + file + ": crashed while " + doing);
  this->CaptureFd = CreateAnonymousFile();
  this->SavedStderr = this->CaptureFd >= 0 ? fcntl(STDERR_FILENO, F_DUPFD_CLOEXEC, 3) : -1;
  if (this->SavedStderr < 0 || dup2(this->CaptureFd, STDERR_FILENO) < 0)
  {
    this->Restore(); // nothing captured: messages show, nothing else goes wrong
    return;
  }
  ActiveCaptureFd = this->CaptureFd;
}

CapturedStderr::~CapturedStderr()
{
  this->Restore();
}

std::string CapturedStderr::Finish()
{
  std::string text;
  if (this->SavedStderr >= 0)
  {
    std::fflush(stderr);
    const off_t size = lseek(this->CaptureFd, 0, SEEK_END);
    // Enough for any message worth showing; the rest is left unread.
    const off_t limit = 1 << 20;
    text.resize(static_cast<size_t>(size < limit ? (size > 0 ? size : 0) : limit));
    lseek(this->CaptureFd, 0, SEEK_SET);
    size_t got = 0;
    while (got < text.size())
    {
      const ssize_t n = read(this->CaptureFd, &text[got], text.size() - got);
      if (n <= 0)
      {
        break;
      }
      got += static_cast<size_t>(n);
    }
    text.resize(got);
  }
  this->Restore();
  return text;
}

void CapturedStderr::Restore()
{
  ActiveCaptureFd = -1;
  Doing[0] = '\0';
  if (this->SavedStderr >= 0)
  {
    std::fflush(stderr);
    dup2(this->SavedStderr, STDERR_FILENO);
    close(this->SavedStderr);
    this->SavedStderr = -1;
  }
  if (this->CaptureFd >= 0)
  {
    close(this->CaptureFd);
    this->CaptureFd = -1;
  }
}
} // namespace mlaa
