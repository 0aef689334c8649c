// Lame's thick cylinder (a = 1, b = 2, internal pressure p, E, NU) as studies run it:
// a gmsh .geo meshed by LIRE_MAILLAGE, MECA_STATIQUE, SIEF_ELGA, REAC_NODA, POST_ERREUR.
// Closed form (plane strain, e_zz = 0), with A = p a^2 / (b^2 - a^2):
//   s_rr = A (1 - b^2/r^2), s_tt = A (1 + b^2/r^2), s_zz = 2 NU A,
//   u_r = (1 + NU)/E A ((1 - 2 NU) r + b^2/r).
//  - AXIS: the section r in [a, b], y in [0, h], DY = 0 on y = 0 and y = h (e_zz = 0),
//    PRES_REP on r = a; transfinite QUAD4 / QUAD8 cells.
//  - D_PLAN: the quarter ring, DY = 0 on y = 0, DX = 0 on x = 0, PRES_REP on the inner
//    arc; transfinite TRIA3 / TRIA6 cells, quadratic cells with their middle nodes on
//    the arcs (gmsh).
// Three meshes (h halved each time): the L2 error of the displacement converges at
// rate 2 (linear cells) and 3 (quadratic), each rate log2(e_k / e_k+1) within 0.15
// (AXIS: the L2 norm of the section, POST_ERREUR on a D_PLAN model of the same mesh;
// with 1 <= r <= 2 it is equivalent to the per-radian norm, same rate). The stresses at
// the Gauss points (SIEF_ELGA; SIZZ the hoop stress in AXIS) and u_r on the inner radius
// approach the closed form; the axial reaction per radian on y = 0 in AXIS is
// -int_a^b s_zz r dr = -NU p a^2 (exactly: see converges()).
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

#include "lang/interpreter.hpp"

using namespace aster::lang;
namespace fs = std::filesystem;

