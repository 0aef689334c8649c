// aster-lite: runs a code_aster-style study written in Lua.
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <string>
#include <vector>

#include "comm/translate.hpp"
#include "core/interrupt.hpp"
#include "core/messages.hpp"
#include "lang/catalogue.hpp"
#include "core/export_file.hpp"
#include "lang/docgen.hpp"
#include "lang/export_run.hpp"
#include "lang/interpreter.hpp"
#include "lang/session.hpp"
#include "linalg/blas_info.hpp"
#include "linalg/factor_memory.hpp"

namespace {

const char* kUsage =
    "usage: aster-lite [options] STUDY.lua [PART2.lua ...]\n"
    "       aster-lite [options] TEST.export\n"
    "\n"
    "Runs a study file written in Lua with code_aster's commands. Several study\n"
    "files run in order in one study, each continuing the one before (POURSUITE).\n"
    "A code_aster command file (.comm, .com0 to .com9) runs as a study: it is\n"
    "translated to Lua line for line (--to-lua prints the translation).\n"
    "A code_aster .export runs its command files so, with its data files bound to\n"
    "their units and its result files written where it lists them (paths from the\n"
    ".export's folder; output folder: the .export's name beside it).\n"
    "\n"
    "options:\n"
    "  --output-dir DIR  where results, tables and plots go\n"
    "                    (default: a folder named after the study, next to it)\n"
    "  -u N=PATH         bind file PATH to logical unit N (as DEFI_FICHIER does;\n"
    "                    it overrides the .export's unit N)\n"
    "  --quiet           print only alarms, errors and check results\n"
    "  --unsafe-lua      lift the Lua sandbox: give the study plain Lua (os.execute,\n"
    "                    io.popen, the debug library, binary chunks, C modules, files\n"
    "                    written anywhere, an .export's result files outside its\n"
    "                    folder) and let gmsh run .geo scripts\n"
    "  --doc FILE        write the command reference (Markdown) to FILE and exit\n"
    "  --to-lua FILE     print the Lua translation of a code_aster command file and exit\n"
    "  --version         print the version and exit\n"
    "  --help            print this help and exit\n"
    "\n"
    "exit status: 0 the study ran and every check was OK, 1 a check was NOOK,\n"
    "             2 a fatal error (<F>) stopped the study (or was caught by it),\n"
    "             130 Ctrl-C stopped it (converged instants are on disk)\n";

int usageError(const std::string& what) {
  std::fprintf(stderr, "<F> <aster-lite> %s\n%s", what.c_str(), kUsage);
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  aster::linalg::startBlasOnOneThread();
  aster::linalg::selectBlasKernels();
  aster::linalg::keepFactorWorkspaces();
  if (const std::string error = aster::linalg::reserveBlasBuffer(); !error.empty()) {
    std::fprintf(stderr, "<F> <aster-lite> %s\n", error.c_str());
    return 2;
  }
  namespace fs = std::filesystem;
  aster::lang::Session session;
  std::vector<std::string> studies;
  std::string outputDir;
  bool quiet = false;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto next = [&](const char* opt) -> std::string {
      if (i + 1 >= argc) throw std::runtime_error(std::string(opt) + " needs a value");
      return argv[++i];
    };
    try {
      if (a == "--help" || a == "-h") {
        std::fputs(kUsage, stdout);
        return 0;
      } else if (a == "--version") {
        std::printf("aster-lite %s\n", ASTER_VERSION);
        return 0;
      } else if (a == "--quiet" || a == "-q") {
        quiet = true;
      } else if (a == "--unsafe-lua") {
        session.unsafeLua = true;
      } else if (a == "--output-dir") {
        outputDir = next("--output-dir");
      } else if (a == "-u") {
        const std::string spec = next("-u");
        const auto eq = spec.find('=');
        char* end = nullptr;
        errno = 0;
        const long unit = std::strtol(spec.c_str(), &end, 10);
        if (eq == std::string::npos || end != spec.c_str() + eq || unit <= 0)
          return usageError("-u expects N=PATH with a positive unit number N, got '" + spec + "'");
        // Units are C++ ints, as the UNITE keywords: a larger N would wrap to another unit.
        if (errno == ERANGE || unit > std::numeric_limits<int>::max())
          return usageError("-u expects N=PATH with a unit number N from 1 to " +
                            std::to_string(std::numeric_limits<int>::max()) + ", got '" + spec + "'");
        session.units[static_cast<int>(unit)] = fs::absolute(spec.substr(eq + 1));
      } else if (a == "--to-lua") {
        const std::string file = next("--to-lua");
        std::ifstream in(file, std::ios::binary);
        if (!in) return usageError("cannot read " + file);
        const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
        const auto lua = aster::comm::translateCommandFile(text, file);
        if (!lua.ok) {
          std::fprintf(stderr, "<F> <COMM> %s\n", lua.error.c_str());
          return 2;
        }
        std::fputs(lua.lua.c_str(), stdout);
        return 0;
      } else if (a == "--doc") {
        const std::string file = next("--doc");
        std::ofstream out(file, std::ios::binary);
        out << aster::lang::commandReference(aster::lang::Catalogue::builtin());
        if (!out) return usageError("cannot write " + file);
        return 0;
      } else if (!a.empty() && a[0] == '-') {
        return usageError("unknown option " + a);
      } else {
        studies.push_back(a);
      }
    } catch (const std::exception& e) {
      return usageError(e.what());
    }
  }
  if (studies.empty()) return usageError("no study file given");
  const bool isExport = fs::path(studies.front()).extension() == ".export";
  for (const auto& file : studies)
    if (fs::path(file).extension() == ".export" && studies.size() > 1)
      return usageError("an .export is run alone: got " + studies.front() + " and " + studies.back());
  for (const auto& study : studies) {
    if (!fs::exists(study)) return usageError("the study file " + study + " does not exist");
    // A directory would read as an empty study (exit 0, nothing done), a FIFO
    // would block: only a regular file (or a link to one) is a study.
    std::error_code ec;
    const auto type = fs::status(study, ec).type();
    if (type != fs::file_type::regular) {
      const char* kind = type == fs::file_type::directory   ? "a directory"
                         : type == fs::file_type::fifo      ? "a FIFO"
                         : type == fs::file_type::character ? "a character device"
                         : type == fs::file_type::block     ? "a block device"
                         : type == fs::file_type::socket    ? "a socket"
                                                            : "not a regular file";
      return usageError("the study file " + study + " is " + kind + ", not a regular file holding a study");
    }
  }

  aster::Messages::setQuiet(quiet);
  aster::interrupt::install();
  const std::string& first = studies.front();
  session.studyPath = first;
  session.outputDir = outputDir.empty() ? fs::path(first).replace_extension("") : fs::path(outputDir);
  try {
    aster::ExportFile exportFile;
    if (isExport) {
      exportFile = aster::readExportFile(first);
      studies = aster::lang::prepareExportRun(exportFile, session);
    }
    for (const auto& study : studies) session.files.addInput(study, "a study file");
    aster::lang::Interpreter interpreter(session);
    int status = interpreter.runFiles(studies);
    if (isExport && status != aster::lang::kInterruptedStatus) {
      std::fflush(stdout);
      for (const auto& failure : aster::lang::writeExportResults(exportFile, session)) {
        std::fprintf(stderr, "%s\n", failure.c_str());
        if (failure.rfind("<F>", 0) == 0) status = 2;
      }
    }
    return status;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "<F> <aster-lite> %s\n", e.what());
    return 2;
  }
}
