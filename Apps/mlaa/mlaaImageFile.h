// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * Image files for the `mlaa` tool: reading any file OpenImageIO reads into a vtkImageData, and
 * writing a vtkImageData so that the destination is either the complete new image or left as
 * it was.
 *
 * Orientation: OpenImageIO's scanline 0 is the top row of the picture; vtkImageData's row 0 is
 * the bottom row (y grows upwards, as in OpenGL textures and in vtkMLAAOptions' "top"). Both
 * functions flip with a negative row stride, so a picture keeps its orientation.
 *
 * Pixel values are moved as they are stored: no colour-space conversion, and alpha is kept
 * unassociated where the format stores it so (PNG, TIFF), so that pixels the filter leaves
 * alone come back bit for bit.
 *
 * Every failure throws mlaa::Error, whose message is one line "FILE: what" without the "mlaa: "
 * prefix. What the image libraries print on stderr themselves (libpng does) is captured (see
 * mlaaCrashReport.h): it is part of OpenImageIO's error message on failure, and a warning
 * otherwise.
 *
 * Hostile files: only regular files are opened (a FIFO would block, a device never ends), and
 * each is opened once: the name is checked, opened (without blocking), and the open descriptor
 * checked again and read through /proc/self/fd/N, so that a file replaced between the check and
 * the open is never read. The image size in the header is checked against a limit before
 * anything is allocated, writers are given only what they are known to handle (see
 * WriteImageFile), and every written file is read back before it becomes the output.
 *
 * "-" is standard input for ReadImageFile (read whole into a file without a name, the format
 * found from its bytes) and standard output for WriteImageFile (the complete file is sent once
 * it has been read back: nothing partial reaches the pipe).
 */

#ifndef mlaaImageFile_h
#define mlaaImageFile_h

#include "mlaaError.h" // For mlaa::Error

#include "vtkSmartPointer.h" // For vtkSmartPointer

#include <OpenImageIO/imageio.h> // For OIIO::ImageSpec, OIIO::TypeDesc

#include <cstdint>   // For std::uint64_t
#include <string>    // For std::string

class vtkImageData;

namespace mlaa
{
/**
 * `text` made safe for one line of a terminal: lines joined with "; ", lines repeated (or the
 * same but for their numbers, as libraries report one per scanline) given once with a count,
 * control bytes and invalid UTF-8 written as \xNN, and at most `maxLength` bytes ("..." at the
 * end when cut). With `joinLines` false, line breaks are escaped too (for names and values
 * given by the user, which must be shown as they are).
 */
std::string Printable(const std::string& text, size_t maxLength = 300, bool joinLines = true);

/**
 * Reads up to `size` bytes of the file open as `fd` from `offset` into `data`, retrying
 * interrupted reads; returns how many it read (fewer at the end of the file, or on an error).
 */
size_t ReadAt(int fd, std::uint64_t offset, char* data, size_t size);

/**
 * The largest image, in pixels, that reading `channels` channels of `type` may allocate by
 * default: what the tool would hold of it (input, output, the filter's buffers) must fit in half
 * of the memory the kernel says is available (MemAvailable), divided between the images in
 * flight (SetImagesInFlight); 2^28 pixels if that is unknown.
 */
std::uint64_t DefaultMaxPixels(int channels, OIIO::TypeDesc type);

/**
 * How many images are read at the same time (a batch's --jobs; default 1): the default size
 * limit gives each its share of the memory, so that as many hostile headers at once cannot
 * take more than one could.
 */
void SetImagesInFlight(int count);

/** An image read from a file. */
struct ImageFile
{
  /** The pixels, bottom row first, one point scalar array with the file's channels. */
  vtkSmartPointer<vtkImageData> Image;
  /** The file's description: size, channel names, metadata. */
  OIIO::ImageSpec Spec;
  /** The file's pixel type (OIIO::TypeHalf for half, though Image holds it as float). */
  OIIO::TypeDesc PixelType;
  /** The OpenImageIO format name, e.g. "png", "openexr". */
  std::string FormatName;
  /** What the image libraries printed while reading (one line), or "". */
  std::string Warning;
};

/**
 * The VTK scalar type that holds pixels of `type` without loss: uint8 -> VTK_UNSIGNED_CHAR,
 * uint16 -> VTK_UNSIGNED_SHORT, half and float -> VTK_FLOAT, double -> VTK_DOUBLE, and the
 * matching VTK types for the other integers. 0 for a type that is not a pixel type.
 */
int GetVTKScalarType(OIIO::TypeDesc type);

/**
 * Reads subimage 0, MIP level 0 of `path`. Throws for a missing or unreadable file, anything
 * but a regular file (directories, FIFOs, devices, sockets), an empty file, deep data, volumes
 * (images deeper than one slice), and images of more than `maxPixels` pixels (0: the default of
 * DefaultMaxPixels), checked from the header before the pixels are allocated.
 */
ImageFile ReadImageFile(const std::string& path, std::uint64_t maxPixels = 0);

/** `path` as messages show it: "standard input" or "standard output" for "-". */
std::string DisplayName(const std::string& path, bool output);

/**
 * Throws UsageError unless OpenImageIO has a writer for `format`, a format name or an extension
 * without its dot ("png", "tif", "openexr").
 */
void CheckOutputFormat(const std::string& format);

/**
 * Removes, from `directory`, the named temporaries of WriteImageFile's fallback that a process
 * killed by SIGKILL left: hidden files named ".NAME.mlaa-PID-XXXXXX.EXT", regular, owned by this
 * user, unmodified for an hour, whose process PID no longer exists. Each directory is swept once
 * per process (a batch sweeps its output directory before it forks).
 */
void SweepStaleTemporaries(const std::string& directory);

/**
 * Writes `image` (bottom row first, 2D, scalars of any pixel type of GetVTKScalarType) to
 * `path`, in the format of the file name's extension, with pixels of type `pixelType` or, where
 * the format cannot hold it, the closest type that OpenImageIO's writer chooses. `description`
 * gives the channel names and the metadata to carry over (its size, channel count and pixel
 * type are replaced by those of the image).
 *
 * When floating-point pixels end up in an integer format, the values in `valueRange` are mapped
 * to the whole integer range and the others clamped (OpenImageIO's conversion maps [0, 1]).
 *
 * Writers get only what they are known to take (OpenImageIO 2.4): a format without alpha gets
 * the colour channels (JPEG, PNM, HDR: a warning says so), GIF and ICO add an alpha channel (a
 * warning says so), and what a writer cannot hold or is known to get wrong is refused before it
 * is called: grey + alpha in BMP, DPX (its writer aborts), GIF, IFF, HDR, HEIF, WebP; more than
 * one channel in Zfile; and every JPEG 2000 (unreadable files), FITS (truncated or transposed
 * images), RLA (bad headers), null and term output.
 *
 * The format is `format` (a format name or extension; required when `path` is "-"), else that
 * of `path`'s extension.
 *
 * The image goes to a new file without a name (O_TMPFILE) in the destination's directory, which
 * is read back (size and channels) and then linked into place (over an existing `path` by a
 * rename); whatever ends the process, nothing is left behind. Where O_TMPFILE is not available,
 * a hidden temporary ".NAME.mlaa-PID-XXXXXX.EXT" beside `path` takes its place (removed on
 * failure and on catchable signals; after a SIGKILL, by SweepStaleTemporaries). On any failure
 * an existing `path` is left untouched; `path` must not name anything but a regular file. For
 * "-", the file is written in $TMPDIR and copied to standard output once it is complete.
 *
 * Returns a one-line note when the written pixel type or channels differ from the image's or
 * the image libraries printed something, else "".
 */
std::string WriteImageFile(vtkImageData* image, const std::string& path,
  const OIIO::ImageSpec& description, OIIO::TypeDesc pixelType, const double valueRange[2],
  const std::string& format = std::string());
} // namespace mlaa

#endif
