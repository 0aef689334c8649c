#include "commands/check_keywords.hpp"

#include "core/error.hpp"

namespace aster::lang {

post::CheckSpec checkSpecOf(const Keywords& k) {
  post::CheckSpec s;
  s.hasValeCalc = k.has("VALE_CALC");
  if (s.hasValeCalc) s.valeCalc = k.real("VALE_CALC");
  s.toleMachine = k.real("TOLE_MACHINE");
  s.reference = k.text("REFERENCE");
  s.hasValeRefe = k.has("VALE_REFE");
  // VALE_REFE and PRECISION come together (the catalogue's block on REFERENCE).
  if (s.hasValeRefe) {
    s.valeRefe = k.real("VALE_REFE");
    s.precision = k.real("PRECISION");
  }
  s.relative = k.text("CRITERE") == "RELATIF";
  s.ordreGrandeur = k.has("ORDRE_GRANDEUR") ? k.real("ORDRE_GRANDEUR") : 0.0;  // 0: no magnitude given
  s.legende = k.text("LEGENDE");
  if (s.reference != "NON_REGRESSION" && !s.hasValeRefe)
    throw Error((k.path.empty() ? "" : k.path + ": ") + "REFERENCE='" + s.reference + "' needs VALE_REFE");
  if (!s.hasValeCalc && !s.hasValeRefe)
    throw Error((k.path.empty() ? "" : k.path + ": ") + "give VALE_CALC (and VALE_REFE with a REFERENCE)");
  return s;
}

void recordCheck(Session& session, double computed, const post::CheckSpec& spec,
                 const std::vector<std::pair<std::string, std::string>>& what) {
  const auto lines = post::check(computed, spec);
  bool ok = true;
  for (const auto& l : lines) ok = ok && l.ok;
  session.recordCheck(post::formatCheck(what, lines, spec.legende), ok);
}

}  // namespace aster::lang
