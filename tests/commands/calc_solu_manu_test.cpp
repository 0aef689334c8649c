// CALC_SOLU_MANU through the interpreter: the Lua table of formulas, and the
// check of the contact condition p <= 0 along a contact edge. Hand case on the
// unit square of meshes/ssnp150b.mail: small strain, plane strain, E = 1,
// NU = 0 (so lambda = 0, mu = 1/2, sigma = eps) and U = (a X, 0): sigma_xx = a,
// no body force, traction a along +X on DROITE (N = (1, 0)); on GAUCHE
// (N = (-1, 0)) t = (-a, 0), p = t.N = a and no tangential part.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <string>

#include "lang/interpreter.hpp"

using namespace aster::lang;
namespace fs = std::filesystem;

namespace {

struct StudyOutput {
  int status;
  std::string out, err;
};

StudyOutput manufactured(const std::string& name, double a, bool withMesh) {
  const fs::path dir = fs::path(ASTER_BINARY_DIR) / "calc_solu_manu_test" / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  Session session;
  session.studyPath = dir / "etude.lua";
  session.outputDir = dir / "out";
  Interpreter interpreter(session);
  char ux[64];
  std::snprintf(ux, sizeof ux, "%.17g*X", a);
  const std::string code =
      "DEFI_FICHIER{ACTION='ASSOCIER', UNITE=20, FICHIER='" + std::string(ASTER_SOURCE_DIR) +
      "/meshes/ssnp150b.mail'}\n"
      "MAIL = LIRE_MAILLAGE{UNITE=20, FORMAT='ASTER'}\n"
      "MAT = DEFI_MATERIAU{ELAS={E=1.0, NU=0.0}}\n"
      "UX = FORMULE{VALE='" + std::string(ux) + "', NOM_PARA={'X', 'Y'}}\n"
      "UY = FORMULE{VALE='0*Y', NOM_PARA={'X', 'Y'}}\n"
      "MMS = CALC_SOLU_MANU{DEPL={DX=UX, DY=UY}, MATER=MAT, MODELISATION='D_PLAN', DEFORMATION='PETIT',\n" +
      (withMesh ? "  MAILLAGE=MAIL,\n" : "") +
      "  BORD={{NOM='DROITE', NORMALE={1, 0}}, {NOM='GAUCHE', NORMALE={-1, 0}, CONTACT='OUI'}}}\n"
      "print(string.format('VALUES %.17g %.17g %.17g %.17g %.17g %.17g %.17g', MMS.GAUCHE.PRES(0.0, 0.3),\n"
      "  MMS.GAUCHE.FX_T(0.0, 0.7), MMS.GAUCHE.FY_T(0.0, 0.7), MMS.DROITE.FX(1.0, 0.2), MMS.DROITE.FY(1.0, 0.2),\n"
      "  MMS.FORCE_INTERNE.FX(0.4, 0.6), MMS.FORCE_INTERNE.FY(0.4, 0.6)))\n";
  testing::internal::CaptureStdout();
  testing::internal::CaptureStderr();
  const int status = interpreter.runString(code, "@etude.lua");
  return {status, testing::internal::GetCapturedStdout(), testing::internal::GetCapturedStderr()};
}

void expectHandValues(const StudyOutput& r, double a) {
  const auto at = r.out.find("VALUES ");
  ASSERT_NE(at, std::string::npos) << r.out << r.err;
  double p, fxt, fyt, fx, fy, bx, by;
  ASSERT_EQ(std::sscanf(r.out.c_str() + at, "VALUES %lf %lf %lf %lf %lf %lf %lf", &p, &fxt, &fyt, &fx, &fy, &bx, &by), 7);
  EXPECT_NEAR(p, a, 1e-15);
  EXPECT_NEAR(fxt, 0.0, 1e-15);
  EXPECT_NEAR(fyt, 0.0, 1e-15);
  EXPECT_NEAR(fx, a, 1e-15);
  EXPECT_NEAR(fy, 0.0, 1e-15);
  EXPECT_NEAR(bx, 0.0, 1e-15);
  EXPECT_NEAR(by, 0.0, 1e-15);
}

}  // namespace

TEST(CalcSoluManu, CompressionMeetsTheContactConditionSilently) {
  const StudyOutput r = manufactured("compression", -0.01, true);
  ASSERT_EQ(r.status, 0) << r.err;
  expectHandValues(r, -0.01);
  EXPECT_EQ((r.out + r.err).find("<A>"), std::string::npos) << r.out << r.err;
}

TEST(CalcSoluManu, TensionOnAContactEdgeRaisesAnAlarmThatSaysWhere) {
  const StudyOutput r = manufactured("tension", 0.01, true);
  ASSERT_EQ(r.status, 0) << r.err;
  expectHandValues(r, 0.01);
  const std::string all = r.out + r.err;
  EXPECT_NE(all.find("<A> <CALC_SOLU_MANU>"), std::string::npos) << all;
  EXPECT_NE(all.find("the exact contact pressure on GAUCHE is positive (0.01 at X=0"), std::string::npos) << all;
}

TEST(CalcSoluManu, WithoutAMeshSaysTheConditionIsNotChecked) {
  const StudyOutput r = manufactured("no_mesh", 0.01, false);
  ASSERT_EQ(r.status, 0) << r.err;
  expectHandValues(r, 0.01);
  const std::string all = r.out + r.err;
  EXPECT_EQ(all.find("<A>"), std::string::npos) << all;
  EXPECT_NE(all.find("without MAILLAGE the contact condition p <= 0 is not checked along GAUCHE"), std::string::npos)
      << all;
}
