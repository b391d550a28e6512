// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
#include "mlaaBatch.h"

#include "mlaaCrashReport.h"
#include "mlaaImageFile.h"

#include <OpenImageIO/filesystem.h>

#include <sched.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <set>
#include <thread>
#include <utility>

namespace mlaa
{
namespace
{
//------------------------------------------------------------------------------
// Names

// "a/b/c.png" -> "c.png"; "c.png" -> "c.png".
std::string BaseName(const std::string& path)
{
  const size_t slash = path.find_last_of('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

// "a/b/c.png" -> "a/b"; "c.png" -> "."; "/c.png" -> "/".
std::string DirectoryName(const std::string& path)
{
  const size_t slash = path.find_last_of('/');
  if (slash == std::string::npos)
  {
    return ".";
  }
  return slash == 0 ? "/" : path.substr(0, slash);
}

// The real path of an existing file or directory, or "".
std::string RealPath(const std::string& path)
{
  char* resolved = realpath(path.c_str(), nullptr);
  if (!resolved)
  {
    return "";
  }
  std::string result(resolved);
  std::free(resolved);
  return result;
}

// Where `path` is once symbolic links in its directory are resolved (the file itself need not
// exist); its own real path instead when it exists.
std::string ResolvedLocation(const std::string& path)
{
  const std::string real = RealPath(path);
  if (!real.empty())
  {
    return real;
  }
  const std::string directory = RealPath(DirectoryName(path));
  return directory.empty() ? path : (directory == "/" ? "" : directory) + "/" + BaseName(path);
}

// Whether `argument` has a frame-number pattern: '#', '@' or a printf "%d" / "%0Nd".
bool HasFramePattern(const std::string& argument)
{
  if (argument.find_first_of("#@") != std::string::npos)
  {
    return true;
  }
  for (size_t p = argument.find('%'); p != std::string::npos; p = argument.find('%', p + 1))
  {
    size_t q = p + 1;
    while (q < argument.size() && argument[q] >= '0' && argument[q] <= '9')
    {
      ++q;
    }
    if (q < argument.size() && argument[q] == 'd')
    {
      return true;
    }
  }
  return false;
}

//------------------------------------------------------------------------------
// Progress

std::string FormatDuration(double seconds)
{
  const long s = static_cast<long>(seconds + 0.5);
  char text[32];
  if (s >= 3600)
  {
    std::snprintf(text, sizeof(text), "%ld:%02ld:%02ld", s / 3600, (s / 60) % 60, s % 60);
  }
  else
  {
    std::snprintf(text, sizeof(text), "%ld:%02ld", s / 60, s % 60);
  }
  return text;
}

void WriteStderr(const std::string& text)
{
  std::fwrite(text.data(), 1, text.size(), stderr);
  std::fflush(stderr);
}

/**
 * What the user sees while a batch runs: on a terminal, one line updated in place,
 * "[=====>    ] 37/100  4.2 files/s  ETA 0:15", which messages push up; elsewhere, one line per
 * file done, "mlaa: [37/100] IN -> OUT"; with --quiet, only the messages.
 */
class Progress
{
public:
  Progress(size_t total, bool quiet)
    : Total(total)
    , Quiet(quiet)
    , Terminal(!quiet && isatty(STDERR_FILENO))
    , Start(std::chrono::steady_clock::now())
  {
  }

  /** File number `number` (from 1), in input order: its messages, then its line. */
  void Report(size_t number, const BatchFile& file, bool failed, const std::string& messages)
  {
    if (!messages.empty())
    {
      this->Clear();
      WriteStderr(messages.back() == '\n' ? messages : messages + "\n");
    }
    if (!failed && !this->Quiet && !this->Terminal)
    {
      WriteStderr("mlaa: [" + std::to_string(number) + "/" + std::to_string(this->Total) + "] " +
        Printable(file.Input, 300, false) + " -> " + Printable(file.Output, 300, false) + "\n");
    }
  }

  /** On a terminal, (re)draws the bar for `done` files finished. */
  void Update(size_t done)
  {
    if (!this->Terminal)
    {
      return;
    }
    const double elapsed =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - this->Start).count();
    const int width = 30;
    const int filled = static_cast<int>(width * done / std::max<size_t>(this->Total, 1));
    std::string bar = "[" + std::string(filled, '=');
    if (filled < width)
    {
      bar += ">" + std::string(width - filled - 1, ' ');
    }
    bar += "] " + std::to_string(done) + "/" + std::to_string(this->Total);
    if (done > 0 && elapsed > 0.0)
    {
      const double rate = done / elapsed;
      char text[64];
      std::snprintf(text, sizeof(text), "  %.1f files/s", rate);
      bar += text;
      bar += done < this->Total ? "  ETA " + FormatDuration((this->Total - done) / rate)
                                : "  " + FormatDuration(elapsed);
    }
    WriteStderr("\r" + bar + "\x1b[K");
    this->Shown = true;
  }

  /** Ends the bar's line. */
  void Finish()
  {
    if (this->Shown)
    {
      WriteStderr("\n");
      this->Shown = false;
    }
  }

private:
  void Clear()
  {
    if (this->Shown)
    {
      WriteStderr("\r\x1b[K");
      this->Shown = false;
    }
  }

  const size_t Total;
  const bool Quiet;
  const bool Terminal;
  const std::chrono::steady_clock::time_point Start;
  bool Shown = false;
};

// Everything in `fd` from its start, at most the last `limit` bytes.
std::string ReadMessages(int fd, off_t limit = 65536)
{
  const off_t size = lseek(fd, 0, SEEK_END);
  if (size <= 0)
  {
    return "";
  }
  const off_t start = size > limit ? size - limit : 0;
  std::string text(static_cast<size_t>(size - start), '\0');
  text.resize(mlaa::ReadAt(fd, static_cast<std::uint64_t>(start), &text[0], text.size()));
  return (start > 0 ? "[... earlier messages left out ...]\n" : "") + text;
}
} // namespace

//------------------------------------------------------------------------------
std::vector<std::string> ExpandInputs(
  const std::vector<std::string>& arguments, const std::string& frames)
{
  std::vector<std::string> inputs;
  bool sequence = false;
  for (const std::string& argument : arguments)
  {
    struct stat status;
    if (lstat(argument.c_str(), &status) == 0 || !HasFramePattern(argument))
    {
      inputs.push_back(argument);
      continue;
    }
    sequence = true;
    const std::string shown = Printable(argument, 300, false);
    std::string pattern;
    std::string range;
    if (!OIIO::Filesystem::parse_pattern(argument.c_str(), 0, pattern, range))
    {
      throw UsageError(shown + ": not a file, nor a sequence pattern OpenImageIO understands");
    }
    if (!range.empty() && !frames.empty())
    {
      throw UsageError(shown + ": frames given twice, in the name and with --frames");
    }
    if (range.empty())
    {
      range = frames;
    }
    std::vector<std::string> names;
    if (!range.empty())
    {
      std::vector<int> numbers;
      if (!OIIO::Filesystem::enumerate_sequence(range, numbers) || numbers.empty())
      {
        throw UsageError(
          shown + ": '" + Printable(range, 100, false) + "' is not a frame range (1-100, 1-100x2, 1,5,9)");
      }
      OIIO::Filesystem::enumerate_file_sequence(pattern, numbers, names);
    }
    else
    {
      // Every existing file that matches, by frame number.
      std::vector<int> numbers;
      std::vector<std::string> found;
      OIIO::Filesystem::scan_for_matching_filenames(pattern, numbers, found);
      std::vector<std::pair<int, std::string>> framesFound;
      for (size_t k = 0; k < found.size() && k < numbers.size(); ++k)
      {
        std::string name = found[k];
        // The scan names files in the current directory "./NAME"; keep the user's spelling.
        if (argument.find('/') == std::string::npos && name.compare(0, 2, "./") == 0)
        {
          name = name.substr(2);
        }
        framesFound.emplace_back(numbers[k], name);
      }
      std::sort(framesFound.begin(), framesFound.end());
      for (const auto& frame : framesFound)
      {
        names.push_back(frame.second);
      }
      if (names.empty())
      {
        throw UsageError(shown + ": no file matches this sequence");
      }
    }
    inputs.insert(inputs.end(), names.begin(), names.end());
  }
  if (!frames.empty() && !sequence)
  {
    throw UsageError("--frames needs a sequence INPUT, such as frame.%04d.png or frame.#.png");
  }
  return inputs;
}

//------------------------------------------------------------------------------
std::vector<BatchFile> PlanBatch(
  const std::vector<std::string>& inputs, const std::string& outputDirectory)
{
  const std::string shownDirectory = Printable(outputDirectory, 300, false);
  struct stat status;
  if (stat(outputDirectory.c_str(), &status) != 0)
  {
    throw UsageError("--output-dir " + shownDirectory + ": " + std::strerror(errno));
  }
  if (!S_ISDIR(status.st_mode))
  {
    throw UsageError("--output-dir " + shownDirectory + ": not a directory");
  }
  if (inputs.empty())
  {
    throw UsageError("--output-dir needs at least one INPUT");
  }

  // Where each input is, resolved, to compare with where the outputs go.
  std::set<std::string> inputLocations;
  for (const std::string& input : inputs)
  {
    inputLocations.insert(ResolvedLocation(input));
  }
  std::vector<BatchFile> files;
  std::map<std::string, std::string> outputs; // resolved output -> its input
  const std::string separator =
    (!outputDirectory.empty() && outputDirectory.back() == '/') ? "" : "/";
  for (const std::string& input : inputs)
  {
    const std::string name = BaseName(input);
    if (name.empty() || name == "." || name == "..")
    {
      throw UsageError(Printable(input, 300, false) + ": not a file name");
    }
    BatchFile file{ input, outputDirectory + separator + name };
    const std::string location = ResolvedLocation(file.Output);
    if (inputLocations.count(location))
    {
      throw UsageError("--output-dir " + shownDirectory + ": " +
        Printable(file.Output, 300, false) + " would replace an input; choose another directory");
    }
    auto inserted = outputs.emplace(location, input);
    if (!inserted.second)
    {
      throw UsageError(Printable(inserted.first->second, 300, false) + " and " +
        Printable(input, 300, false) + " would both be written to " +
        Printable(file.Output, 300, false));
    }
    files.push_back(file);
  }
  return files;
}

//------------------------------------------------------------------------------
int CountProcessors()
{
  cpu_set_t set;
  CPU_ZERO(&set);
  if (sched_getaffinity(0, sizeof(set), &set) == 0 && CPU_COUNT(&set) > 0)
  {
    return CPU_COUNT(&set);
  }
  return std::max(1u, std::thread::hardware_concurrency());
}

//------------------------------------------------------------------------------
int RunBatch(const std::vector<BatchFile>& files, const BatchSettings& settings)
{
  struct Outcome
  {
    bool Done = false;
    bool Failed = false;
    std::string Messages;
  };
  struct Running
  {
    size_t Index;
    int MessagesFd;
  };

  const size_t total = files.size();
  const size_t jobs = static_cast<size_t>(std::max(1, settings.Jobs));
  Progress progress(total, settings.Quiet);
  std::vector<Outcome> outcomes(total);
  std::map<pid_t, Running> running;
  size_t next = 0;     // the next file to start
  size_t reported = 0; // files reported, in order
  size_t done = 0;
  int failed = 0;
  const pid_t parent = getpid();

  // The signals that stop a batch are held from fork() until the child is in the list that
  // the handler passes them on to (mlaaCrashReport.h).
  sigset_t cleanupSignals;
  sigemptyset(&cleanupSignals);
  for (int sig : { SIGINT, SIGTERM, SIGHUP, SIGQUIT })
  {
    sigaddset(&cleanupSignals, sig);
  }

  auto finish = [&](size_t index, bool fileFailed, const std::string& messages)
  {
    outcomes[index].Done = true;
    outcomes[index].Failed = fileFailed;
    outcomes[index].Messages = messages;
    ++done;
    failed += fileFailed ? 1 : 0;
  };

  progress.Update(0);
  while (reported < total)
  {
    while (running.size() < jobs && next < total)
    {
      const size_t index = next++;
      const std::string shown = Printable(files[index].Input, 300, false);
      const int messagesFd = CreateAnonymousFile();
      if (messagesFd < 0)
      {
        finish(index, true,
          "mlaa: " + shown + ": cannot create a file for its messages: " + std::strerror(errno));
        continue;
      }
      std::fflush(stdout);
      std::fflush(stderr);
      sigset_t previous;
      sigprocmask(SIG_BLOCK, &cleanupSignals, &previous);
      const pid_t pid = fork();
      if (pid == 0)
      {
        BeginChildProcess(messagesFd, parent);
        sigprocmask(SIG_SETMASK, &previous, nullptr);
        const int status = settings.ProcessFile(files[index]);
        std::fflush(stdout);
        std::fflush(stderr);
        // Not exit(): the parent's atexit handlers and static objects are the parent's.
        _exit(status);
      }
      const int forkError = errno;
      if (pid > 0)
      {
        AddChildProcess(pid);
        running[pid] = Running{ index, messagesFd };
      }
      sigprocmask(SIG_SETMASK, &previous, nullptr);
      if (pid < 0)
      {
        close(messagesFd);
        finish(index, true, "mlaa: " + shown + ": cannot start a process: " +
          std::strerror(forkError));
      }
    }

    if (!running.empty())
    {
      int status = 0;
      const pid_t pid = waitpid(-1, &status, 0);
      if (pid < 0)
      {
        if (errno == EINTR)
        {
          continue;
        }
        // No child left to wait for although some are listed: cannot happen; give up on them.
        for (const auto& child : running)
        {
          close(child.second.MessagesFd);
          finish(child.second.Index, true,
            "mlaa: " + Printable(files[child.second.Index].Input, 300, false) +
              ": lost its process");
        }
        running.clear();
      }
      auto child = running.find(pid);
      if (pid > 0 && child != running.end())
      {
        RemoveChildProcess(pid);
        const size_t index = child->second.Index;
        std::string messages = ReadMessages(child->second.MessagesFd);
        close(child->second.MessagesFd);
        running.erase(child);
        const bool ok = WIFEXITED(status) && WEXITSTATUS(status) == 0;
        const std::string shown = Printable(files[index].Input, 300, false);
        if (!ok && WIFSIGNALED(status))
        {
          // The crash report has said what happened; say how it ended.
          const int sig = WTERMSIG(status);
          messages += (messages.empty() || messages.back() == '\n' ? "" : "\n") +
            std::string("mlaa: ") + shown + ": stopped by signal " + std::to_string(sig) + " (" +
            strsignal(sig) + ")\n";
        }
        else if (!ok && messages.empty())
        {
          messages = "mlaa: " + shown + ": failed with exit status " +
            std::to_string(WEXITSTATUS(status)) + "\n";
        }
        finish(index, !ok, messages);
      }
    }

    while (reported < total && outcomes[reported].Done)
    {
      const Outcome& outcome = outcomes[reported];
      progress.Report(reported + 1, files[reported], outcome.Failed, outcome.Messages);
      outcomes[reported].Messages.clear();
      ++reported;
    }
    progress.Update(done);
  }
  progress.Finish();
  if (failed > 0)
  {
    WriteStderr("mlaa: " + std::to_string(failed) + " of " + std::to_string(total) +
      (total == 1 ? " file" : " files") + " failed\n");
  }
  return failed;
}
} // namespace mlaa
