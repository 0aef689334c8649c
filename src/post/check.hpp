// The OK/NOOK machinery shared by TEST_RESU, TEST_TABLE and TEST_FONCTION, with
// code_aster's rules (its TEST_RESU documentation, U4.92.01, and its checking
// sources). One check compares the computed value with VALE_CALC (the
// NON_REGRESSION line, tolerance TOLE_MACHINE) and, when REFERENCE is given, with
// VALE_REFE (tolerance PRECISION); CRITERE (RELATIF or ABSOLU) applies to both.
//  - RELATIF: OK when |computed - ref| <= tol * |ref|; a reference of exactly 0 is
//    met only by exactly 0 (ERREUR printed 0 when met, 999.999999 % otherwise).
//  - ABSOLU: OK when |computed - ref| <= tol * ORDRE_GRANDEUR (1 when not given).
//  - VALE_CALC within DBL_EPSILON of 0: without ORDRE_GRANDEUR the NON_REGRESSION
//    line is skipped (SKIP, neither OK nor NOOK); with it, ORDRE_GRANDEUR scales the
//    absolute tolerance of that line (and is printed). The VALE_REFE line never uses it.
//  - VALE_ABS='OUI': the absolute values of the computed value and of the references.
//  - Several values in VALE_CALC (or VALE_REFE): the one closest to the computed value.
#pragma once
#include <string>
#include <utility>
#include <vector>

namespace aster::post {

struct CheckSpec {
  std::vector<double> valeCalc;        // VALE_CALC (or VALE_CALC_I): one or several
  std::vector<double> valeRefe;        // VALE_REFE (or VALE_REFE_I), with a reference
  bool integer = false;                // VALE_CALC_I: integers, printed as such
  double toleMachine = 1e-6;           // TOLE_MACHINE: tolerance on VALE_CALC
  std::string reference;               // REFERENCE; empty: NON_REGRESSION only
  double precision = 1e-3;             // PRECISION: tolerance on VALE_REFE
  bool relative = true;                // CRITERE = 'RELATIF' (else 'ABSOLU')
  bool hasOrdreGrandeur = false;       // ORDRE_GRANDEUR given (only when VALE_CALC is 0)
  double ordreGrandeur = 1.0;
  bool valeAbs = false;                // VALE_ABS = 'OUI'
  std::string legende = "XXXX";
};

struct CheckLine {
  enum class Diag { Ok, Nook, Skip };
  Diag diag = Diag::Nook;
  std::string reference;  // NON_REGRESSION, ANALYTIQUE, ...
  double expected = 0, computed = 0;
  bool integer = false;
  double error = 0;       // |computed - expected|, in % of |expected| when relative
  double tolerance = 0;   // in % when relative
  bool relative = true;
  double compare = 1.0;   // ORDRE_GRANDEUR used (1: none)
  bool ok() const { return diag != Diag::Nook; }
};

// One comparison, as code_aster makes it.
CheckLine compareValue(double computed, double expected, double tolerance, bool relative, double compare = 1.0);

// Compares; returns one line per comparison (NON_REGRESSION, then the reference).
std::vector<CheckLine> check(double computed, const CheckSpec& spec);

// Python's repr of a float, exponent in capitals (code_aster prints the values of a
// check so): "301.105319971", "0.0", "5.31098862756E-05", "1E+16".
std::string pythonRepr(double v);

// The result lines of a check, in code_aster's .resu layout, the column names on
// the first line only:
//      REFERENCE        LEGENDE          VALE_REFE          VALE_CALC          ERREUR           TOLE
//  OK  NON_REGRESSION   XXXX             0.125              0.125              0.0%             0.0001%
std::string formatLines(const std::vector<CheckLine>& lines, const std::string& legende);

// The two header lines of a check: what is tested (keyword names over their
// values). The first column (the factor keyword, e.g. CHAM_NO, and the concept)
// is 21 characters wide after "---- " / "     ", each further one 17; Fortran
// starts each line with a blank unless `leadingBlank` is false (code_aster's
// CHAM_ELEM header of one value has none).
std::string formatHeader(const std::vector<std::pair<std::string, std::string>>& what, bool leadingBlank = true);

// A text comparison (TEST_TABLE's VALE_CALC_K): code_aster's layout for texts.
std::string formatTextLine(bool ok, const std::string& reference, const std::string& legende,
                           const std::string& expected, const std::string& computed, bool label);

// TEST_FONCTION's result lines (its own layout: values rounded to the tolerance,
// at least 12 digits for NON_REGRESSION; signed error when absolute; ORDRE_GRANDEUR
// not used; VALE_ABS on the computed value only).
std::vector<CheckLine> checkFunctionValue(double computed, const CheckSpec& spec);
std::string formatFunctionLines(const std::vector<CheckLine>& lines, const std::string& legende);

}  // namespace aster::post
