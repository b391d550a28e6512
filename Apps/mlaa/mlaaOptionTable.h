// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * The options of the `mlaa` tool, in one table (mlaa::GetOptions): for each option its
 * spelling, the kind of value it takes and that value's range or names, which method's filter it
 * configures (vtkMLAAOptions for --method mlaa, vtkDLAAOptions for dlaa, or only the tool's own
 * settings), how it is applied to a mlaa::CommandLine, its default and its help text. Ranges,
 * names and defaults are read from the option classes, never copied.
 *
 * Everything that knows the options is made from the table: `mlaa --help` (PrintUsage), the
 * command-line parser (ParseCommandLine, with its method-ownership and "--preset first" checks),
 * the option list of docs/mlaa-tool.md (PrintOptionsMarkdown, checked by a test) and the MLAA
 * options the benchmarks of Examples/Benchmarks take (ApplyOption).
 *
 * This library (mlaaOptions) needs VTK and the FiltersMLAA module only: what the help says
 * about the machine (memory, processors) is given by the tool in mlaa::UsageFacts.
 */

#ifndef mlaaOptionTable_h
#define mlaaOptionTable_h

#include "mlaaError.h" // For mlaa::UsageError

#include "vtkDLAAOptions.h"  // For vtkDLAAOptions
#include "vtkMLAAOptions.h"  // For vtkMLAAOptions
#include "vtkSmartPointer.h" // For vtkSmartPointer

#include <cstdint> // For std::uint64_t
#include <iosfwd>  // For std::ostream
#include <string>  // For std::string
#include <vector>  // For std::vector

namespace mlaa
{
/** The antialiasing methods (--method). */
enum Methods
{
  MethodMLAA = 0,
  MethodDLAA = 1
};

/**
 * Where the value range comes from: vtkImageMLAA's default for the image's type, --value-range
 * LO HI, or --value-range auto (the image's own minimum and maximum).
 */
enum ValueRangeModes
{
  ValueRangeDefault = 0,
  ValueRangeGiven = 1,
  ValueRangeAuto = 2
};

/**
 * How the colour of an image with alpha relates to its alpha
 * (vtkMLAAOptions::PremultipliedAlpha): from the file (auto), or as given.
 */
enum AlphaModes
{
  AlphaAuto = 0,
  AlphaStraight = 1,
  AlphaPremultiplied = 2
};

/** What the command line asks for. A default-constructed one holds every default. */
struct CommandLine
{
  CommandLine();

