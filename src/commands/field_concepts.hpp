// Nodal fields made by CREA_CHAMP: a field of functions (NOEU_NEUT_F: one
// function per node and component, evaluated by OPERATION='EVAL'), and helpers
// the post-processing operators share (components by name, the support).
#pragma once
#include <cmath>
#include <string>
#include <vector>

#include "commands/result_concepts.hpp"
#include "core/error.hpp"
#include "expr/function.hpp"
#include "lang/keywords.hpp"
#include "post/check.hpp"

namespace aster::lang {

// A cham_no_sdaster whose values are functions (TYPE_CHAM NOEU_*_F): field.values
// stays zero; functions[node * components + c] is the function (null: unassigned).
class FunctionFieldConcept : public NodalFieldConcept {
 public:
  using NodalFieldConcept::NodalFieldConcept;
  std::vector<expr::FunctionPtr> functions;
};

// Throws unless `cmp` is a component of the quantity (NEUT: X1, X2, ...; GEOM:
// X, Y, Z; DEPL: DX, DY, DZ, DRX..., LAGS_C...); other quantities are not checked.
inline void checkComponentOfQuantity(const std::string& quantity, const std::string& cmp) {
  bool ok = true;
  if (quantity == "NEUT") {
    ok = cmp.size() > 1 && cmp[0] == 'X';
    for (std::size_t i = 1; ok && i < cmp.size(); ++i) ok = cmp[i] >= '0' && cmp[i] <= '9';
  } else if (quantity == "GEOM") {
    ok = cmp == "X" || cmp == "Y" || cmp == "Z";
  } else if (quantity == "DEPL") {
    static const char* names[] = {"DX", "DY", "DZ", "DRX", "DRY", "DRZ", "LAGS_C", "LAGS_F1", "LAGS_F2"};
    ok = false;
    for (const char* n : names) ok = ok || cmp == n;
  }
  if (!ok)
    throw Error("component " + cmp + " does not belong to the quantity " + quantity +
                (quantity == "NEUT" ? " (X1, X2, ...)" : quantity == "GEOM" ? " (X, Y, Z)" : " (DX, DY, DZ, LAGS_C, ...)"));
}

inline int componentIndex(const std::vector<std::string>& components, const std::string& name,
                          const std::string& fieldName) {
  for (std::size_t i = 0; i < components.size(); ++i)
    if (components[i] == name) return static_cast<int>(i);
  std::string list;
  for (const auto& c : components) list += (list.empty() ? "" : ", ") + c;
  throw Error("the field " + fieldName + " has no component " + name + " (components: " +
              (list.empty() ? "none" : list) + ")");
}

inline int componentIndex(const mesh::NodalField& f, const std::string& name, const std::string& fieldName) {
  return componentIndex(f.components, name, fieldName);
}

// What an occurrence of ASSE takes from its CHAM_GD (nodal or at Gauss points alike):
// components NOM_CMP (default: all of `available`) renamed NOM_CMP_RESU, times COEF_R,
// added (CUMUL='OUI') or written over.
struct AsseTerm {
  std::vector<std::string> names, resultNames;
  bool cumul = false;
  double coef = 1.0;
};

inline AsseTerm asseTermOf(const Keywords& occ, const std::vector<std::string>& available) {
  AsseTerm t;
  t.names = occ.has("NOM_CMP") ? occ.texts("NOM_CMP") : available;
  t.resultNames = occ.has("NOM_CMP_RESU") ? occ.texts("NOM_CMP_RESU") : t.names;
  if (t.names.size() != t.resultNames.size())
    throw Error(occ.path + ": NOM_CMP has " + std::to_string(t.names.size()) + " component(s), NOM_CMP_RESU " +
                std::to_string(t.resultNames.size()));
  t.cumul = occ.text("CUMUL") == "OUI";
  t.coef = occ.real("COEF_R");
  return t;
}

// The nodes a field is defined on: its support, or every node of the mesh.
inline std::vector<int> supportOf(const NodalFieldConcept& f) {
  if (!f.support.empty()) return f.support;
  std::vector<int> all(static_cast<std::size_t>(f.mesh->nodeCount()));
  for (int i = 0; i < f.mesh->nodeCount(); ++i) all[static_cast<std::size_t>(i)] = i;
  return all;
}

inline bool isFunctionField(const NodalFieldConcept& f) {
  return dynamic_cast<const FunctionFieldConcept*>(&f) != nullptr;
}

// The instant an occurrence designates with INST (CRITERE, PRECISION) or
// NUME_ORDRE; the last one when neither is given.
inline const ResultInstant& instantOf(const ResultConcept& r, const Keywords& occ) {
  if (occ.has("NUME_ORDRE")) {
    const long long n = occ.integer("NUME_ORDRE");
    std::string list;
    for (const auto& i : r.instants) {
      if (i.index == n) return i;
      list += (list.empty() ? "" : ", ") + std::to_string(i.index);
    }
    throw Error("NUME_ORDRE=" + std::to_string(n) + " is not stored in the result (NUME_ORDRE: " +
                (list.empty() ? std::string("none") : list) + ")");
  }
  if (!occ.has("INST")) return r.last();
  const double t = occ.real("INST");
  const double precision = occ.real("PRECISION");
  if (occ.text("CRITERE") == "ABSOLU") {
    for (const auto& i : r.instants)
      if (std::abs(i.time - t) <= precision) return i;
  }
  return r.at(t, precision);
}

}  // namespace aster::lang
