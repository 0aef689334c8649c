// A code_aster .export run by aster-lite: its command files run in order in one
// interpreter, its data files bound to their units, its result files written
// where it lists them (never over a file the run reads).
#pragma once
#include <string>
#include <vector>

#include "core/export_file.hpp"
#include "lang/session.hpp"

namespace aster::lang {

// Checks the .export's files and binds them in `session` (a unit the command line
// bound with -u keeps that binding); returns the command files to run, in order.
// Throws aster::Error "<export>:<line>: ..." for a file it cannot use: a data
// file missing, a gzipped file, a folder, no command file.
std::vector<std::string> prepareExportRun(const ExportFile& exportFile, Session& session);

// After the run: the checks' .resu file copied to the .export's `F resu ... R`
// files. Returns the messages of what could not be written.
std::vector<std::string> writeExportResults(const ExportFile& exportFile, Session& session);

}  // namespace aster::lang
