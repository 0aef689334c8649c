#include "commands/result_concepts.hpp"

#include <algorithm>
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

void ResultConcept::requireNotExcluded(const ResultInstant& i, const std::string& name) {
  if (std::find(i.excluded.begin(), i.excluded.end(), name) != i.excluded.end())
    throw Error("NOM_CHAM='" + name + "' is not stored in the result at INST=" + format::asterValue(i.time) +
                ": STAT_NON_LINE was told not to store it (ARCHIVAGE/CHAM_EXCLU)");
}

const mesh::NodalField& ResultConcept::nodalField(const ResultInstant& i, const std::string& name) {
  std::string list;
  for (const auto& f : i.nodal) {
    if (f.name == name) return f;
    list += (list.empty() ? "" : ", ") + f.name;
  }
  if (cellField(i, name))
    throw Error("NOM_CHAM='" + name + "' is a field on cells (ELGA or ELNO), not at nodes (nodal fields at INST=" +
                format::asterValue(i.time) + ": " + list + ")");
  requireNotExcluded(i, name);
  for (const auto& g : i.cells) list += (list.empty() ? "" : ", ") + g.name;
  throw Error("NOM_CHAM='" + name + "' is not stored in the result at INST=" + format::asterValue(i.time) +
              " (fields: " + list + ")");
}

std::vector<int> ResultConcept::nodalSupportOf(const ResultInstant& i, const std::string& name) const {
  auto it = i.nodalSupport.find(name);
  if (it != i.nodalSupport.end()) return it->second;
  std::vector<int> nodes;
  for (int n = 0; n < model->mesh().nodeCount(); ++n)
    if (model->nodeInModel(n)) nodes.push_back(n);
  return nodes;
}

std::string quantityOfField(const std::string& name) {
  const std::string prefix = name.substr(0, name.find('_'));
  if (prefix == "SIEF" || prefix == "SIGM" || prefix == "SIEQ") return "SIEF";
  if (prefix == "EPSI" || prefix == "EPSG" || prefix == "EPSP") return "EPSI";
  if (prefix == "VARI") return "VARI";
  if (name == "DEPL" || name == "FORC_NODA" || name == "REAC_NODA") return "DEPL";
  return "";
}

const CellField* ResultConcept::cellField(const ResultInstant& i, const std::string& name) {
  for (const auto& g : i.cells)
    if (g.name == name) return &g;
  return nullptr;
}

}  // namespace aster::lang
