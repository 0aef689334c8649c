// Mechanical loads as AFFE_CHAR_MECA(_F) and AFFE_CHAR_CINE define them, in
// plain data for the solver: node and cell lists of the mesh, component
// numbers (0 DX, 1 DY), values as SpaceFunction of (X, Y, Z, INST).
#pragma once
#include <string>
#include <vector>

#include "model/space_function.hpp"

namespace aster::model {

struct ImposedDisplacement {  // DDL_IMPO, MECA_IMPO
  std::vector<int> nodes;
  int component = 0;
  SpaceFunction value;
};

struct EdgeForce {  // FORCE_CONTOUR: force per unit reference length (dead load)
  std::vector<int> cells;
  SpaceFunction fx, fy;
};

struct BodyForce {  // FORCE_INTERNE: force per unit reference area
  std::vector<int> cells;
  SpaceFunction fx, fy;
};

struct Pressure {  // PRES_REP: dead, or follower (STAT_NON_LINE TYPE_CHARGE='SUIV')
  std::vector<int> cells;
  SpaceFunction p;
};

struct NodalForce {  // FORCE_NODALE
  std::vector<int> nodes;
  SpaceFunction fx, fy;
};

// LIAISON_DDL, LIAISON_UNIF, LIAISON_SOLIDE, FACE_IMPO DNOR/DTAN: a linear relation
// sum_i coefficient_i u(node_i, component_i) = value, eliminated from the system.
struct RelationTerm {
  int node = 0;
  int component = 0;  // 0 DX, 1 DY
  double coefficient = 0;
};

struct LinearRelation {
  std::vector<RelationTerm> terms;
  SpaceFunction value;  // at the first term's node (X, Y, Z) and INST
  std::string origin;   // "AFFE_CHAR_MECA (study.lua:12) LIAISON_DDL[2]", for messages
};

struct MechanicalLoad {
  // AFFE_CHAR_CINE: conditions eliminated from the system. DDL_IMPO of
  // AFFE_CHAR_MECA are eliminated as well in aster-lite (reactions are the
  // residual at those DOFs, so they are available either way).
  bool kinematic = false;
  std::vector<ImposedDisplacement> imposed;
  std::vector<LinearRelation> relations;
  std::vector<EdgeForce> edgeForces;
  std::vector<BodyForce> bodyForces;
  std::vector<Pressure> pressures;
  std::vector<NodalForce> nodalForces;
};

}  // namespace aster::model
