#include "lang/session.hpp"

#include <system_error>

#include "core/error.hpp"

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

}  // namespace aster::lang
