// The OK/NOOK machinery shared by TEST_RESU, TEST_TABLE and TEST_FONCTION.
// As in code_aster, one test compares the computed value with VALE_CALC
// (non-regression, tolerance TOLE_MACHINE) and, when a REFERENCE other than
// NON_REGRESSION is given, also with VALE_REFE within PRECISION.
#pragma once
#include <string>
#include <utility>
#include <vector>


namespace aster::post {

struct CheckSpec {
  double valeCalc = 0.0;
  bool hasValeCalc = true;
  double toleMachine = 1e-6;           // TOLE_MACHINE: tolerance on VALE_CALC
  std::string reference = "NON_REGRESSION";
  bool hasValeRefe = false;
  double valeRefe = 0.0;
  double precision = 1e-3;             // PRECISION: tolerance on VALE_REFE
  bool relative = true;                // CRITERE = 'RELATIF' (else 'ABSOLU')
  double ordreGrandeur = 0.0;          // ORDRE_GRANDEUR: scale for values near zero (0: unset)
  std::string legende = "XXXX";
};

struct CheckLine {
  bool ok = false;
  std::string reference;  // NON_REGRESSION, ANALYTIQUE, ...
  double expected = 0, computed = 0;
  double error = 0;       // relative (in %) or absolute, as `relative` says
  double tolerance = 0;
  bool relative = true;
};

// Compares; returns one line per comparison made (one or two).
std::vector<CheckLine> check(double computed, const CheckSpec& spec);

// The .resu block: what was tested (name/value pairs), then one line per comparison.
//  ---- FONCTION         NOM_PARA         VALE_PARA
//       F                X                0.5
//       REFERENCE        LEGENDE          VALE_REFE        VALE_CALC        ERREUR           TOLE
//  OK   NON_REGRESSION   XXXX             0.125            0.125            0.000E+00%       1.000E-04%
std::string formatCheck(const std::vector<std::pair<std::string, std::string>>& what,
                        const std::vector<CheckLine>& lines, const std::string& legende);

}  // namespace aster::post
