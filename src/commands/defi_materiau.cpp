// DEFI_MATERIAU: the data of a material's behaviours (ELAS, ECRO_LINE, TRACTION,
// PRAGER, ELAS_HYPER). Each relation checks its own parameters when STAT_NON_LINE
// builds it (model/behaviour.hpp); here only what each keyword alone requires.
#include "commands/function_concepts.hpp"
#include "commands/model_concepts.hpp"
#include "core/error.hpp"
#include "expr/constant.hpp"
#include "expr/tabulated.hpp"
#include "lang/operators.hpp"

namespace aster::lang {
namespace {

// TRACTION's SIGM: the points of a tabulated function of EPSI and its PROL_DROITE.
mechanics::TractionCurve tractionCurve(const Keywords& traction, Session& session) {
  const ConceptPtr sigm = traction.conceptPtr("SIGM");
  const std::string name = session.nameOf(*sigm);
  const auto f = functionOf(sigm);
  if (dynamic_cast<const expr::Constant*>(f.get()))
    throw Error("TRACTION/SIGM: " + name + " is a constant function; the traction curve is a function of EPSI "
                "given by points (DEFI_FONCTION NOM_PARA='EPSI')");
  const auto* curve = dynamic_cast<const expr::Tabulated*>(f.get());
  if (!curve)
    throw Error("TRACTION/SIGM: " + name + " is not a function given by points; the traction curve is a "
                "DEFI_FONCTION of EPSI");
  if (curve->parameters().size() != 1 || curve->parameters().front() != "EPSI")
    throw Error("TRACTION/SIGM: " + name + " is a function of " + expr::joinNames(curve->parameters()) +
                "; the traction curve is a function of EPSI (DEFI_FONCTION NOM_PARA='EPSI')");
  mechanics::TractionCurve out;
  out.strain = curve->abscissas();
  out.stress = curve->ordinates();
  switch (curve->options().right) {
    case expr::Extension::Linear: out.beyond = mechanics::IsotropicHardening::Beyond::Linear; break;
    case expr::Extension::Constant: out.beyond = mechanics::IsotropicHardening::Beyond::Constant; break;
    case expr::Extension::Excluded: out.beyond = mechanics::IsotropicHardening::Beyond::Refuse; break;
  }
  return out;
}

ConceptPtr defiMateriau(const Keywords& k, Session& session, ConceptPtr) {
  auto m = std::make_shared<model::ElasticMaterial>();
  m->hasElas = k.has("ELAS");
  if (m->hasElas) {
    const auto& elas = k.factor("ELAS").front();
    m->E = elas.real("E");
    m->NU = elas.real("NU");
    if (!(m->E > 0)) throw Error("ELAS/E must be positive, got " + std::to_string(m->E));
    if (!(m->NU > -1 && m->NU < 0.5)) throw Error("ELAS/NU must lie in ]-1, 0.5[, got " + std::to_string(m->NU));
    if (elas.has("RHO")) {
      m->RHO = elas.real("RHO");
      m->hasRho = true;
    }
  }
  if (k.has("ECRO_LINE")) {
    const auto& ecro = k.factor("ECRO_LINE").front();
    m->ecroLine = model::LinearHardeningData{ecro.real("D_SIGM_EPSI"), ecro.real("SY")};
  }
  if (k.has("TRACTION")) m->traction = tractionCurve(k.factor("TRACTION").front(), session);
  if (k.has("PRAGER")) m->prager = k.factor("PRAGER").front().real("C");
  if (k.has("ELAS_HYPER")) {
    const auto& hyper = k.factor("ELAS_HYPER").front();
    model::HyperelasticData h;
    h.c10 = hyper.real("C10");
    h.c01 = hyper.real("C01");
    h.c20 = hyper.real("C20");
    h.bulkGiven = hyper.has("K");
    if (h.bulkGiven) h.bulk = hyper.real("K");
    else h.poisson = hyper.real("NU");
    h.rho = hyper.real("RHO");
    m->hyper = h;
  }
  if (k.has("LEMAITRE")) {
    const auto& lemaitre = k.factor("LEMAITRE").front();
    m->lemaitre = model::LemaitreData{lemaitre.real("N"), lemaitre.real("UN_SUR_K"), lemaitre.real("UN_SUR_M")};
  }
  return std::make_shared<MaterialConcept>(m);
}

RegisterOperator reg("DEFI_MATERIAU", defiMateriau);

}  // namespace
}  // namespace aster::lang
