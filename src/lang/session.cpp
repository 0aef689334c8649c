#include "lang/session.hpp"

#include <fstream>
#include <system_error>

#include "core/messages.hpp"

#include "core/error.hpp"
#include <cstdio>

namespace aster::lang {

std::filesystem::path Session::studyRelative(const std::string& file) const {
  std::filesystem::path p(file);
  if (p.is_absolute()) return p;
  return studyPath.parent_path() / p;
}

std::filesystem::path Session::unitPath(int unit, const std::string& defaultExtension) const {
  auto it = units.find(unit);
  if (it != units.end()) return it->second;
  std::filesystem::path p = studyPath;
  return p.replace_extension(defaultExtension);
}

std::filesystem::path Session::outputFile(const std::string& name) const {
  std::error_code ec;
  std::filesystem::create_directories(outputDir, ec);
  if (ec) throw Error("cannot create the output folder " + outputDir.string() + ": " + ec.message());
  return outputDir / name;
}

std::string Session::uniqueOutputStem(const std::string& base) {
  const int n = ++stems_[base];
  return n == 1 ? base : base + "-" + std::to_string(n);
}

std::filesystem::path Session::resuPath() const {
  return outputDir / (studyPath.stem().string() + ".resu");
}

void Session::recordCheck(const std::string& block, bool ok) {
  (ok ? checksOk : checksNook) += 1;
  // Checks are always shown, even with --quiet: they are the study's verdict.
  std::fputs(block.c_str(), stdout);
  std::fflush(stdout);
  const auto path = outputFile(resuPath().filename().string());
  std::ofstream out(path, checksOk + checksNook == 1 ? std::ios::trunc : std::ios::app);
  out << block;
  if (!out) throw Error("cannot write " + path.string());
}

std::string Session::recordCheckSummary() {
  const int total = checksOk + checksNook;
  if (total == 0) return "";
  const std::string line =
      "<I> checks: " + std::to_string(checksOk) + " OK, " + std::to_string(checksNook) + " NOOK";
  const auto path = outputFile(resuPath().filename().string());
  std::ofstream out(path, std::ios::app);
  out << "\n" << line << "\n";
  return line;
}

}  // namespace aster::lang
