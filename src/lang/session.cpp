#include "lang/session.hpp"

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

std::filesystem::path Session::checksPath() const {
  return outputDir / (studyPath.stem().string() + ".checks");
}

void Session::writeFile(const std::filesystem::path& target,
                        const std::function<void(const std::filesystem::path&)>& write) {
  if (!studyPath.empty()) files.addInput(studyPath, "the study file");
  writeAtomically(target, write, &files);
}

std::string Session::inputOf(const std::filesystem::path& file) {
  if (!studyPath.empty()) files.addInput(studyPath, "the study file");
  return files.inputOf(file);
}

void Session::checkUnitWritable(int unit, const std::filesystem::path& path) {
  namespace fs = std::filesystem;
  const std::string unitText = "UNITE=" + std::to_string(unit);
  if (const std::string how = inputOf(path); !how.empty())
    throw Error(unitText + " is bound to " + path.string() + ", an input of the study (" + how +
                "): aster-lite never writes over a file the study read; bind another file to the unit");
  if (unsafeLua || !unitsBoundByStudy.count(unit)) return;
  std::error_code fileError, folderError;
  const fs::path file = fs::weakly_canonical(fs::absolute(path), fileError);
  const fs::path folder = fs::weakly_canonical(fs::absolute(outputDir), folderError);
  const auto rel = file.lexically_relative(folder);
  if (fileError || folderError || rel.empty() || *rel.begin() == "..")
    throw Error(unitText + " is bound by DEFI_FICHIER to " + path.string() +
                ", outside the output folder " + outputDir.string() +
                ": a study writes only below its output folder (bind the unit with -u on the command line, "
                "or run with --unsafe-lua if you trust the study)");
}

void Session::recordCheck(const std::string& block, bool ok) {
  (ok ? checksOk : checksNook) += 1;
  // Checks are always shown, even with --quiet: they are the study's verdict.
  std::fputs(block.c_str(), stdout);
  std::fflush(stdout);
  const auto path = outputFile(resuPath().filename().string());
  if (!studyPath.empty()) files.addInput(studyPath, "the study file");
  appendAtomically(path, block, checksOk + checksNook > 1 && files.written(path), &files);
  // One line a check, for programs (tools/astest): its verdict and where the study made it.
  const auto list = outputFile(checksPath().filename().string());
  appendAtomically(list, std::string(ok ? "OK" : "NOOK") + "\t" + where + "\n",
                   checksOk + checksNook > 1 && files.written(list), &files);
}

std::string Session::recordCheckSummary() {
  const int total = checksOk + checksNook;
  if (total == 0) return "";
  const std::string line =
      "<I> checks: " + std::to_string(checksOk) + " OK, " + std::to_string(checksNook) + " NOOK";
  const auto path = outputFile(resuPath().filename().string());
  appendAtomically(path, "\n" + line + "\n", files.written(path), &files);
  return line;
}

}  // namespace aster::lang