namespace {

constexpr double kA = 1, kB = 2, kP = 10, kE = 1000, kNu = 0.3, kH = 0.5;

class Lame : public testing::Test {
 protected:
  void SetUp() override {
    const auto* info = testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() / ("aster_lame_" + std::to_string(::getpid()) + "_" + info->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override {
    if (!HasFailure()) fs::remove_all(dir_);
  }

  // Runs the study; returns its "@key=value" lines (status in "status").
  std::map<std::string, double> run(const std::string& code, std::string& log) {
    Session session;
    session.studyPath = dir_ / "etude.lua";
    session.outputDir = dir_ / "etude";
    session.unsafeLua = true;  // LIRE_MAILLAGE hands the .geo to gmsh
    Interpreter interpreter(session);
    testing::internal::CaptureStdout();
    testing::internal::CaptureStderr();
    const int status = interpreter.runString(code, "@etude.lua");
    const std::string out = testing::internal::GetCapturedStdout();
    log = out + testing::internal::GetCapturedStderr();
    std::map<std::string, double> shown{{"status", status}};
    std::istringstream lines(out);
    for (std::string line; std::getline(lines, line);) {
      if (line.empty() || line[0] != '@') continue;
      const auto eq = line.find('=');
      shown[line.substr(1, eq - 1)] = std::stod(line.substr(eq + 1));
    }
    return shown;
  }

  std::string writeGeo(bool axis, int order, int n) {
    const std::string path = (dir_ / ("lame_" + std::to_string(order) + "_" + std::to_string(n) + ".geo")).string();
    std::ofstream geo(path);
    geo << "a = " << kA << "; b = " << kB << "; h = " << kH << "; n = " << n << ";\n";
    if (axis) {
      geo << "Point(1) = {a, 0, 0}; Point(2) = {b, 0, 0}; Point(3) = {b, h, 0}; Point(4) = {a, h, 0};\n"
             "Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};\n"
             "Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};\n"
             "Transfinite Curve {1, 3} = n + 1; Transfinite Curve {2, 4} = n / 2 + 1;\n"
             "Transfinite Surface {1} = {1, 2, 3, 4}; Recombine Surface {1};\n"
             "Physical Surface(\"SECTION\") = {1}; Physical Curve(\"BAS\") = {1};\n"
             "Physical Curve(\"EXT\") = {2}; Physical Curve(\"HAUT\") = {3}; Physical Curve(\"INT\") = {4};\n";
    } else {
      geo << "Point(1) = {0, 0, 0}; Point(2) = {a, 0, 0}; Point(3) = {b, 0, 0};\n"
             "Point(4) = {0, b, 0}; Point(5) = {0, a, 0};\n"
             "Line(1) = {2, 3}; Circle(2) = {3, 1, 4}; Line(3) = {4, 5}; Circle(4) = {5, 1, 2};\n"
             "Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};\n"
             "Transfinite Curve {1, 3} = n + 1; Transfinite Curve {2, 4} = 2 * n + 1;\n"
             "Transfinite Surface {1} = {2, 3, 4, 5};\n"
             "Physical Surface(\"SECTION\") = {1}; Physical Curve(\"BAS\") = {1};\n"
             "Physical Curve(\"EXT\") = {2}; Physical Curve(\"GAUCHE\") = {3}; Physical Curve(\"INT\") = {4};\n";
    }
    geo << "Mesh.ElementOrder = " << order << ";\nMesh.SecondOrderIncomplete = 1;\n";
    return path;
  }

  // One mesh: the errors the study measures.
  std::map<std::string, double> solve(bool axis, int order, int n) {
    const std::string geo = writeGeo(axis, order, n);
    std::ostringstream s;
    s.precision(17);
    s << "local a, b, p, E, NU = " << kA << ", " << kB << ", " << kP << ", " << kE << ", " << kNu << "\n"
      << "local AXIS = " << (axis ? "true" : "false") << "\n"
      << "DEFI_FICHIER{ACTION='ASSOCIER', UNITE=19, FICHIER='" << geo << "'}\n";
    s << R"(
local A = p * a * a / (b * b - a * a)
local function ur(r) return (1 + NU) / E * A * ((1 - 2 * NU) * r + b * b / r) end
MA = LIRE_MAILLAGE{FORMAT='GMSH', UNITE=19}
MO = AFFE_MODELE{MAILLAGE=MA, AFFE={TOUT='OUI', PHENOMENE='MECANIQUE', MODELISATION=AXIS and 'AXIS' or 'D_PLAN'}}
MAT = DEFI_MATERIAU{ELAS={E=E, NU=NU}}
CM = AFFE_MATERIAU{MAILLAGE=MA, AFFE={TOUT='OUI', MATER=MAT}}
local fixed = AXIS and {{GROUP_MA='BAS', DY=0.0}, {GROUP_MA='HAUT', DY=0.0}}
                    or {{GROUP_MA='BAS', DY=0.0}, {GROUP_MA='GAUCHE', DX=0.0}}
BC = AFFE_CHAR_MECA{MODELE=MO, DDL_IMPO=fixed}
PR = AFFE_CHAR_MECA{MODELE=MO, PRES_REP={GROUP_MA='INT', PRES=p}}
R = MECA_STATIQUE{MODELE=MO, CHAM_MATER=CM, EXCIT={{CHARGE=BC}, {CHARGE=PR}}}
U = R:getField('DEPL', 0.0)
-- L2 error of the displacement over the section (a D_PLAN model of the same mesh).
MOP = AFFE_MODELE{MAILLAGE=MA, AFFE={GROUP_MA='SECTION', PHENOMENE='MECANIQUE', MODELISATION='D_PLAN'}}
local c = string.format('%.17g', (1 + NU) / E * A)
local k1, k2 = string.format('%.17g', 1 - 2 * NU), string.format('%.17g', b * b)
local UX, UY
if AXIS then
  UX = FORMULE{VALE=c .. '*(' .. k1 .. '*X + ' .. k2 .. '/X)', NOM_PARA={'X', 'Y'}}
  UY = FORMULE{VALE='0*X', NOM_PARA={'X', 'Y'}}
else
  UX = FORMULE{VALE=c .. '*(' .. k1 .. ' + ' .. k2 .. '/(X*X + Y*Y))*X', NOM_PARA={'X', 'Y'}}
  UY = FORMULE{VALE=c .. '*(' .. k1 .. ' + ' .. k2 .. '/(X*X + Y*Y))*Y', NOM_PARA={'X', 'Y'}}
end
ERR = POST_ERREUR{OPTION='DEPL_ABSO', CHAM_GD=U, MODELE=MOP, GROUP_MA='SECTION', DX=UX, DY=UY}
print(string.format('@l2=%.17g', ERR:get('ERREUR', ERR:getNumberOfRows())))
-- Stresses at the Gauss points against the closed form (their coordinates from ELGA_GEOM_R).
GEOM = CREA_CHAMP{TYPE_CHAM='NOEU_GEOM_R', OPERATION='EXTR', MAILLAGE=MA, NOM_CHAM='GEOMETRIE'}
XG = CREA_CHAMP{TYPE_CHAM='ELGA_GEOM_R', OPERATION='DISC', MODELE=MOP, CHAM_GD=GEOM}
local xg, xc = XG:getValues(), #XG:getComponents()
local S = R:getField('SIEF_ELGA', 0.0)
local s, cmp = S:getValues(), S:getComponents()
local at = {}
for i, name in ipairs(cmp) do at[name] = i end
local nc = #cmp
if #s / nc ~= #xg / xc then error('SIEF_ELGA and ELGA_GEOM_R differ in points') end
local stress, zz = 0.0, 0.0
for q = 0, #s / nc - 1 do
  local x, y = xg[q * xc + 1], xg[q * xc + 2]
  local sxx, syy, szz, sxy = s[q * nc + at.SIXX], s[q * nc + at.SIYY], s[q * nc + at.SIZZ], s[q * nc + at.SIXY]
  local r, srr, stt
  if AXIS then
    r, srr, stt = x, sxx, szz
    zz = math.max(zz, math.abs(syy - 2 * NU * A))
  else
    r = math.sqrt(x * x + y * y)
    local cs, sn = x / r, y / r
    srr = cs * cs * sxx + sn * sn * syy + 2 * cs * sn * sxy
    stt = sn * sn * sxx + cs * cs * syy - 2 * cs * sn * sxy
    zz = math.max(zz, math.abs(szz - NU * (sxx + syy)))  -- D_PLAN: s_zz = NU (s_xx + s_yy)
  end
  stress = math.max(stress, math.abs(srr - A * (1 - b * b / (r * r))), math.abs(stt - A * (1 + b * b / (r * r))))
end
print(string.format('@stress=%.17g', stress / p))
print(string.format('@szz=%.17g', zz / p))
-- u_r on the inner radius: the node of INT on y = 0.
local xyz, u = MA:getCoordinates(), U:getValues()
local worst = 0.0
for _, n in ipairs(MA:getNodes('INT')) do
  local x, y = xyz[3 * n - 2], xyz[3 * n - 1]
  local r = AXIS and x or math.sqrt(x * x + y * y)
  local urh = AXIS and u[2 * n - 1] or (u[2 * n - 1] * x + u[2 * n] * y) / r
  worst = math.max(worst, math.abs(urh - ur(a)) / ur(a))
end
print(string.format('@ur=%.17g', worst))
if AXIS then
  local reac, sum = R:getField('REAC_NODA', 0.0):getValues(), 0.0
  for _, n in ipairs(MA:getNodes('BAS')) do sum = sum + reac[2 * n] end
  print(string.format('@axial=%.17g', sum / (-NU * p * a * a) - 1))
end
)";
    std::string log;
    auto shown = run(s.str(), log);
    EXPECT_EQ(shown["status"], 0) << log;
    return shown;
  }

  // Three meshes; returns the errors of `key` and checks the L2 rates.
  void converges(bool axis, int order) {
    SCOPED_TRACE(std::string(axis ? "AXIS" : "D_PLAN") + " order " + std::to_string(order));
    std::vector<std::map<std::string, double>> runs;
    for (int n : {4, 8, 16}) runs.push_back(solve(axis, order, n));
    const double theory = order + 1;
    for (int k = 0; k + 1 < 3; ++k) {
      const double rate = std::log2(runs[k]["l2"] / runs[k + 1]["l2"]);
      std::printf("%s order %d: L2 error %.4g -> %.4g, rate %.3f; stress %.3g -> %.3g; u_r(a) %.3g -> %.3g\n",
                  axis ? "AXIS" : "D_PLAN", order, runs[k]["l2"], runs[k + 1]["l2"], rate, runs[k]["stress"],
                  runs[k + 1]["stress"], runs[k]["ur"], runs[k + 1]["ur"]);
      EXPECT_NEAR(rate, theory, 0.15) << "meshes " << k << " and " << k + 1;
      EXPECT_LT(runs[k + 1]["stress"], runs[k]["stress"]);
      if (axis) std::printf("  axial reaction relative error %.3g -> %.3g\n", runs[k]["axial"], runs[k + 1]["axial"]);
    }
    // The finest mesh (16 cells across the wall).
    auto& fine = runs.back();
    // Relative to p, the largest error at a Gauss point: O(h) on linear cells, O(h^2)
    // on quadratic ones (measured: AXIS 0.079, 0.0020; D_PLAN 0.12, 0.0046).
    EXPECT_LT(fine["stress"], order == 1 ? 0.15 : 0.01);
    // u_r(a) at the nodes, relative (measured: AXIS 6.5e-4, 2.6e-7; D_PLAN 8.1e-3, 1.6e-5).
    EXPECT_LT(fine["ur"], order == 1 ? 1e-2 : 1e-4);
    EXPECT_LT(fine["szz"], axis ? (order == 1 ? 0.15 : 0.01) : 1e-12);  // D_PLAN: s_zz = NU (s_xx + s_yy) exactly
    // AXIS: u_r = r is a virtual displacement of the discrete space, so the discrete
    // int (s_rr + s_tt) r dA equals the work of the pressure, p a * a h, exactly; with
    // e_zz = 0, s_zz = NU (s_rr + s_tt), and the axial reaction per radian is exactly
    // -NU p a^2 (per unit height: BAS), on every mesh.
    if (axis) {
      for (auto& run : runs) EXPECT_LT(std::abs(run["axial"]), 1e-10);
    }
  }

  fs::path dir_;
};

TEST_F(Lame, AxisLinear) { converges(true, 1); }
TEST_F(Lame, AxisQuadratic) { converges(true, 2); }
TEST_F(Lame, PlaneStrainLinear) { converges(false, 1); }
TEST_F(Lame, PlaneStrainQuadratic) { converges(false, 2); }

}  // namespace
