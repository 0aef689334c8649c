#include "lang/export_run.hpp"

#include <fstream>
#include <sstream>
#include <system_error>

#include "core/atomic_write.hpp"
#include "core/error.hpp"

namespace aster::lang {

namespace fs = std::filesystem;

std::vector<std::string> prepareExportRun(const ExportFile& ex, Session& session) {
  std::vector<std::string> commandFiles;
  session.files.addInput(ex.source, "the .export file");
  for (const auto& e : ex.entries) {
    const std::string at = ex.where(e.line) + ": ";
    if (e.folder)
      throw Error(at + "folders (R lines) are not supported: list the files of " + e.path.string() +
                  " one by one (F lines)");
    if (e.compressed)
      throw Error(at + "gzipped files (flag C) are not supported: gunzip " + e.path.string() +
                  " and list it without C");
    const fs::path path = fs::absolute(ex.resolve(e)).lexically_normal();
    if (e.result && !session.unsafeLua) {
      // An .export is untrusted input as a study is: it writes only inside its own folder.
      std::error_code folderError, fileError;
      const fs::path folder = fs::weakly_canonical(fs::absolute(ex.source).parent_path(), folderError);
      const fs::path file = fs::weakly_canonical(path, fileError);
      const fs::path rel = file.lexically_relative(folder);
      if (folderError || fileError || rel.empty() || *rel.begin() == "..")
        throw Error(at + "the result file " + path.string() + " is outside the .export's folder " + folder.string() +
                    ": an .export writes only inside its own folder (run with --unsafe-lua if you trust it)");
    }
    if (e.data) {
      std::error_code ec;
      const auto type = fs::status(path, ec).type();
      if (type == fs::file_type::not_found || ec)
        throw Error(at + "the file " + path.string() + " does not exist");
      if (type != fs::file_type::regular) throw Error(at + path.string() + " is not a regular file");
      // D and DR alike: the run never writes over a file it reads.
      session.files.addInput(path, "listed as a data file in " + ex.where(e.line));
    }
    if (e.isCommandFile()) {
      commandFiles.push_back(path.string());
      continue;
    }
    // unit 0: a file the study opens by its name; "resu": the checks, written after the run.
    if (e.unit == 0 || e.type == "resu" || session.units.count(e.unit)) continue;
    if (e.type == "mess") continue;  // the messages go to the standard output
    session.units[e.unit] = path;
  }
  if (commandFiles.empty())
    throw Error(ex.source.string() + ": no command file (a line 'F comm <file> D 1') to run");
  return commandFiles;
}

std::vector<std::string> writeExportResults(const ExportFile& ex, Session& session) {
  std::vector<std::string> failures;
  for (const auto& e : ex.entries) {
    if (!e.result || e.folder) continue;
    const fs::path target = fs::absolute(ex.resolve(e)).lexically_normal();
    if (e.type == "mess") {
      failures.push_back("<A> <aster-lite> " + ex.where(e.line) + ": " + target.string() +
                         " not written: the messages are on the standard output");
      continue;
    }
    if (e.type != "resu" || session.checksOk + session.checksNook == 0) continue;  // no check: no .resu
    const fs::path resu = session.resuPath();
    std::ifstream in(resu, std::ios::binary);
    if (!in) {
      failures.push_back("<F> <aster-lite> " + ex.where(e.line) + ": cannot read " + resu.string());
      continue;
    }
    std::stringstream text;
    text << in.rdbuf();
    try {
      const std::string content = text.str();
      session.writeFile(target, [&](const fs::path& p) { writeTextFile(p, content); });
    } catch (const std::exception& err) {
      failures.push_back("<F> <aster-lite> " + ex.where(e.line) + ": " + err.what());
    }
  }
  return failures;
}

}  // namespace aster::lang
