// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * The errors of the `mlaa` tool: mlaa::Error, a failure to report (exit status 1), and
 * mlaa::UsageError, a bad command line (exit status 2). Their messages are one line without the
 * "mlaa: " prefix.
 */

#ifndef mlaaError_h
#define mlaaError_h

#include <stdexcept> // For std::runtime_error

namespace mlaa
{
/** A failure to report: one line, without the "mlaa: " prefix. */
class Error : public std::runtime_error
{
public:
  using std::runtime_error::runtime_error;
};

/** A bad command line (exit status 2). */
class UsageError : public Error
{
public:
  using Error::Error;
};
} // namespace mlaa

#endif