  bool Help = false;
  int Method = MethodMLAA;
  vtkSmartPointer<vtkMLAAOptions> Options;
  vtkSmartPointer<vtkDLAAOptions> DLAAOptions;
  std::string DepthImage;
  double ValueRange[2] = { 0.0, 1.0 }; // vtkImageMLAA's, for floating-point images
  int ValueRangeMode = ValueRangeDefault;
  int AlphaMode = AlphaAuto;
  int AreaTextureCellSize = 0;            // 0: antialias INPUT
  unsigned long long MaxPixels = 0;       // 0: mlaa::DefaultMaxPixels
  std::vector<std::string> FilterOptions; // the options given that configure the filter
  std::vector<std::string> MLAAOnly;      // of those, the ones only MLAA takes
  std::vector<std::string> DLAAOnly;      // of those, the ones only DLAA takes
  std::vector<std::string> Files;
  std::string Format; // --format: the output's format ("": OUTPUT's extension)
  // Batch mode (--output-dir).
  bool Batch = false;
  std::string OutputDirectory;
  std::string Frames;
  int Jobs = 0; // 0: one per processor
  bool Quiet = false;
  std::vector<std::string> BatchOnly; // the batch options given
};

/** What --help says about the machine it runs on. */
struct UsageFacts
{
  std::uint64_t DefaultMaxPixels = 0; // mlaa::DefaultMaxPixels(4, UINT8)
  int Processors = 1;                 // mlaa::CountProcessors()
};

/** The kinds of value an option takes. */
enum class ValueKind
{
  None,       // a switch without value (--quiet)
  Number,     // a finite number in Option::Range
  Integer,    // an integer in Option::Range
  Count,      // a positive integer (unsigned long long)
  Name,       // one of Option::Names (on|off is one)
  Text,       // any non-empty text (a file name)
  ValueRange, // two numbers LO < HI, or "auto"
  Help        // -h, --help: wins over everything else on the line
};

/** Which method's filter an option configures (bits); 0: only the tool's own settings. */
enum OptionMethods
{
  ToolSetting = 0,
  ForMLAA = 1,
  ForDLAA = 2,
  ForBothMethods = ForMLAA | ForDLAA
};

/** Flags of an option. */
enum OptionFlags
{
  /**
   * Refused before --preset: the quality options, which the preset sets (a value given before
   * it would silently be replaced), and DLAA's options (--preset is MLAA's; this message is the
   * one the tool gives first).
   */
  RefusedBeforePreset = 1,
  /** An option of batches only (needs --output-dir). */
  BatchOnly = 2,
  /** --preset itself. */
  IsPreset = 4,
  /** Set by --preset: one of the quality options of vtkMLAAOptions::CopyQualitySettings. */
  SetByPreset = 8
};

/** The value(s) given to an option, parsed according to its kind. */
struct OptionValue
{
  std::string Text;        // Name, Text, Number, Integer, Count: the value as given
  double Number = 0.0;     // Number; ValueRange: unused
  long Integer = 0;        // Integer
  unsigned long long Count = 0;
  bool Auto = false;       // ValueRange: "auto"
  double Range[2] = { 0.0, 1.0 }; // ValueRange: LO HI
};

/** One option of the tool. */
struct Option
{
  const char* Name;      // "--threshold"
  const char* ShortName; // "-q", or nullptr
  const char* Value;     // the value's name in the usage ("T"); nullptr: Names joined by '|'
  ValueKind Kind;
  int Methods; // OptionMethods
  int Flags;   // OptionFlags
  /**
   * Errors: for Name, what a name is ("mode": "unknown mode 'x' (expected one of ...)"; nullptr:
   * "'x' is neither A nor B"); for Integer, what the value is ("an integer"); for Text, what the
   * value is ("a file name": "--depth-image needs a file name").
   */
  const char* Noun;
  /** Number, Integer: the range of the value, from the option classes. */
  void (*Range)(double range[2]);
  /** Name: the names the value may take, in the order of the usage. */
  std::vector<std::string> (*Names)();
  /** Name: what each name means, printed under the option by --help (nullptr: nothing). */
  std::string (*DescribeName)(const std::string& name);
  /** Applies a valid value. */
  void (*Apply)(CommandLine& cl, const OptionValue& value);
  /** The default, as --help and docs/mlaa-tool.md show it (machine-independent). */
  std::string (*Default)(const CommandLine& defaults);
  /** The help text. `range` is "[lo, hi]" for Number and Integer options. */
  std::string (*Help)(
    const CommandLine& defaults, const UsageFacts& facts, const std::string& range);
};

/** Every option of the tool, in the order of `mlaa --help`. */
const std::vector<Option>& GetOptions();

/** The option spelled `name` ("--threshold" or "-q"), or nullptr. */
const Option* FindOption(const std::string& name);

/** "[lo, hi]" for a Number or Integer option; "" for others. */
std::string GetRangeText(const Option& option);

/**
 * Parses `values` (one, or two for a ValueRange option that is not "auto") as the value of
 * `option`, spelled `name` on the command line, and applies it to `cl`. Throws UsageError with
 * the tool's message when the value is bad.
 */
void ApplyOption(const Option& option, const std::string& name,
  const std::vector<std::string>& values, CommandLine& cl);

/** Parses the tool's command line into `cl`; throws UsageError for a bad one. */
void ParseCommandLine(const std::vector<std::string>& args, CommandLine& cl);

/** `mlaa --help`. */
void PrintUsage(std::ostream& os, const UsageFacts& facts);

/** The options as a Markdown table: the option list of docs/mlaa-tool.md. */
void PrintOptionsMarkdown(std::ostream& os);
} // namespace mlaa

#endif
