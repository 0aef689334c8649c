// Post-processing commands through the interpreter on meshes/ssnp150b.mail: one
// QUAD8 cell SURFACE on the unit square (nodes N1 (0,0), N4 (1,0), N3 (1,1),
// N2 (0,1), mid-side N10 (.5,0), N9 (1,.5), N8 (.5,1), N7 (0,.5)) and SEG3 edges
// (BAS: N4 N1 N10). Expected values are computed by hand in the comments.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "lang/interpreter.hpp"

using namespace aster::lang;
namespace fs = std::filesystem;

namespace {

struct StudyRun {
  int status;
  int ok, nook;
  std::string out, err;
  fs::path dir;
};

// The mesh with two node groups added: LIGNE (N1 N7 N2, the side x = 0) and
// COIN (N3).
fs::path meshWithNodeGroups(const fs::path& dir) {
  std::ifstream in(std::string(ASTER_SOURCE_DIR) + "/meshes/ssnp150b.mail");
  std::stringstream ss;
  ss << in.rdbuf();
  std::string text = ss.str();
  const auto fin = text.rfind(" FIN");
  text.insert(fin, " GROUP_NO\n LIGNE\n N1 N7 N2\n FINSF\n %\n GROUP_NO\n COIN\n N3\n FINSF\n %\n");
  const auto p = dir / "ssnp150b_groups.mail";
  std::ofstream(p) << text;
  return p;
}

StudyRun run(const std::string& name, const std::string& body) {
  const fs::path dir = fs::path(ASTER_BINARY_DIR) / "post_commands_test" / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  const auto mesh = meshWithNodeGroups(dir);
  Session session;
  session.studyPath = dir / "etude.lua";
  session.outputDir = dir / "out";
  Interpreter interpreter(session);
  const std::string code = "DEBUT{}\nDEFI_FICHIER{ACTION='ASSOCIER', UNITE=20, FICHIER='" + mesh.string() + "'}\n" +
                           "MAIL = LIRE_MAILLAGE{UNITE=20, FORMAT='ASTER'}\n" +
                           "MODE = AFFE_MODELE{MAILLAGE=MAIL, AFFE={GROUP_MA='SURFACE', PHENOMENE='MECANIQUE', MODELISATION='D_PLAN'}}\n" +
                           body + "\nFIN{}\n";
  testing::internal::CaptureStdout();
  testing::internal::CaptureStderr();
  const int status = interpreter.runString(code, "@etude.lua");
  StudyRun r{status, session.checksOk, session.checksNook, testing::internal::GetCapturedStdout(),
             testing::internal::GetCapturedStderr(), dir};
  return r;
}

std::string readFile(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// UCALC = (x, 2y) and UANA = (x + 0.1, y^2) on the nodes of SURFACE, DIFF = UCALC - UANA
// = (-0.1, 2y - y^2), built as the SSNP150 study does (AFFE of VALE_F, EVAL on the
// geometry, ASSE with CUMUL and COEF_R).
const char* kFields = R"(
GEOM = CREA_CHAMP{TYPE_CHAM='NOEU_GEOM_R', OPERATION='EXTR', MAILLAGE=MAIL, NOM_CHAM='GEOMETRIE'}
FX = FORMULE{VALE='X', NOM_PARA={'X', 'Y'}}
F2Y = FORMULE{VALE='2*Y', NOM_PARA={'X', 'Y'}}
UX = FORMULE{VALE='X + 0.1', NOM_PARA={'X', 'Y'}}
UY = FORMULE{VALE='Y*Y', NOM_PARA={'Y'}}
CF = CREA_CHAMP{TYPE_CHAM='NOEU_NEUT_F', OPERATION='AFFE', MAILLAGE=MAIL,
                AFFE={GROUP_MA='SURFACE', NOM_CMP={'X1', 'X2'}, VALE_F={FX, F2Y}}}
CV = CREA_CHAMP{TYPE_CHAM='NOEU_NEUT_R', OPERATION='EVAL', CHAM_F=CF, CHAM_PARA={GEOM}}
UCALC = CREA_CHAMP{TYPE_CHAM='NOEU_DEPL_R', OPERATION='ASSE', MODELE=MODE,
                   ASSE={GROUP_MA='SURFACE', CHAM_GD=CV, NOM_CMP={'X1', 'X2'}, NOM_CMP_RESU={'DX', 'DY'}}}
UANAF = CREA_CHAMP{TYPE_CHAM='NOEU_NEUT_F', OPERATION='AFFE', MAILLAGE=MAIL,
                   AFFE={GROUP_MA='SURFACE', NOM_CMP={'X1', 'X2'}, VALE_F={UX, UY}}}
UANA = CREA_CHAMP{TYPE_CHAM='NOEU_NEUT_R', OPERATION='EVAL', CHAM_F=UANAF, CHAM_PARA={GEOM}}
DIFF = CREA_CHAMP{TYPE_CHAM='NOEU_DEPL_R', OPERATION='ASSE', MAILLAGE=MAIL, ASSE={
  {GROUP_MA='SURFACE', CHAM_GD=UCALC, NOM_CMP={'DX', 'DY'}, CUMUL='OUI', COEF_R=1.0},
  {GROUP_MA='SURFACE', CHAM_GD=UANA, NOM_CMP={'X1', 'X2'}, NOM_CMP_RESU={'DX', 'DY'}, CUMUL='OUI', COEF_R=-1.0}}}
)";

}  // namespace

