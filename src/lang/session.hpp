// What a running study shares with every command operator: where the study is,
// where results go, the files bound to units, the checks made so far.
#pragma once
#include <filesystem>
#include <functional>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "core/atomic_write.hpp"
#include "core/concept.hpp"

namespace aster::lang {

struct Session {
  std::filesystem::path studyPath;  // as given on the command line (the .export for a test)
  // The study file being run continues one run before it in this run (several
  // study files, or an .export's command files): POURSUITE may be used.
  bool continuesEarlierFile = false;
  std::filesystem::path outputDir;  // results, tables, plots
  std::map<int, std::filesystem::path> units;  // DEFI_FICHIER and -u N=path
  // The units the study itself bound (DEFI_FICHIER), not the command line (-u).
  std::set<int> unitsBoundByStudy;

  // --unsafe-lua: keep os.execute, io.popen, binary chunks and C modules.
  bool unsafeLua = false;

  // Where the command being run was called from: "studies/a.lua:12".
  std::string where;
  std::string command;
  // The variable its result is assigned to on that line ("RESU" for
  // RESU = STAT_NON_LINE{...}), empty when the call is no plain assignment.
  std::string assignedName;

  // Concepts a macro-command created under names given with CO('name'):
  // the interpreter binds each to a global variable of the study after the call.
  std::vector<std::pair<std::string, ConceptPtr>> produced;
  // Concepts DETRUIRE destroyed: the interpreter unbinds the study's variables
  // that hold them after the call.
  std::vector<ConceptPtr> destroyed;

  // The files of the run: those the study read (LIRE_MAILLAGE, DEFI_FICHIER
  // ACCES='OLD', the study itself), which are never written over, and those it wrote.
  RunFiles files;
  // Every file a command writes: complete or absent (writeAtomically), never over
  // an input of the study; the study file counts as one.
  void writeFile(const std::filesystem::path& target, const std::function<void(const std::filesystem::path&)>& write);
  // How `file` was read when it is an input of the study (the study file included), else "".
  std::string inputOf(const std::filesystem::path& file);
  // Throws unless a command may write `path`, the file bound to `unit`: never an
  // input of the study; in the sandbox, a file the study bound (DEFI_FICHIER)
  // only below the output folder (-u on the command line is the user's choice).
  void checkUnitWritable(int unit, const std::filesystem::path& path);

  // TEST_RESU and friends: counts, and the lines of <output-dir>/<study>.resu.
  int checksOk = 0;
  int checksNook = 0;
  // Prints a check block, appends it to the .resu file, counts it (the .checks
  // records are written by the checks themselves: check_keywords.cpp).
  void recordCheck(const std::string& block, bool ok);
  // The closing line of the checks ("<I> checks: 3 OK, 0 NOOK"), printed and
  // appended to the .resu file at the end of the run; empty when there were none.
  std::string recordCheckSummary();

  // Plots whose gnuplot scripts IMPR_FONCTION wrote: one gnuplot draws them all
  // at the end of the run, however it ends (FIN, <F>, Ctrl-C), so its start-up
  // (0.2 s, most of a small study's time) is paid once, not once per plot.
  struct PlotScript {
    std::filesystem::path script, image;
    std::string where;  // "IMPR_FONCTION" and file:line, for messages
  };
  std::vector<PlotScript> plots;
  // Set by IMPR_FONCTION: draws `plots`, returns one message per plot it could not draw.
  std::function<std::vector<std::string>(const std::vector<PlotScript>&)> drawPlots;
  std::filesystem::path resuPath() const;

  // The study's name for a concept ("MAIL"), or a generated one: set by the interpreter.
  std::function<std::string(const Concept&)> nameOf = [](const Concept& c) {
    return c.name.empty() ? c.typeName() : c.name;
  };

  // A path relative to the study's folder, as code_aster users expect for FICHIER=.
  std::filesystem::path studyRelative(const std::string& file) const;
  // The file bound to a unit, or the default "<study>.<extension>" beside the study.
  std::filesystem::path unitPath(int unit, const std::string& defaultExtension) const;
  // Makes sure the output folder exists; returns path/name inside it.
  std::filesystem::path outputFile(const std::string& name) const;
  // A file stem in the output folder not handed out before in this run: `base`,
  // then base-2, base-3, ... (a STAT_NON_LINE in a loop gets its own files each
  // time; "-" because "_<k>" numbers the instants of one result).
  std::string uniqueOutputStem(const std::string& base);

 private:
  std::map<std::string, int> stems_;
};

}  // namespace aster::lang
