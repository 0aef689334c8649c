// What STAT_NON_LINE and MECA_STATIQUE share: the loads of EXCIT, and the fields of
// a solved state stored in their result (ResultInstant).
#pragma once
#include <memory>
#include <vector>

#include <Eigen/Core>

#include "analysis/additional_terms.hpp"
#include "analysis/mechanical_system.hpp"
#include "commands/model_concepts.hpp"
#include "commands/result_concepts.hpp"
#include "lang/operators.hpp"

namespace aster::lang {

// EXCIT: each CHARGE (on MODELE's model) with its FONC_MULT and TYPE_CHARGE, added to
// problem.loads; `keep` holds the loads the problem points to.
void readExcit(const Keywords& k, Session& session, const std::shared_ptr<model::Model>& model,
               analysis::MechanicalProblem& problem, std::vector<std::shared_ptr<LoadConcept>>& keep);

// The fields of a state stored in a result: DEPL (with the terms' own unknowns),
// REAC_NODA, FORC_NODA, the terms' fields, SIEF_ELGA (unless withStresses is false), and
// VARI_ELGA (V1, V2, ...) of the accepted state when a law has internal variables.
// REAC_NODA only when reactions is not null. The terms' fields (contact pressures...)
// only for a converged state (converged: the initial state was not solved for).
ResultInstant resultInstant(const analysis::MechanicalSystem& system, const analysis::AdditionalTerms* terms,
                            double time, const Eigen::VectorXd& U, const Eigen::VectorXd& internalForces,
                            const Eigen::VectorXd* reactions, bool withStresses = true, bool converged = true);

}  // namespace aster::lang