TEST(PostCommands, TestResuOnAffeFieldByHand) {
  // DX = 1.5, DY = -2 on the 8 nodes of SURFACE: SOMM_ABS = 8 * 3.5 = 28,
  // SOMM = 8 * (-0.5) = -4, MAX = 1.5, MIN = -2, SOMM of DY = -16.
  const auto r = run("affe", R"(
CH = CREA_CHAMP{TYPE_CHAM='NOEU_DEPL_R', OPERATION='AFFE', MAILLAGE=MAIL,
                AFFE={GROUP_MA='SURFACE', NOM_CMP={'DX', 'DY'}, VALE={1.5, -2.0}}}
TEST_RESU{CHAM_NO={
  {CHAM_GD=CH, TYPE_TEST='SOMM_ABS', VALE_CALC=28.0, REFERENCE='ANALYTIQUE', VALE_REFE=28.0},
  {CHAM_GD=CH, TYPE_TEST='SOMM', VALE_CALC=-4.0},
  {CHAM_GD=CH, TYPE_TEST='MAX', VALE_CALC=1.5},
  {CHAM_GD=CH, TYPE_TEST='MIN', VALE_CALC=-2.0},
  {CHAM_GD=CH, TYPE_TEST='SOMM', NOM_CMP='DY', VALE_CALC=-16.0},
  {CHAM_GD=CH, NOEUD='N10', NOM_CMP='DX', VALE_CALC=1.5},
  {CHAM_GD=CH, GROUP_NO='COIN', NOM_CMP='DY', VALE_CALC=-2.0},
}}
)");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.ok, 7);
  EXPECT_EQ(r.nook, 0);
  EXPECT_NE(readFile(r.dir / "out" / "etude.resu").find("SOMM_ABS"), std::string::npos);
}

TEST(PostCommands, NookIsCountedAndSetsTheExitStatus) {
  const auto r = run("nook", R"(
CH = CREA_CHAMP{TYPE_CHAM='NOEU_DEPL_R', OPERATION='AFFE', MAILLAGE=MAIL,
                AFFE={TOUT='OUI', NOM_CMP={'DX'}, VALE={1.0}}}
TEST_RESU{CHAM_NO={CHAM_GD=CH, TYPE_TEST='SOMM', VALE_CALC=12.0}}
)");
  // 11 nodes carry DX = 1: the sum is 11, not 12.
  EXPECT_EQ(r.ok, 0);
  EXPECT_EQ(r.nook, 1);
  EXPECT_EQ(r.status, 1) << r.err;
  EXPECT_NE(r.out.find("NOOK"), std::string::npos);
}

