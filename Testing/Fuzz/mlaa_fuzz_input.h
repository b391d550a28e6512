// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * What the fuzz targets share: reading the fuzzer's bytes in order, and failing loudly.
 *
 * The bytes are read front to back, each field as a fixed number of bytes, and a field past the
 * end reads as zeros, so that every input is valid and make-corpus.py can write seeds field by
 * field (its comments name the layout each target reads).
 */

#ifndef mlaa_fuzz_input_h
#define mlaa_fuzz_input_h

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include <fcntl.h>
#include <unistd.h>

// The sanitizers' report stream (sanitizer/common_interface_defs.h), weak: present whenever the
// target is built as it must be, with -fsanitize=fuzzer,address.
extern "C" void __sanitizer_set_report_fd(void* fd) __attribute__((weak));

namespace mlaafuzz
{
/** The fuzzer's bytes, read in order; reads past the end give zeros. */
class ByteReader
{
public:
  ByteReader(const std::uint8_t* data, std::size_t size)
    : Data(data)
    , Size(size)
  {
  }

  /** Copies the next `n` bytes to `out` (zeros past the end). */
  void Read(void* out, std::size_t n)
  {
    if (n == 0)
    {
      return;
    }
    const std::size_t available = this->Position < this->Size ? this->Size - this->Position : 0;
    const std::size_t copied = n < available ? n : available;
    if (copied > 0)
    {
      std::memcpy(out, this->Data + this->Position, copied);
    }
    std::memset(static_cast<std::uint8_t*>(out) + copied, 0, n - copied);
    this->Position += copied;
  }

  std::uint8_t U8()
  {
    std::uint8_t v;
    this->Read(&v, 1);
    return v;
  }

  /** Little-endian. */
  std::uint16_t U16()
  {
    const std::uint16_t lo = this->U8();
    return static_cast<std::uint16_t>(lo | (this->U8() << 8));
  }

  std::int8_t I8() { return static_cast<std::int8_t>(this->U8()); }

  /** An IEEE double from the next 8 bytes (any bit pattern: NaN and infinities included). */
  double F64()
  {
    double v;
    this->Read(&v, sizeof(v));
    return v;
  }

  /** A value in [0, 1] from one byte. */
  double Unit() { return this->U8() / 255.0; }

  std::size_t Remaining() const { return this->Position < this->Size ? this->Size - this->Position : 0; }
  const std::uint8_t* Rest() const { return this->Data + (this->Position < this->Size ? this->Position : this->Size); }

private:
  const std::uint8_t* Data;
  std::size_t Size;
  std::size_t Position = 0;
};

/** Where failures are reported: a duplicate of the stderr the fuzzer started with. */
inline int& ReportFd()
{
  static int fd = STDERR_FILENO;
  return fd;
}

/**
 * Call from LLVMFuzzerInitialize (which runs before libFuzzer applies -close_fd_mask): keeps the
 * real stderr for broken invariants and sanitizer reports, which would otherwise be lost while
 * the code under test has file descriptor 2 closed or redirected (the mlaa tool captures it
 * while the image libraries run, see Apps/mlaa/mlaaCrashReport.h).
 */
inline void KeepStderr()
{
  const int fd = fcntl(STDERR_FILENO, F_DUPFD_CLOEXEC, 10);
  if (fd >= 0)
  {
    ReportFd() = fd;
    if (__sanitizer_set_report_fd)
    {
      __sanitizer_set_report_fd(reinterpret_cast<void*>(static_cast<std::intptr_t>(fd)));
    }
  }
}

/**
 * A broken invariant: printed, then abort(), which libFuzzer reports as a crash and saves the
 * input for.
 */
[[noreturn]] inline void Fail(const char* what)
{
  dprintf(ReportFd(), "mlaa fuzz invariant broken: %s\n", what);
  std::abort();
}

#define MLAA_FUZZ_CHECK(condition, what)                                                          \
  do                                                                                               \
  {                                                                                                \
    if (!(condition))                                                                              \
    {                                                                                              \
      ::mlaafuzz::Fail(what " (" #condition ")");                                                  \
    }                                                                                              \
  } while (false)
} // namespace mlaafuzz

#endif
