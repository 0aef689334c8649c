// CALC_SOLU_MANU: the loads of a manufactured solution for finite-strain (or
// small-strain) plane elasticity, derived exactly by automatic differentiation
// from the displacement formulas. Returns formulas of (X, Y):
//   mms.FORCE_INTERNE.FX/FY   body force -div Pi
//   mms.<BORD>.FX/FY          nominal traction Pi.N on each boundary
//   mms.<BORD>.FX_T/FY_T/PRES tangential traction and contact pressure (CONTACT='OUI')
//   mms.DEPL.DX/DY            the displacement itself
#include <algorithm>
#include <cstdio>
#include <map>

#include "commands/function_concepts.hpp"
#include "commands/mesh_concept.hpp"
#include "commands/model_concepts.hpp"
#include "core/error.hpp"
#include "core/messages.hpp"
#include "expr/expression.hpp"
#include "mechanics/manufactured.hpp"
#include "lang/operators.hpp"

namespace aster::lang {
namespace {

class ManufacturedConcept : public Concept {
 public:
  std::string typeName() const override { return "solu_manu"; }
  // group ("FORCE_INTERNE", "BAS", "DEPL") -> component ("FX", "PRES", ...) -> formula
  std::map<std::string, std::vector<std::pair<std::string, ConceptPtr>>> groups;
};

ConceptPtr formula(expr::FunctionPtr f) { return std::make_shared<FunctionConcept>("formule", std::move(f)); }

expr::ExpressionPtr expressionOf(const Keywords& occ, const std::string& key) {
  auto f = std::dynamic_pointer_cast<const expr::Expression>(functionOf(occ.conceptPtr(key)));
  if (!f)
    throw Error("DEPL/" + key + " must be a FORMULE given as a text (VALE='...'), so that it can be "
                "differentiated exactly; a Lua function or a tabulated function cannot");
  for (const auto& p : f->parameters())
    if (p != "X" && p != "Y")
      throw Error("DEPL/" + key + " may depend on X and Y only; it has parameter " + p);
  return f;
}

// Samples p along the cells of a group: 20 points per segment, through its
// isoparametric map. Warns when the exact solution is not in contact (p > 0).
void checkContactConditions(const mesh::Mesh& mesh, const std::string& group, const mechanics::ManufacturedElasticity& s,
                            const Eigen::Vector2d& N, bool verbose) {
  double pmin = 1e300, pmax = -1e300, xAtMax = 0, yAtMax = 0;
  for (int c : mesh.cellGroup(group)) {
    const auto nodes = mesh.cellNodes(c);
    for (int k = 0; k <= 20; ++k) {
      const double xi = -1.0 + 2.0 * k / 20.0;
      double w[3];
      int n = nodes.size();
      if (n == 2) {
        w[0] = (1 - xi) / 2;
        w[1] = (1 + xi) / 2;
      } else if (n == 3) {
        w[0] = xi * (xi - 1) / 2;
        w[1] = xi * (xi + 1) / 2;
        w[2] = 1 - xi * xi;
      } else {
        throw Error("BORD " + group + ": cell " + mesh.cellName(c) + " is not a SEG2 or SEG3");
      }
      double X = 0, Y = 0;
      for (int a = 0; a < n; ++a) {
        X += w[a] * mesh.node(nodes[a])(0);
        Y += w[a] * mesh.node(nodes[a])(1);
      }
      const double p = s.contact(X, Y, N).pressure;
      pmin = std::min(pmin, p);
      if (p > pmax) {
        pmax = p;
        xAtMax = X;
        yAtMax = Y;
      }
    }
  }
  char buf[256];
  std::snprintf(buf, sizeof buf, "CALC_SOLU_MANU: exact contact pressure on %s: min %.6g, max %.6g", group.c_str(),
                pmin, pmax);
  if (verbose) Messages::info(buf);
  if (pmax > 0) {
    std::snprintf(buf, sizeof buf,
                  "the exact contact pressure on %s is positive (%.6g at X=%.6g, Y=%.6g): the manufactured solution "
                  "violates the contact conditions p <= 0 there, so a contact solver cannot reproduce it",
                  group.c_str(), pmax, xAtMax, yAtMax);
    Messages::alarm("CALC_SOLU_MANU", buf);
  }
}

ConceptPtr calcSoluManu(const Keywords& k, Session&, ConceptPtr) {
  const auto& depl = k.factor("DEPL").front();
  const auto ux = expressionOf(depl, "DX");
  const auto uy = expressionOf(depl, "DY");
  const auto& mat = *static_cast<MaterialConcept&>(*k.conceptPtr("MATER")).material;
  auto sol = std::make_shared<mechanics::ManufacturedElasticity>(
      ux, uy, mat.E, mat.NU, mechanics::planeHypothesisFromName(k.text("MODELISATION")),
      mechanics::kinematicsFromName(k.text("DEFORMATION")));
  auto out = std::make_shared<ManufacturedConcept>();
  using Q = mechanics::ManufacturedQuantity;
  out->groups["DEPL"] = {{"DX", depl.conceptPtr("DX")}, {"DY", depl.conceptPtr("DY")}};
  out->groups["FORCE_INTERNE"] = {{"FX", formula(mechanics::manufacturedFunction(sol, Q::BodyForce, 0))},
                                  {"FY", formula(mechanics::manufacturedFunction(sol, Q::BodyForce, 1))}};
  const mesh::Mesh* mesh = k.has("MAILLAGE") ? &meshOf(k.conceptPtr("MAILLAGE")) : nullptr;
  for (const auto& bord : k.factor("BORD")) {
    const std::string name = bord.text("NOM");
    if (name == "DEPL" || name == "FORCE_INTERNE" || out->groups.count(name))
      throw Error(bord.path + ": NOM='" + name + "' is used twice or clashes with DEPL / FORCE_INTERNE");
    const auto n = bord.reals("NORMALE");
    const Eigen::Vector2d N(n[0], n[1]);
    if (N.norm() == 0) throw Error(bord.path + ": NORMALE must not be zero");
    auto& g = out->groups[name];
    g = {{"FX", formula(mechanics::manufacturedFunction(sol, Q::Traction, 0, N))},
         {"FY", formula(mechanics::manufacturedFunction(sol, Q::Traction, 1, N))}};
    if (bord.text("CONTACT") == "OUI") {
      g.push_back({"FX_T", formula(mechanics::manufacturedFunction(sol, Q::TangentialTraction, 0, N))});
      g.push_back({"FY_T", formula(mechanics::manufacturedFunction(sol, Q::TangentialTraction, 1, N))});
      g.push_back({"PRES", formula(mechanics::manufacturedFunction(sol, Q::ContactPressure, 0, N))});
      if (mesh)
        checkContactConditions(*mesh, name, *sol, N.normalized(), k.integer("INFO") >= 1);
      else
        Messages::info("CALC_SOLU_MANU: " + bord.path + ": without MAILLAGE the contact condition p <= 0 is not "
                       "checked along " + name + " (give MAILLAGE to check it)");
    }
  }
  return out;
}

Datum field(Concept& self, const std::string& key) {
  const auto& groups = static_cast<ManufacturedConcept&>(self).groups;
  auto it = groups.find(key);
  if (it == groups.end()) return Datum{};
  std::vector<std::pair<std::string, Datum>> m;
  for (const auto& [name, c] : it->second) m.emplace_back(name, Datum::ofConcept(c));
  return Datum::ofMap(m);
}

RegisterOperator reg("CALC_SOLU_MANU", calcSoluManu);
struct RegisterFields {
  RegisterFields() { Operators::instance().setFieldGetter("solu_manu", field); }
} regFields;

}  // namespace
}  // namespace aster::lang
