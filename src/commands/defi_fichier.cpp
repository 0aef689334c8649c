// DEFI_FICHIER: binds a file to a logical unit (UNITE) for later commands, or
// releases a unit, given by its number or by the file bound to it.
#include <filesystem>
#include <string>
#include <system_error>

#include "core/error.hpp"
#include "lang/operators.hpp"

namespace aster::lang {
namespace {

namespace fs = std::filesystem;

// One spelling per file: "./a.med", "a.med" and its absolute path are the same file.
fs::path sameFileKey(const fs::path& p) {
  std::error_code ec;
  fs::path c = fs::weakly_canonical(fs::absolute(p), ec);
  return ec ? fs::absolute(p).lexically_normal() : c;
}

std::string boundUnits(const Session& session) {
  if (session.units.empty()) return "no unit is bound";
  std::string s = "bound units:";
  for (const auto& [unit, path] : session.units) s += " " + std::to_string(unit) + " -> " + path.string() + ",";
  s.pop_back();
  return s;
}

ConceptPtr defiFichier(const Keywords& k, Session& session, ConceptPtr) {
  if (k.text("ACTION") == "LIBERER") {
    // The catalogue's UN_PARMI('UNITE', 'FICHIER') guarantees exactly one of them.
    if (k.has("UNITE")) {
      const int unit = static_cast<int>(k.integer("UNITE"));
      if (session.units.erase(unit) == 0)
        throw Error("UNITE=" + std::to_string(unit) + ": no file is bound to unit " + std::to_string(unit) +
                    ", nothing to release (" + boundUnits(session) + ")");
      return nullptr;
    }
    const std::string file = k.text("FICHIER");
    const fs::path wanted = sameFileKey(session.studyRelative(file));
    int released = 0;
    for (auto it = session.units.begin(); it != session.units.end();) {
      if (sameFileKey(it->second) == wanted) {
        it = session.units.erase(it);
        ++released;
      } else {
        ++it;
      }
    }
    if (released == 0)
      throw Error("FICHIER='" + file + "': no unit is bound to " + wanted.string() + ", nothing to release (" +
                  boundUnits(session) + ")");
    return nullptr;
  }
  const int unit = static_cast<int>(k.integer("UNITE"));
  const std::string file = k.has("FICHIER") ? k.text("FICHIER") : "fort." + std::to_string(unit);
  session.units[unit] = session.studyRelative(file);
  session.unitsBoundByStudy.insert(unit);
  if (k.text("ACCES") == "OLD")  // declared for reading: never written over
    session.files.addInput(session.units[unit], "bound for reading by DEFI_FICHIER at " + session.where);
  return nullptr;
}

RegisterOperator reg("DEFI_FICHIER", defiFichier);

}  // namespace
}  // namespace aster::lang
