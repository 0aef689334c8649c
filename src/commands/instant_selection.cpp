#include "commands/instant_selection.hpp"

#include <cmath>
#include <string>

#include "commands/function_concepts.hpp"
#include "core/error.hpp"

namespace aster::lang {

std::vector<const ResultInstant*> selectedInstants(const ResultConcept& r, const Keywords& occ) {
  std::vector<const ResultInstant*> out;
  if (occ.has("NUME_ORDRE")) {
    for (const auto& v : occ.values("NUME_ORDRE")) {
      const ResultInstant* found = nullptr;
      std::string list;
      for (const auto& i : r.instants) {
        if (i.index == v.integer) found = &i;
        list += (list.empty() ? "" : ", ") + std::to_string(i.index);
      }
      if (!found)
        throw Error("NUME_ORDRE=" + std::to_string(v.integer) + " is not stored in the result (NUME_ORDRE: " +
                    (list.empty() ? std::string("none") : list) + ")");
      out.push_back(found);
    }
    return out;
  }
  std::vector<double> times;
  if (occ.has("INST")) times = occ.reals("INST");
  else if (occ.has("LIST_INST")) times = occ.concept<RealListConcept>("LIST_INST")->values;
  else {
    for (const auto& i : r.instants) out.push_back(&i);
    if (out.empty()) throw Error("RESULTAT: the result holds no instant");
    return out;
  }
  const double precision = occ.has("PRECISION") ? occ.real("PRECISION") : 1e-6;
  const bool absolute = occ.has("CRITERE") && occ.text("CRITERE") == "ABSOLU";
  for (double t : times) {
    const ResultInstant* found = nullptr;
    if (absolute)
      for (const auto& i : r.instants)
        if (!found && std::fabs(i.time - t) <= precision) found = &i;
    out.push_back(found ? found : &r.at(t, precision));
  }
  return out;
}

}  // namespace aster::lang