TEST(PostCommands, DiffOfComputedAndExactFields) {
  // DIFF = (-0.1, 2y - y^2): DX sums to -0.8 over 8 nodes; DY is 0 at y = 0 (3 nodes),
  // 1 at y = 1 (3 nodes), 0.75 at y = 0.5 (2 nodes): 4.5. SOMM_ABS = 5.3.
  const auto r = run("diff", std::string(kFields) + R"(
TEST_RESU{CHAM_NO={
  {CHAM_GD=DIFF, TYPE_TEST='SOMM_ABS', VALE_CALC=5.3},
  {CHAM_GD=DIFF, TYPE_TEST='SOMM', NOM_CMP='DX', VALE_CALC=-0.8},
  {CHAM_GD=DIFF, TYPE_TEST='MAX', VALE_CALC=1.0},
  {CHAM_GD=DIFF, TYPE_TEST='MIN', VALE_CALC=-0.1},
  {CHAM_GD=DIFF, NOEUD='N7', NOM_CMP='DY', VALE_CALC=0.75},
}}
)");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.ok, 5);
}

TEST(PostCommands, PostElemAndPostErreur) {
  // ||DIFF||^2 = int 0.01 + (2y - y^2)^2 = 0.01 + 8/15 (QUAD8 holds both exactly).
  // UCALC = (x, 2y) against (X, 2Y): error 0, reference^2 = 1/3 + 4/3 = 5/3.
  // UCALC against (X + 0.1, Y^2): error^2 = 0.01 + 8/15, reference^2 = (1.1^3 - 0.1^3)/3 + 1/5.
  // LAGS_C = x at the vertices of BAS against X^2: error^2 = int_0^1 (x - x^2)^2 = 1/30,
  // reference^2 = 1/5.
  const auto r = run("norms", std::string(kFields) + R"(
N = POST_ELEM{NORME={TYPE_NORM='L2', GROUP_MA='SURFACE', CHAM_GD=DIFF, MODELE=MODE}}
NDX = POST_ELEM{NORME={TOUT='OUI', CHAM_GD=DIFF, MODELE=MODE, NOM_CMP={'DX'}}}
TEST_TABLE{TABLE=N, NOM_PARA='VALE_NORM', VALE_CALC=math.sqrt(0.01 + 8/15), TOLE_MACHINE=1e-12}
TEST_TABLE{TABLE=NDX, NOM_PARA='VALE_NORM', VALE_CALC=0.1, TOLE_MACHINE=1e-12}
E0 = POST_ERREUR{OPTION='DEPL_ABSO', CHAM_GD=UCALC, MODELE=MODE, GROUP_MA='SURFACE', DX=FX, DY=F2Y}
TEST_TABLE{TABLE=E0, NOM_PARA='ERREUR', FILTRE={NOM_PARA='GROUP_MA', VALE_K='TOTAL'},
           VALE_CALC=0.0, CRITERE='ABSOLU', TOLE_MACHINE=1e-12}
TEST_TABLE{TABLE=E0, NOM_PARA='REFERENCE', FILTRE={NOM_PARA='GROUP_MA', VALE_K='SURFACE'},
           VALE_CALC=math.sqrt(5/3), TOLE_MACHINE=1e-12}
E1 = POST_ERREUR{OPTION='DEPL_RELA', CHAM_GD=UCALC, MODELE=MODE, GROUP_MA='SURFACE', DX=UX, DY=UY}
TEST_TABLE{TABLE=E1, NOM_PARA='ERREUR', FILTRE={NOM_PARA='GROUP_MA', VALE_K='TOTAL'},
           VALE_CALC=math.sqrt(0.01 + 8/15) / math.sqrt((1.1^3 - 0.1^3)/3 + 0.2), TOLE_MACHINE=1e-12}
FL = FORMULE{VALE='X', NOM_PARA={'X'}}
CFL = CREA_CHAMP{TYPE_CHAM='NOEU_NEUT_F', OPERATION='AFFE', MAILLAGE=MAIL,
                 AFFE={GROUP_MA='BAS', NOM_CMP={'X1'}, VALE_F={FL}}}
CL = CREA_CHAMP{TYPE_CHAM='NOEU_NEUT_R', OPERATION='EVAL', CHAM_F=CFL, CHAM_PARA={GEOM}}
UL = CREA_CHAMP{TYPE_CHAM='NOEU_DEPL_R', OPERATION='ASSE', MAILLAGE=MAIL, ASSE={
  {TOUT='OUI', CHAM_GD=UCALC},
  {GROUP_MA='BAS', CHAM_GD=CL, NOM_CMP={'X1'}, NOM_CMP_RESU={'LAGS_C'}}}}
PX2 = FORMULE{VALE='X*X', NOM_PARA={'X', 'Y'}}
EL = POST_ERREUR{OPTION='LAGR_ABSO', CHAM_GD=UL, MODELE=MODE, GROUP_MA='BAS', LAGS_C=PX2}
TEST_TABLE{TABLE=EL, NOM_PARA='ERREUR', FILTRE={NOM_PARA='GROUP_MA', VALE_K='BAS'},
           VALE_CALC=math.sqrt(1/30), TOLE_MACHINE=1e-12}
TEST_TABLE{TABLE=EL, NOM_PARA='REFERENCE', FILTRE={NOM_PARA='GROUP_MA', VALE_K='BAS'},
           VALE_CALC=math.sqrt(0.2), TOLE_MACHINE=1e-12}
print(string.format('rows=%d %s', EL:getNumberOfRows(), EL:get('GROUP_MA', 2)))
)");
  EXPECT_EQ(r.status, 0) << r.err << r.out;
  EXPECT_EQ(r.ok, 7);
  EXPECT_NE(r.out.find("rows=2 TOTAL"), std::string::npos);
}

