#include "commands/result_concepts.hpp"

#include <cmath>

#include "core/error.hpp"
#include "core/number_format.hpp"

namespace aster::lang {

const ResultInstant& ResultConcept::at(double time, double precision) const {
  for (const auto& i : instants)
    if (std::fabs(i.time - time) <= precision * std::max(1.0, std::fabs(time))) return i;
  std::string list;
  for (const auto& i : instants) list += (list.empty() ? "" : ", ") + format::asterValue(i.time);
  throw Error("INST=" + format::asterValue(time) + " is not an instant of the result (instants: " +
              (list.empty() ? std::string("none") : list) + ")");
}

const ResultInstant& ResultConcept::last() const {
  if (instants.empty()) throw Error("the result holds no converged instant");
  return instants.back();
}

const mesh::NodalField& ResultConcept::nodalField(const ResultInstant& i, const std::string& name) {
  std::string list;
  for (const auto& f : i.nodal) {
    if (f.name == name) return f;
    list += (list.empty() ? "" : ", ") + f.name;
  }
  if (cellField(i, name))
    throw Error("NOM_CHAM='" + name + "' is a field at Gauss points, not at nodes (nodal fields at INST=" +
                format::asterValue(i.time) + ": " + list + ")");
  for (const auto& g : i.cells) list += (list.empty() ? "" : ", ") + g.name;
  throw Error("NOM_CHAM='" + name + "' is not stored in the result at INST=" + format::asterValue(i.time) +
              " (fields: " + list + ")");
}

const CellField* ResultConcept::cellField(const ResultInstant& i, const std::string& name) {
  for (const auto& g : i.cells)
    if (g.name == name) return &g;
  return nullptr;
}

}  // namespace aster::lang
