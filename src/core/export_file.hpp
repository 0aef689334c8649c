// code_aster's .export file: how its runner runs a test. One entry a line:
//   P name [value ...]             a parameter (time_limit, memory_limit, testlist...)
//   A name [value ...]             arguments of the code_aster command line
//   F type path D|R|DR[C] unit     a file: D read by the run, R written by it, C gzipped
//   R type path D|R|DR[C] unit     a folder, as F
// Blank lines and lines starting with '#' are skipped. The command files are the
// files of type "comm" (and the older "com0".."com9"), run in their order; the
// other data files are bound to their logical unit (0: none).
#pragma once
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace aster {

struct ExportEntry {
  bool folder = false;          // an R line
  std::string type;             // "comm", "mail", "mmed", "msh", "nom"...
  std::filesystem::path path;   // as written: relative to the .export's folder unless absolute
  bool data = false;            // D: read by the run
  bool result = false;          // R: written by the run
  bool compressed = false;      // C: gzipped
  int unit = 0;                 // logical unit, 0 for none
  int line = 0;                 // where in the .export (1-based)

  bool isCommandFile() const;
};

struct ExportParameter {
  std::string name;
  std::vector<std::string> values;
  int line = 0;
};

struct ExportFile {
  std::filesystem::path source;  // the .export itself
  std::vector<ExportParameter> parameters;
  std::vector<std::string> arguments;  // the A lines' words, in order
  std::vector<ExportEntry> entries;

  // "ssnp02a.export:7", for messages.
  std::string where(int line) const;
  // The folder relative paths start from.
  std::filesystem::path folder() const;
  std::filesystem::path resolve(const ExportEntry& entry) const;
  const ExportParameter* parameter(const std::string& name) const;
  // P time_limit in seconds, when given.
  std::optional<double> timeLimit() const;
  // The command files read by the run, in order.
  std::vector<const ExportEntry*> commandFiles() const;
};

// Reads `text` as the .export `source`; throws aster::Error("<source>:<line>: ...")
// on a malformed line: an unknown line kind, a missing field, flags other than
// D, R and C, a unit that is no integer from 0 up, a time_limit that is no
// positive number, two different files read on one unit, a file both read
// and written under two lines.
ExportFile parseExportFile(const std::string& text, const std::filesystem::path& source);
// Reads the file `source`; throws aster::Error when it cannot be read or is malformed.
ExportFile readExportFile(const std::filesystem::path& source);

}  // namespace aster