TEST(PostCommands, ReleveRecuFonctionTablesAndPrints) {
  // Along LIGNE (N1 N7 N2, x = 0, y = 0, .5, 1) DIFF's DY = 2y - y^2 is 0, .75, 1;
  // RECU_FONCTION interpolates linearly: F(0.25) = 0.375, F(0.75) = 0.875.
  const auto r = run("releve", std::string(kFields) + R"(
T = POST_RELEVE_T{ACTION={OPERATION='EXTRACTION', INTITULE='GAUCHE', GROUP_NO='LIGNE', CHAM_GD=DIFF,
                          NOM_CMP={'DX', 'DY'}}}
TEST_TABLE{TABLE=T, NOM_PARA='DY', FILTRE={NOM_PARA='NOEUD', VALE_K='N7'}, VALE_CALC=0.75}
TEST_TABLE{TABLE=T, NOM_PARA='COOR_Y', TYPE_TEST='SOMM', VALE_CALC=1.5}
TEST_TABLE{TABLE=T, NOM_PARA='NOEUD', FILTRE={NOM_PARA='COOR_Y', CRIT_COMP='MAXI'}, VALE_CALC_K='N2'}
F = RECU_FONCTION{TABLE=T, PARA_X='COOR_Y', PARA_Y='DY'}
TEST_FONCTION{VALEUR={{FONCTION=F, VALE_PARA=0.25, VALE_CALC=0.375}, {FONCTION=F, VALE_PARA=0.75, VALE_CALC=0.875}}}
print('params ' .. table.concat(T:getParameters(), ','))
print('col ' .. table.concat(T:column('NOEUD'), ','))
L = CREA_TABLE{LISTE={{PARA='N', LISTE_I={1, 2, 3}}, {PARA='H', LISTE_R={0.5, 0.25, 0.125}},
                      {PARA='NOM', LISTE_K={'a', 'b', 'c'}}}}
TEST_TABLE{TABLE=L, NOM_PARA='N', TYPE_TEST='SOMM', VALE_CALC_I=6}
TEST_TABLE{TABLE=L, NOM_PARA='H', FILTRE={NOM_PARA='NOM', VALE_K='b'}, VALE_CALC=0.25}
TEST_TABLE{TABLE=L, NOM_PARA='H', TYPE_TEST='MAX', FILTRE={NOM_PARA='N', CRIT_COMP='GE', VALE_I=2}, VALE_CALC=0.25}
IMPR_TABLE{TABLE=L, FORMAT='CSV', FORMAT_R='F6.3', TRI={NOM_PARA='H'}}
IMPR_TABLE{TABLE=T, NOM_PARA={'NOEUD', 'DY'}}
DETRUIRE{NOM={L}}
)");
  EXPECT_EQ(r.status, 0) << r.err << r.out;
  EXPECT_EQ(r.ok, 8);
  EXPECT_NE(r.out.find("params INTITULE,NOEUD,ABSC_CURV,COOR_X,COOR_Y,DX,DY"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("col N1,N7,N2"), std::string::npos);
  EXPECT_EQ(readFile(r.dir / "out" / "L.csv"), "N,H,NOM\n3,0.125,c\n2,0.250,b\n1,0.500,a\n");
  EXPECT_NE(r.out.find("NOEUD          DY"), std::string::npos) << r.out;
  EXPECT_TRUE(fs::exists(r.dir / "out" / "T.tab"));
}

TEST(PostCommands, ImprFonctionTableauAndPngWithSlope) {
  // y = 3 x^-2: the least-squares slope of log y against log x is -2.
  const auto r = run("plot", R"(
DEFI_FICHIER{ACTION='ASSOCIER', UNITE=30, FICHIER='courbes.txt'}
IMPR_FONCTION{FORMAT='TABLEAU', UNITE=30, COURBE={ABSCISSE={1, 2, 4}, ORDONNEE={3, 0.75, 0.1875}, LEGENDE='h'}}
DEFI_FICHIER{ACTION='ASSOCIER', UNITE=29, FICHIER='convergence.png'}
IMPR_FONCTION{FORMAT='PNG', UNITE=29, PENTE='OUI', ECHELLE_X='LOG', ECHELLE_Y='LOG', TITRE='Convergence: slope -2',
  LEGENDE_X='h', LEGENDE_Y='error',
  COURBE={{ABSCISSE={1, 2, 4, 8}, ORDONNEE={3, 0.75, 0.1875, 0.046875}, LEGENDE='erreur L2'},
          {ABSCISSE={1, 2, 4, 8}, ORDONNEE={1, 0.5, 0.25, 0.125}, LEGENDE='ordre 1'}}}
)");
  EXPECT_EQ(r.status, 0) << r.err << r.out;
  EXPECT_EQ(readFile(r.dir / "courbes.txt"), "# COURBE 1: h\n# X  Y\n1  3\n2  0.75\n4  0.1875\n\n");
  EXPECT_NE(r.out.find("erreur L2 (pente -2.000)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("ordre 1 (pente -1.000)"), std::string::npos) << r.out;
  EXPECT_GT(fs::file_size(r.dir / "convergence.png"), 1000u);
}

TEST(PostCommands, ClearErrors) {
  auto r = run("err1", R"(
CH = CREA_CHAMP{TYPE_CHAM='ELGA_NEUT_R', OPERATION='AFFE', MODELE=MODE, AFFE={TOUT='OUI', NOM_CMP={'X1'}, VALE={1.0}}}
)");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("not available yet"), std::string::npos) << r.err;
  r = run("err2", R"(
GEOM = CREA_CHAMP{TYPE_CHAM='NOEU_DEPL_R', OPERATION='EXTR', MAILLAGE=MAIL, NOM_CHAM='GEOMETRIE'}
)");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("NOEU_GEOM_R"), std::string::npos) << r.err;
  r = run("err3", R"(
CH = CREA_CHAMP{TYPE_CHAM='NOEU_NEUT_R', OPERATION='AFFE', MAILLAGE=MAIL, AFFE={TOUT='OUI', NOM_CMP={'DX'}, VALE={1.0}}}
)");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("X1, X2"), std::string::npos) << r.err;
}
