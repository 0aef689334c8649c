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

TEST(PostCommands, AsseSkipsAComponentTheSourceLacks) {
  // As code_aster: a component a source field does not carry brings nothing (an
  // alarm says so); the other terms assemble. LAGS_C = 2 * 1.5 - (nothing) = 3.
  const auto r = run("asse_missing", R"(
A = CREA_CHAMP{TYPE_CHAM='NOEU_DEPL_R', OPERATION='AFFE', MAILLAGE=MAIL,
               AFFE={GROUP_MA='SURFACE', NOM_CMP={'DX', 'DY'}, VALE={1.5, -2.0}}}
P = CREA_CHAMP{TYPE_CHAM='NOEU_DEPL_R', OPERATION='AFFE', MAILLAGE=MAIL,
               AFFE={GROUP_MA='SURFACE', NOM_CMP={'LAGS_C'}, VALE={7.0}}}
D = CREA_CHAMP{TYPE_CHAM='NOEU_DEPL_R', OPERATION='ASSE', MAILLAGE=MAIL, ASSE={
  {GROUP_MA='SURFACE', CHAM_GD=A, NOM_CMP='DX', NOM_CMP_RESU='LAGS_C', CUMUL='OUI', COEF_R=2.0},
  {GROUP_MA='SURFACE', CHAM_GD=P, NOM_CMP='DX', NOM_CMP_RESU='LAGS_C', CUMUL='OUI', COEF_R=-1.0}}}
TEST_RESU{CHAM_NO={CHAM_GD=D, TYPE_TEST='MAX', VALE_CALC=3.0}}
TEST_RESU{CHAM_NO={CHAM_GD=D, TYPE_TEST='MIN', VALE_CALC=3.0}}
)");
  EXPECT_EQ(r.status, 0) << r.err << r.out;
  EXPECT_EQ(r.ok, 2);
  EXPECT_NE(r.err.find("ASSE[2]: CHAM_GD P has no component DX (components: LAGS_C): nothing is taken from it for LAGS_C"),
            std::string::npos)
      << r.err;
}

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
  // LAGS_C = x at the nodes of BAS against X^2: error^2 = int_0^1 (x - x^2)^2 = 1/30,
  // reference^2 = 1/5.
  const auto r = run("norms", std::string(kFields) + R"(
N = POST_ELEM{NORME={TYPE_NORM='L2', GROUP_MA='SURFACE', CHAM_GD=DIFF, MODELE=MODE}}
NDX = POST_ELEM{NORME={TOUT='OUI', CHAM_GD=DIFF, MODELE=MODE, NOM_CMP={'DX'}}}
TEST_TABLE{TABLE=N, NOM_PARA='VALE_NORM', VALE_CALC=math.sqrt(0.01 + 8/15), TOLE_MACHINE=1e-12}
TEST_TABLE{TABLE=NDX, NOM_PARA='VALE_NORM', VALE_CALC=0.1, TOLE_MACHINE=1e-12}
E0 = POST_ERREUR{OPTION='DEPL_ABSO', CHAM_GD=UCALC, MODELE=MODE, GROUP_MA='SURFACE', DX=FX, DY=F2Y}
TEST_TABLE{TABLE=E0, NOM_PARA='ERREUR', FILTRE={NOM_PARA='GROUP_MA', VALE_K='TOTAL'},
           VALE_CALC=0.0, ORDRE_GRANDEUR=1.0, CRITERE='ABSOLU', TOLE_MACHINE=1e-12}
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
-- code_aster's ERREUR RELATIVE (row TOTAL, any option): sqrt(1/30) / sqrt(1/5) = sqrt(1/6).
TEST_TABLE{TABLE=EL, NOM_PARA='ERREUR RELATIVE', FILTRE={NOM_PARA='GROUP_MA', VALE_K='TOTAL'},
           VALE_CALC=math.sqrt(1/6), TOLE_MACHINE=1e-12}
TEST_TABLE{TABLE=E1, NOM_PARA='ERREUR RELATIVE', FILTRE={NOM_PARA='GROUP_MA', VALE_K='TOTAL'},
           VALE_CALC=math.sqrt(0.01 + 8/15) / math.sqrt((1.1^3 - 0.1^3)/3 + 0.2), TOLE_MACHINE=1e-12}
-- LAGS_C = x^2 at every node of BAS's SEG3 (INTERPOL_LAGS_C='QUADRATIQUE'):
-- the shape functions reproduce X^2, the error is 0.
FQ = FORMULE{VALE='X*X', NOM_PARA={'X'}}
CFQ = CREA_CHAMP{TYPE_CHAM='NOEU_NEUT_F', OPERATION='AFFE', MAILLAGE=MAIL,
                 AFFE={GROUP_MA='BAS', NOM_CMP={'X1'}, VALE_F={FQ}}}
CQ = CREA_CHAMP{TYPE_CHAM='NOEU_NEUT_R', OPERATION='EVAL', CHAM_F=CFQ, CHAM_PARA={GEOM}}
UQ = CREA_CHAMP{TYPE_CHAM='NOEU_DEPL_R', OPERATION='ASSE', MAILLAGE=MAIL, ASSE={
  {TOUT='OUI', CHAM_GD=UCALC},
  {GROUP_MA='BAS', CHAM_GD=CQ, NOM_CMP={'X1'}, NOM_CMP_RESU={'LAGS_C'}}}}
EQ = POST_ERREUR{OPTION='LAGR_ABSO', CHAM_GD=UQ, MODELE=MODE, GROUP_MA='BAS', LAGS_C=PX2}
TEST_TABLE{TABLE=EQ, NOM_PARA='ERREUR', FILTRE={NOM_PARA='GROUP_MA', VALE_K='BAS'},
           VALE_CALC=0.0, ORDRE_GRANDEUR=1.0, CRITERE='ABSOLU', TOLE_MACHINE=1e-12}
print(string.format('rows=%d %s', EL:getNumberOfRows(), EL:get('GROUP_MA', 2)))
print('relative of BAS: ' .. tostring(EL:get('ERREUR RELATIVE', 1)))
)");
  EXPECT_EQ(r.status, 0) << r.err << r.out;
  EXPECT_EQ(r.ok, 10);
  EXPECT_NE(r.out.find("rows=2 TOTAL"), std::string::npos);
  EXPECT_NE(r.out.find("relative of BAS: nil"), std::string::npos);
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
DEFI_FICHIER{ACTION='ASSOCIER', UNITE=30, FICHIER='out/courbes.txt'}
IMPR_FONCTION{FORMAT='TABLEAU', UNITE=30, COURBE={ABSCISSE={1, 2, 4}, ORDONNEE={3, 0.75, 0.1875}, LEGENDE='h'}}
DEFI_FICHIER{ACTION='ASSOCIER', UNITE=29, FICHIER='out/convergence.png'}
IMPR_FONCTION{FORMAT='PNG', UNITE=29, PENTE='OUI', ECHELLE_X='LOG', ECHELLE_Y='LOG', TITRE='Convergence: slope -2',
  LEGENDE_X='h', LEGENDE_Y='error',
  COURBE={{ABSCISSE={1, 2, 4, 8}, ORDONNEE={3, 0.75, 0.1875, 0.046875}, LEGENDE='erreur L2'},
          {ABSCISSE={1, 2, 4, 8}, ORDONNEE={1, 0.5, 0.25, 0.125}, LEGENDE='ordre 1'}}}
)");
  EXPECT_EQ(r.status, 0) << r.err << r.out;
  EXPECT_EQ(readFile(r.dir / "out" / "courbes.txt"), "# COURBE 1: h\n# X  Y\n1  3\n2  0.75\n4  0.1875\n\n");
  EXPECT_NE(r.out.find("erreur L2 (pente -2.000)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("ordre 1 (pente -1.000)"), std::string::npos) << r.out;
  EXPECT_GT(fs::file_size(r.dir / "out" / "convergence.png"), 1000u);
}

TEST(PostCommands, ImprFonctionXmgrace) {
  // Without PILOTE, a Grace project: the sets in order, Grace's escapes kept in
  // the texts (code_aster's titles use them), a quote in a text made harmless.
  const auto r = run("grace", R"(
DEFI_FICHIER{ACTION='ASSOCIER', UNITE=82, FICHIER='out/courbe.agr'}
IMPR_FONCTION{FORMAT='XMGRACE', UNITE=82, TITRE=[[Erreur en norme L\s2\N]], ECHELLE_X='LOG', LEGENDE_Y='say "h"',
  BORNE_X={0.5, 4}, COURBE={{ABSCISSE={1, 2}, ORDONNEE={3, 0.75}, LEGENDE='e'}, {ABSCISSE={1}, ORDONNEE={2}}}}
DEFI_FICHIER{ACTION='ASSOCIER', UNITE=83, FICHIER='out/courbe.eps'}
IMPR_FONCTION{FORMAT='XMGRACE', UNITE=83, PILOTE='EPS', COURBE={ABSCISSE={1, 2}, ORDONNEE={3, 0.75}}}
)");
  EXPECT_EQ(r.status, 0) << r.err << r.out;
  EXPECT_EQ(readFile(r.dir / "out" / "courbe.agr"),
            "# Grace project file\n@version 50125\n@title \"Erreur en norme L\\s2\\N\"\n@with g0\n"
            "@    world xmin 0.5\n@    world xmax 4\n@    xaxes scale Logarithmic\n@    yaxes scale Normal\n"
            "@    yaxis label \"say 'h'\"\n@    s0 legend \"e\"\n@    s1 legend \"\"\n"
            "@target G0.S0\n@type xy\n1 3\n2 0.75\n&\n@target G0.S1\n@type xy\n1 2\n&\n");
  EXPECT_EQ(readFile(r.dir / "out" / "courbe.eps").rfind("%!PS-Adobe", 0), 0u);
}

TEST(PostCommands, ClearErrors) {
  // ELNO fields are extracted from results only: AFFE of one is refused clearly.
  auto r = run("err1", R"(
CH = CREA_CHAMP{TYPE_CHAM='ELNO_NEUT_R', OPERATION='AFFE', MODELE=MODE, AFFE={TOUT='OUI', NOM_CMP={'X1'}, VALE={1.0}}}
)");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("TYPE_CHAM='ELNO_NEUT_R': fields at the nodes of cells (ELNO) are made by OPERATION='EXTR' "
                       "from a result only"),
            std::string::npos)
      << r.err;
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

// ------------------------------------------------------------ fields at Gauss points
// On SURFACE (M6, the unit square: x = (1 + xi) / 2, y = (1 + eta) / 2) the model
// integrates with code_aster's FPG9, 3 x 3 Gauss points xi, eta in {-a, 0, a},
// a = sqrt(3/5), numbered as code_aster does: the corners counterclockwise from
// (-a, -a), the mid-edges counterclockwise from (0, -a), the centre. On BAS (M4, from N4 (1,0) to N1 (0,0))
// a SEG3 has 3 points, x = (1 - s) / 2 for s = -a, 0, a. Expected values below
// come from these formulas, not from the program.
namespace {

const char* kGaussPoints = R"(
local a = math.sqrt(0.6)
XI = {-a, 0.0, a}
FPG9 = {{-a, -a}, {a, -a}, {a, a}, {-a, a}, {0, -a}, {a, 0}, {0, a}, {-a, 0}, {0, 0}}
function surfacePoint(q)  -- q = 1..9 -> x, y on M6
  return (1 + FPG9[q][1]) / 2, (1 + FPG9[q][2]) / 2
end
MODT = AFFE_MODELE{MAILLAGE=MAIL, AFFE={TOUT='OUI', PHENOMENE='MECANIQUE', MODELISATION='D_PLAN'}}
GEOM = CREA_CHAMP{TYPE_CHAM='NOEU_GEOM_R', OPERATION='EXTR', MAILLAGE=MAIL, NOM_CHAM='GEOMETRIE'}
)";

}  // namespace

TEST(ElgaFields, DiscOfQuadraticNodalFieldsIsExactAtTheGaussPoints) {
  // DX = 2 + 2x - 3y + x^2 + xy - y^2/2 and DY = 1 + x + 2y are in the QUAD8's
  // space: DISC must give their values at the 9 points (and the geometry X, Y
  // of the points, on SURFACE and on the segment BAS), to 1e-13.
  const auto r = run("disc", std::string(kGaussPoints) + R"(
F1 = FORMULE{VALE='2 + 2*X - 3*Y + X*X + X*Y - 0.5*Y*Y', NOM_PARA={'X', 'Y'}}
F2 = FORMULE{VALE='1 + X + 2*Y', NOM_PARA={'X', 'Y'}}
CF = CREA_CHAMP{TYPE_CHAM='NOEU_NEUT_F', OPERATION='AFFE', MAILLAGE=MAIL,
                AFFE={GROUP_MA='SURFACE', NOM_CMP={'X1', 'X2'}, VALE_F={F1, F2}}}
CV = CREA_CHAMP{TYPE_CHAM='NOEU_NEUT_R', OPERATION='EVAL', CHAM_F=CF, CHAM_PARA={GEOM}}
U = CREA_CHAMP{TYPE_CHAM='NOEU_DEPL_R', OPERATION='ASSE', MAILLAGE=MAIL,
               ASSE={GROUP_MA='SURFACE', CHAM_GD=CV, NOM_CMP={'X1', 'X2'}, NOM_CMP_RESU={'DX', 'DY'}}}
UG = CREA_CHAMP{TYPE_CHAM='ELGA_DEPL_R', OPERATION='DISC', MODELE=MODE, CHAM_GD=U}
XG = CREA_CHAMP{TYPE_CHAM='ELGA_GEOM_R', OPERATION='DISC', MODELE=MODT, CHAM_GD=GEOM}
local checks = {}
for q = 1, 9 do
  local x, y = surfacePoint(q)
  local dx = 2 + 2*x - 3*y + x*x + x*y - 0.5*y*y
  local dy = 1 + x + 2*y
  checks[#checks + 1] = {CHAM_GD=UG, GROUP_MA='SURFACE', POINT=q, NOM_CMP='DX', VALE_CALC=dx, TOLE_MACHINE=1e-13}
  checks[#checks + 1] = {CHAM_GD=UG, GROUP_MA='SURFACE', POINT=q, NOM_CMP='DY', VALE_CALC=dy, TOLE_MACHINE=1e-13}
  checks[#checks + 1] = {CHAM_GD=XG, GROUP_MA='SURFACE', POINT=q, NOM_CMP='X', VALE_CALC=x, TOLE_MACHINE=1e-13}
  checks[#checks + 1] = {CHAM_GD=XG, GROUP_MA='SURFACE', POINT=q, NOM_CMP='Y', VALE_CALC=y, TOLE_MACHINE=1e-13}
end
for q = 1, 3 do
  checks[#checks + 1] = {CHAM_GD=XG, GROUP_MA='BAS', POINT=q, NOM_CMP='X', VALE_CALC=(1 - XI[q]) / 2, TOLE_MACHINE=1e-13}
end
TEST_RESU{CHAM_ELEM=checks}
-- XG lives on the 6 cells of MODT: Z is 0 everywhere; the largest X is on MAITRE
-- (N6 (1.5, -0.05), N5 (-0.5, -0.05), middle N11 (0.5, 0): x = 0.5 - s), at s = -a.
TEST_RESU{CHAM_ELEM={{CHAM_GD=XG, TYPE_TEST='SOMM_ABS', NOM_CMP='Z', VALE_CALC=0.0, ORDRE_GRANDEUR=1.0, CRITERE='ABSOLU', TOLE_MACHINE=1e-15},
                     {CHAM_GD=XG, TYPE_TEST='MAX', NOM_CMP='X', VALE_CALC=0.5 + a, TOLE_MACHINE=1e-13}}}
print('values ' .. #UG:getValues() .. ' ' .. #XG:getValues())
)");
  EXPECT_EQ(r.status, 0) << r.err << r.out;
  EXPECT_EQ(r.ok, 41) << r.out;
  EXPECT_EQ(r.nook, 0);
  // UG: 9 points x 2 components; XG: (9 + 5 * 3) points x 3 components.
  EXPECT_NE(r.out.find("values 18 72"), std::string::npos) << r.out;
}

TEST(ElgaFields, EvalOfFunctionsAtTheGaussPointsGeometry) {
  // F(X, Y) = sin(X) exp(Y) assigned at the Gauss points of TOUT, evaluated with
  // the points' coordinates: F(x_q, y_q) on SURFACE, F((1 - s)/2, 0) on BAS.
  // G = X1 + X2 (two parameters taken from two fields) checks CHAM_PARA lists.
  const auto r = run("eval", std::string(kGaussPoints) + R"(
F = FORMULE{VALE='sin(X)*exp(Y)', NOM_PARA={'X', 'Y'}}
XG = CREA_CHAMP{TYPE_CHAM='ELGA_GEOM_R', OPERATION='DISC', MODELE=MODT, CHAM_GD=GEOM}
CF = CREA_CHAMP{TYPE_CHAM='ELGA_NEUT_F', OPERATION='AFFE', MODELE=MODT, AFFE={TOUT='OUI', NOM_CMP='X1', VALE_F=F}}
CV = CREA_CHAMP{TYPE_CHAM='ELGA_NEUT_R', OPERATION='EVAL', CHAM_F=CF, CHAM_PARA=XG}
local checks = {}
for q = 1, 9 do
  local x, y = surfacePoint(q)
  checks[#checks + 1] = {CHAM_GD=CV, GROUP_MA='SURFACE', POINT=q, NOM_CMP='X1', VALE_CALC=math.sin(x) * math.exp(y),
                         TOLE_MACHINE=1e-13}
end
for q = 1, 3 do
  checks[#checks + 1] = {CHAM_GD=CV, GROUP_MA='BAS', POINT=q, NOM_CMP='X1', VALE_CALC=math.sin((1 - XI[q]) / 2),
                         TOLE_MACHINE=1e-13}
end
TEST_RESU{CHAM_ELEM=checks}
C2 = CREA_CHAMP{TYPE_CHAM='ELGA_NEUT_R', OPERATION='AFFE', MODELE=MODE, AFFE={TOUT='OUI', NOM_CMP='X2', VALE=10.0}}
G = FORMULE{VALE='X1 + X2', NOM_PARA={'X1', 'X2'}}
GF = CREA_CHAMP{TYPE_CHAM='ELGA_NEUT_F', OPERATION='AFFE', MODELE=MODE, AFFE={GROUP_MA='SURFACE', NOM_CMP='X3', VALE_F=G}}
GV = CREA_CHAMP{TYPE_CHAM='ELGA_NEUT_R', OPERATION='EVAL', CHAM_F=GF, CHAM_PARA={CV, C2}}
local x, y = surfacePoint(7)
TEST_RESU{CHAM_ELEM={CHAM_GD=GV, GROUP_MA='SURFACE', POINT=7, NOM_CMP='X3', VALE_CALC=math.sin(x) * math.exp(y) + 10,
                     TOLE_MACHINE=1e-13}}
)");
  EXPECT_EQ(r.status, 0) << r.err << r.out;
  EXPECT_EQ(r.ok, 13) << r.out;
}

TEST(ElgaFields, PostElemNormIntegratesAtTheModelsGaussPoints) {
  // int over the unit square of (x y)^2 = 1/9: norm 1/3, on M6 and on the mesh
  // refined twice (16 QUAD8, |J| = 1/64); 3 x 3 points integrate it exactly.
  // Over BAS: int_0^1 x^2 = 1/3 (3 points on the SEG3). With two components
  // X1 = x y and X2 = 2: 1/9 + 4 (COEF_MULT {1, 0.25}: 1/9 + 1).
  const auto r = run("norme", std::string(kGaussPoints) + R"(
FXY = FORMULE{VALE='X*Y', NOM_PARA={'X', 'Y'}}
FX = FORMULE{VALE='X', NOM_PARA={'X'}}
TWO = FORMULE{VALE='2 + 0*X', NOM_PARA={'X'}}
function cellField(mesh, model, name)
  local chxn = CREA_CHAMP{TYPE_CHAM='NOEU_GEOM_R', OPERATION='EXTR', MAILLAGE=mesh, NOM_CHAM='GEOMETRIE'}
  local chxg = CREA_CHAMP{TYPE_CHAM='ELGA_GEOM_R', OPERATION='DISC', MODELE=model, CHAM_GD=chxn}
  local cf = CREA_CHAMP{TYPE_CHAM='ELGA_NEUT_F', OPERATION='AFFE', MODELE=model,
                        AFFE={{GROUP_MA='SURFACE', NOM_CMP={'X1', 'X2'}, VALE_F={FXY, TWO}},
                              {GROUP_MA='BAS', NOM_CMP='X1', VALE_F=FX}}}
  return CREA_CHAMP{TYPE_CHAM='ELGA_NEUT_R', OPERATION='EVAL', CHAM_F=cf, CHAM_PARA=chxg}
end
V0 = cellField(MAIL, MODT, 'V0')
N0 = POST_ELEM{NORME={TYPE_NORM='L2', GROUP_MA='SURFACE', CHAM_GD=V0, MODELE=MODT, NOM_CMP='X1'}}
TEST_TABLE{TABLE=N0, NOM_PARA='VALE_NORM', VALE_CALC=1/3, TOLE_MACHINE=1e-12}
NB = POST_ELEM{NORME={TYPE_NORM='L2', GROUP_MA='BAS', CHAM_GD=V0, MODELE=MODT, NOM_CMP='X1'}}
TEST_TABLE{TABLE=NB, NOM_PARA='VALE_NORM', VALE_CALC=math.sqrt(1/3), TOLE_MACHINE=1e-12}
N2 = POST_ELEM{NORME={TYPE_NORM='L2', GROUP_MA='SURFACE', CHAM_GD=V0, MODELE=MODT}}
TEST_TABLE{TABLE=N2, NOM_PARA='VALE_NORM', VALE_CALC=math.sqrt(1/9 + 4), TOLE_MACHINE=1e-12}
NW = POST_ELEM{NORME={TOUT='OUI', CHAM_GD=V0, MODELE=MODT, NOM_CMP={'X1', 'X2'}, COEF_MULT={1, 0.25}}}
TEST_TABLE{TABLE=NW, NOM_PARA='VALE_NORM', VALE_CALC=math.sqrt(1/9 + 1), TOLE_MACHINE=1e-12}
MA1 = MACR_ADAP_MAIL{ADAPTATION='RAFFINEMENT_UNIFORME', GROUP_MA='SURFACE', MAILLAGE_N=MAIL}
MA2 = MACR_ADAP_MAIL{ADAPTATION='RAFFINEMENT_UNIFORME', GROUP_MA='SURFACE', MAILLAGE_N=MA1}
MO2 = AFFE_MODELE{MAILLAGE=MA2, AFFE={TOUT='OUI', PHENOMENE='MECANIQUE', MODELISATION='D_PLAN'}}
V2 = cellField(MA2, MO2, 'V2')
N4 = POST_ELEM{NORME={TYPE_NORM='L2', GROUP_MA={'SURFACE', 'BAS'}, CHAM_GD=V2, MODELE=MO2, NOM_CMP='X1'}}
TEST_TABLE{TABLE=N4, NOM_PARA='VALE_NORM', FILTRE={NOM_PARA='GROUP_MA', VALE_K='SURFACE'}, VALE_CALC=1/3, TOLE_MACHINE=1e-12}
TEST_TABLE{TABLE=N4, NOM_PARA='VALE_NORM', FILTRE={NOM_PARA='GROUP_MA', VALE_K='BAS'}, VALE_CALC=math.sqrt(1/3),
           TOLE_MACHINE=1e-12}
print('cells ' .. #MA2:getCells('SURFACE'))
)");
  EXPECT_EQ(r.status, 0) << r.err << r.out;
  EXPECT_EQ(r.ok, 6) << r.out;
  EXPECT_NE(r.out.find("cells 16"), std::string::npos) << r.out;
}

TEST(ElgaFields, AffeAsseProlZeroAndTypeTest) {
  // MODT carries M6 (9 points) and 5 SEG3 (3 points each): 24 points.
  const auto r = run("affe_asse", std::string(kGaussPoints) + R"(
C = CREA_CHAMP{TYPE_CHAM='ELGA_DEPL_R', OPERATION='AFFE', MODELE=MODT, AFFE={TOUT='OUI', NOM_CMP={'DX', 'DY'}, VALE={1.5, -2.0}}}
-- SOMM_ABS = 24 * 3.5, SOMM of DY = 24 * -2.
TEST_RESU{CHAM_ELEM={{CHAM_GD=C, TYPE_TEST='SOMM_ABS', VALE_CALC=84.0},
                     {CHAM_GD=C, TYPE_TEST='SOMM', NOM_CMP='DY', VALE_CALC=-48.0},
                     {CHAM_GD=C, TYPE_TEST='MAX', VALE_CALC=1.5},
                     {CHAM_GD=C, TYPE_TEST='MIN', VALE_CALC=-2.0},
                     {CHAM_GD=C, GROUP_MA='HAUT', POINT=2, NOM_CMP='DX', VALE_CALC=1.5}}}
-- DX = 1 on BAS only; PROL_ZERO='OUI': every cell of the model, DX = 0 elsewhere.
B = CREA_CHAMP{TYPE_CHAM='ELGA_DEPL_R', OPERATION='AFFE', MODELE=MODT, PROL_ZERO='OUI',
               AFFE={GROUP_MA='BAS', NOM_CMP='DX', VALE=1.0}}
TEST_RESU{CHAM_ELEM={{CHAM_GD=B, TYPE_TEST='SOMM', VALE_CALC=3.0},
                     {CHAM_GD=B, GROUP_MA='SURFACE', POINT=5, NOM_CMP='DX', VALE_CALC=0.0, ORDRE_GRANDEUR=1.0, CRITERE='ABSOLU'}}}
-- D = 2 C - B on SURFACE and BAS (CUMUL), DY renamed DZ: on BAS DX = 2 * 1.5 - 1 = 2, on
-- SURFACE 3; DZ = -4 on the 12 points of both.
D = CREA_CHAMP{TYPE_CHAM='ELGA_DEPL_R', OPERATION='ASSE', MODELE=MODT, ASSE={
  {GROUP_MA={'SURFACE', 'BAS'}, CHAM_GD=C, NOM_CMP={'DX', 'DY'}, NOM_CMP_RESU={'DX', 'DZ'}, CUMUL='OUI', COEF_R=2.0},
  {GROUP_MA={'SURFACE', 'BAS'}, CHAM_GD=B, NOM_CMP='DX', CUMUL='OUI', COEF_R=-1.0}}}
TEST_RESU{CHAM_ELEM={{CHAM_GD=D, GROUP_MA='BAS', POINT=3, NOM_CMP='DX', VALE_CALC=2.0},
                     {CHAM_GD=D, GROUP_MA='SURFACE', POINT=9, NOM_CMP='DX', VALE_CALC=3.0},
                     {CHAM_GD=D, TYPE_TEST='SOMM', NOM_CMP='DZ', VALE_CALC=-48.0},
                     {CHAM_GD=D, TYPE_TEST='SOMM', NOM_CMP='DX', VALE_CALC=9 * 3.0 + 3 * 2.0}}}
-- Components on some cells only: DX on SURFACE, DY on BAS. The norm over SURFACE of DX
-- alone is 3 (|SURFACE| = 1); asking for DY there is an error (next test).
E = CREA_CHAMP{TYPE_CHAM='ELGA_DEPL_R', OPERATION='ASSE', MODELE=MODT, ASSE={
  {GROUP_MA='SURFACE', CHAM_GD=D, NOM_CMP='DX'},
  {GROUP_MA='BAS', CHAM_GD=C, NOM_CMP='DY'}}}
NE = POST_ELEM{NORME={GROUP_MA='SURFACE', CHAM_GD=E, MODELE=MODT, NOM_CMP='DX'}}
TEST_TABLE{TABLE=NE, NOM_PARA='VALE_NORM', VALE_CALC=3.0, TOLE_MACHINE=1e-13}
TEST_RESU{CHAM_ELEM={{CHAM_GD=E, TYPE_TEST='SOMM', VALE_CALC=9 * 3.0 + 3 * -2.0}}}
print('values ' .. #E:getValues() .. ' ' .. table.concat(E:getComponents(), ','))
)");
  EXPECT_EQ(r.status, 0) << r.err << r.out;
  EXPECT_EQ(r.ok, 13) << r.out;
  // E lives on M4 (BAS) and M6: (3 + 9) points x 2 components, absent ones stored as 0.
  EXPECT_NE(r.out.find("values 24 DX,DY"), std::string::npos) << r.out;
}

TEST(ElgaFields, ChainOnTheFinestMeshAgreesWithPostErreur) {
  // The reference study's L2 error (ELGA fields + POST_ELEM NORME) and POST_ERREUR
  // on ssnp150b's finest mesh (256 QUAD8, h = 1/16), for U = ((x^2 - x)(y^2 - y), 2x - y)
  // interpolated at the nodes. On each (affine) cell x^2 y^2 - its QUAD8 interpolant
  // is (h/2)^4 (1 - xi^2)(1 - eta^2) and DY is exact, so both errors are
  // sqrt(sum_cells (h/2)^10 (16/15)^2) = h^4 / 30 = 1 / 1966080: 3 x 3 Gauss points
  // (the chain) and POST_ERREUR's rule integrate this polynomial exactly.
  const auto r = run("chain", R"(
local M = MAIL
for i = 1, 4 do M = MACR_ADAP_MAIL{ADAPTATION='RAFFINEMENT_UNIFORME', GROUP_MA='SURFACE', MAILLAGE_N=M} end
MO4 = AFFE_MODELE{MAILLAGE=M, AFFE={TOUT='OUI', PHENOMENE='MECANIQUE', MODELISATION='D_PLAN'}}
FB = FORMULE{VALE='(X*X - X)*(Y*Y - Y)', NOM_PARA={'X', 'Y'}}
FL = FORMULE{VALE='2*X - Y', NOM_PARA={'X', 'Y'}}
CHXN = CREA_CHAMP{TYPE_CHAM='NOEU_GEOM_R', OPERATION='EXTR', MAILLAGE=M, NOM_CHAM='GEOMETRIE'}
UF = CREA_CHAMP{TYPE_CHAM='NOEU_NEUT_F', OPERATION='AFFE', MAILLAGE=M,
                AFFE={GROUP_MA='SURFACE', NOM_CMP={'X1', 'X2'}, VALE_F={FB, FL}}}
UN = CREA_CHAMP{TYPE_CHAM='NOEU_NEUT_R', OPERATION='EVAL', CHAM_F=UF, CHAM_PARA=CHXN}
UCALC = CREA_CHAMP{TYPE_CHAM='NOEU_DEPL_R', OPERATION='ASSE', MAILLAGE=M,
                   ASSE={GROUP_MA='SURFACE', CHAM_GD=UN, NOM_CMP={'X1', 'X2'}, NOM_CMP_RESU={'DX', 'DY'}}}
EU = POST_ERREUR{OPTION='DEPL_ABSO', CHAM_GD=UCALC, MODELE=MO4, GROUP_MA='SURFACE', DX=FB, DY=FL}
CHXG = CREA_CHAMP{TYPE_CHAM='ELGA_GEOM_R', OPERATION='DISC', MODELE=MO4, CHAM_GD=CHXN}
UANAF = CREA_CHAMP{TYPE_CHAM='ELGA_NEUT_F', OPERATION='AFFE', MODELE=MO4,
                   AFFE={GROUP_MA='SURFACE', NOM_CMP={'X1', 'X2'}, VALE_F={FB, FL}}}
UANA = CREA_CHAMP{TYPE_CHAM='ELGA_NEUT_R', OPERATION='EVAL', CHAM_F=UANAF, CHAM_PARA=CHXG}
UCALG = CREA_CHAMP{TYPE_CHAM='ELGA_DEPL_R', OPERATION='DISC', MODELE=MO4, CHAM_GD=UCALC}
DIFF = CREA_CHAMP{TYPE_CHAM='ELGA_DEPL_R', OPERATION='ASSE', MODELE=MO4, ASSE={
  {GROUP_MA='SURFACE', CHAM_GD=UCALG, NOM_CMP={'DX', 'DY'}, CUMUL='OUI', COEF_R=1.0},
  {GROUP_MA='SURFACE', CHAM_GD=UANA, NOM_CMP={'X1', 'X2'}, NOM_CMP_RESU={'DX', 'DY'}, CUMUL='OUI', COEF_R=-1.0}}}
N = POST_ELEM{NORME={TYPE_NORM='L2', GROUP_MA='SURFACE', CHAM_GD=DIFF, MODELE=MO4}}
TEST_TABLE{TABLE=N, NOM_PARA='VALE_NORM', VALE_CALC=1/1966080, TOLE_MACHINE=1e-10}
TEST_TABLE{TABLE=EU, NOM_PARA='ERREUR', FILTRE={NOM_PARA='GROUP_MA', VALE_K='SURFACE'}, VALE_CALC=1/1966080,
           TOLE_MACHINE=1e-10}
print(string.format('cells %d chain %.17g post_erreur %.17g', #M:getCells('SURFACE'), N:get('VALE_NORM', 1),
                    EU:get('ERREUR', 1)))
)");
  EXPECT_EQ(r.status, 0) << r.err << r.out;
  EXPECT_EQ(r.ok, 2) << r.out;
  EXPECT_NE(r.out.find("cells 256 "), std::string::npos) << r.out;
}

TEST(ElgaFields, ClearErrors) {
  struct Case {
    const char* body;
    const char* message;
  };
  const Case cases[] = {
      // DISC from a field at Gauss points back to the nodes.
      {R"(XG = CREA_CHAMP{TYPE_CHAM='ELGA_GEOM_R', OPERATION='DISC', MODELE=MODT, CHAM_GD=GEOM}
X = CREA_CHAMP{TYPE_CHAM='NOEU_GEOM_R', OPERATION='DISC', MODELE=MODT, CHAM_GD=XG})",
       "OPERATION='DISC' from the field at Gauss points XG to TYPE_CHAM='NOEU_GEOM_R' is not possible"},
      // DISC to the Gauss points without the model.
      {R"(XG = CREA_CHAMP{TYPE_CHAM='ELGA_GEOM_R', OPERATION='DISC', CHAM_GD=GEOM})",
       "MODELE is missing: OPERATION='DISC' towards TYPE_CHAM='ELGA_GEOM_R' needs the model"},
      {R"(C = CREA_CHAMP{TYPE_CHAM='ELGA_NEUT_R', OPERATION='AFFE', MAILLAGE=MAIL, AFFE={TOUT='OUI', NOM_CMP='X1', VALE=1.0}})",
       "MODELE is missing: OPERATION='AFFE' towards TYPE_CHAM='ELGA_NEUT_R' needs the model whose cells and Gauss "
       "points carry the field (MAILLAGE is for nodal fields)"},
      // Unknown components.
      {R"(C = CREA_CHAMP{TYPE_CHAM='ELGA_NEUT_R', OPERATION='AFFE', MODELE=MODT, AFFE={TOUT='OUI', NOM_CMP='DX', VALE=1.0}})",
       "AFFE[1]: NOM_CMP: component DX does not belong to the quantity NEUT (X1, X2, ...), that of TYPE_CHAM='ELGA_NEUT_R'"},
      {R"(XG = CREA_CHAMP{TYPE_CHAM='ELGA_DEPL_R', OPERATION='DISC', MODELE=MODT, CHAM_GD=GEOM})",
       "CHAM_GD GEOM: component X does not belong to the quantity DEPL"},
      {R"(XG = CREA_CHAMP{TYPE_CHAM='ELGA_GEOM_R', OPERATION='DISC', MODELE=MODT, CHAM_GD=GEOM}
D = CREA_CHAMP{TYPE_CHAM='ELGA_DEPL_R', OPERATION='ASSE', MODELE=MODT, ASSE={TOUT='OUI', CHAM_GD=XG, NOM_CMP='DX'}})",
       "ASSE[1]: NOM_CMP: the field XG has no component DX (components: X, Y, Z)"},
      {R"(XG = CREA_CHAMP{TYPE_CHAM='ELGA_GEOM_R', OPERATION='DISC', MODELE=MODT, CHAM_GD=GEOM}
N = POST_ELEM{NORME={GROUP_MA='SURFACE', CHAM_GD=XG, MODELE=MODT, NOM_CMP='DX'}})",
       "NORME: NOM_CMP: the field XG has no component DX (components: X, Y, Z)"},
      {R"(XG = CREA_CHAMP{TYPE_CHAM='ELGA_GEOM_R', OPERATION='DISC', MODELE=MODT, CHAM_GD=GEOM}
TEST_RESU{CHAM_ELEM={CHAM_GD=XG, GROUP_MA='SURFACE', POINT=1, NOM_CMP='DX', VALE_CALC=0.0}})",
       "CHAM_ELEM[1]: NOM_CMP: the field XG has no component DX (components: X, Y, Z)"},
      // A component absent on a cell the norm integrates over.
      {R"(E = CREA_CHAMP{TYPE_CHAM='ELGA_DEPL_R', OPERATION='AFFE', MODELE=MODT, AFFE={
  {GROUP_MA='SURFACE', NOM_CMP='DX', VALE=1.0}, {GROUP_MA='BAS', NOM_CMP='DY', VALE=1.0}}}
N = POST_ELEM{NORME={GROUP_MA='SURFACE', CHAM_GD=E, MODELE=MODT}})",
       "NORME: component DY of the field E is not defined on cell M6 of GROUP_MA SURFACE"},
      // EVAL at Gauss points with a nodal parameter field.
      {R"(F = FORMULE{VALE='X', NOM_PARA='X'}
CF = CREA_CHAMP{TYPE_CHAM='ELGA_NEUT_F', OPERATION='AFFE', MODELE=MODT, AFFE={TOUT='OUI', NOM_CMP='X1', VALE_F=F}}
CV = CREA_CHAMP{TYPE_CHAM='ELGA_NEUT_R', OPERATION='EVAL', CHAM_F=CF, CHAM_PARA=GEOM})",
       "CHAM_PARA: GEOM is a nodal field; CHAM_F is at Gauss points"},
      // A check needs POINT with GROUP_MA; POINT must exist.
      {R"(XG = CREA_CHAMP{TYPE_CHAM='ELGA_GEOM_R', OPERATION='DISC', MODELE=MODT, CHAM_GD=GEOM}
TEST_RESU{CHAM_ELEM={CHAM_GD=XG, GROUP_MA='SURFACE', NOM_CMP='X', VALE_CALC=0.0}})",
       "CHAM_ELEM[1]: POINT is missing: the Gauss point of cell M6 (1 to 9)"},
      {R"(XG = CREA_CHAMP{TYPE_CHAM='ELGA_GEOM_R', OPERATION='DISC', MODELE=MODT, CHAM_GD=GEOM}
TEST_RESU{CHAM_ELEM={CHAM_GD=XG, GROUP_MA='BAS', POINT=4, NOM_CMP='X', VALE_CALC=0.0}})",
       "CHAM_ELEM[1]: POINT=4: cell M4 has 3 Gauss points in the field XG"},
      // MODE carries SURFACE only.
      {R"(C = CREA_CHAMP{TYPE_CHAM='ELGA_NEUT_R', OPERATION='AFFE', MODELE=MODE, AFFE={GROUP_MA='BAS', NOM_CMP='X1', VALE=1.0}})",
       "AFFE[1]: no cell of GROUP_MA BAS belongs to the model (AFFE_MODELE)"},
      // The geometry at Gauss points is made by DISC, not EXTR.
      {R"(XG = CREA_CHAMP{TYPE_CHAM='ELGA_GEOM_R', OPERATION='EXTR', MAILLAGE=MAIL, NOM_CHAM='GEOMETRIE'})",
       "the coordinates of the Gauss points are CREA_CHAMP{OPERATION='DISC', TYPE_CHAM='ELGA_GEOM_R'"},
  };
  int i = 0;
  for (const auto& c : cases) {
    const auto r = run("elga_err" + std::to_string(++i), std::string(kGaussPoints) + c.body);
    EXPECT_EQ(r.status, 2) << c.body << "\n" << r.out;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << c.body << "\n" << r.err;
    EXPECT_NE(r.err.find("<F> <"), std::string::npos) << r.err;
  }
}

// The unit square pulled by DY = 0.01 on HAUT, DX = DY = 0 on BAS, PETIT, E = 1, NU = 0: result R.
const char* kPulledSquare = R"(
MAT = DEFI_MATERIAU{ELAS={E=1.0, NU=0.0}}
CM = AFFE_MATERIAU{MAILLAGE=MAIL, AFFE={TOUT='OUI', MATER=MAT}}
BC = AFFE_CHAR_MECA{MODELE=MODE, DDL_IMPO={{GROUP_MA='BAS', DX=0.0, DY=0.0}, {GROUP_MA='HAUT', DY=0.01}}}
L = DEFI_LIST_REEL{DEBUT=0.0, INTERVALLE={JUSQU_A=1.0, NOMBRE=1}}
R = STAT_NON_LINE{MODELE=MODE, CHAM_MATER=CM, EXCIT={CHARGE=BC},
                  COMPORTEMENT={RELATION='ELAS', DEFORMATION='PETIT'}, INCREMENT={LIST_INST=L}}
)";

TEST(ElgaFields, ExtrOfSiefElgaFromAResult) {
  // The unit square pulled by DY = 0.01 on HAUT, DX = DY = 0 on BAS, PETIT, E = 1,
  // NU = 0: a uniform strain eps_yy = 0.01, hence SIYY = 0.01 and SIXX = SIZZ =
  // SIXY = 0 at the 9 points of M6. EXTR gives that field (ELGA_SIEF_R) at the
  // model's Gauss points: POST_ELEM integrates it (norm of SIYY = 0.01 over the
  // unit area), ASSE combines it.
  const auto r = run("extr", std::string(kPulledSquare) + R"(
S = CREA_CHAMP{TYPE_CHAM='ELGA_SIEF_R', OPERATION='EXTR', RESULTAT=R, NOM_CHAM='SIEF_ELGA', INST=1.0}
TEST_RESU{CHAM_ELEM={{CHAM_GD=S, GROUP_MA='SURFACE', POINT=7, NOM_CMP='SIYY', VALE_CALC=0.01, TOLE_MACHINE=1e-10},
                     {CHAM_GD=S, TYPE_TEST='SOMM', NOM_CMP='SIYY', VALE_CALC=0.09, TOLE_MACHINE=1e-10},
                     {CHAM_GD=S, TYPE_TEST='MAX', NOM_CMP='SIXX', VALE_CALC=0.0, ORDRE_GRANDEUR=1.0, CRITERE='ABSOLU', TOLE_MACHINE=1e-12}}}
N = POST_ELEM{NORME={GROUP_MA='SURFACE', CHAM_GD=S, MODELE=MODE, NOM_CMP='SIYY'}}
TEST_TABLE{TABLE=N, NOM_PARA='VALE_NORM', VALE_CALC=0.01, TOLE_MACHINE=1e-10}
N2 = CREA_CHAMP{TYPE_CHAM='ELGA_NEUT_R', OPERATION='ASSE', MODELE=MODE,
                ASSE={TOUT='OUI', CHAM_GD=S, NOM_CMP='SIYY', NOM_CMP_RESU='X1', COEF_R=100.0}}
TEST_RESU{CHAM_ELEM={CHAM_GD=N2, TYPE_TEST='SOMM', VALE_CALC=9.0, TOLE_MACHINE=1e-10}}
)");
  EXPECT_EQ(r.status, 0) << r.err << r.out;
  EXPECT_EQ(r.ok, 5) << r.out;
  const auto bad = run("extr_bad", std::string(kPulledSquare) + R"(
S = CREA_CHAMP{TYPE_CHAM='ELGA_DEPL_R', OPERATION='EXTR', RESULTAT=R, NOM_CHAM='DEPL', INST=1.0}
)");
  EXPECT_EQ(bad.status, 2);
  EXPECT_NE(bad.err.find("NOM_CHAM='DEPL' is a nodal field: TYPE_CHAM='NOEU_..._R' (then OPERATION='DISC'"),
            std::string::npos)
      << bad.err;
}

TEST(CalcChamp, ElnoFieldsPrintedReadAndDestroyed) {
  // The unit square stretched along x: DX = 0 on GAUCHE, DY = 0 on BAS, DX = 0.01 on
  // DROITE, D_PLAN, E = 1000, NU = 0.25: EPXX = 0.01, SIYY = 0, SIXX = E / (1 - NU^2) EPXX
  // = 10.666..., SIZZ = NU SIXX = 2.666... everywhere. SIGM_ELNO has 8 nodes x 4 values on
  // the one QUAD8; IMPR_RESU prints it node by node under code_aster's heading.
  auto r = run("calc_champ_elno", R"(
MAT = DEFI_MATERIAU{ELAS={E=1000.0, NU=0.25}}
CM = AFFE_MATERIAU{MAILLAGE=MAIL, AFFE={TOUT='OUI', MATER=MAT}}
BC = AFFE_CHAR_MECA{MODELE=MODE, DDL_IMPO={{GROUP_MA='GAUCHE', DX=0.0}, {GROUP_MA='BAS', DY=0.0}, {GROUP_MA='DROITE', DX=0.01}}}
R = MECA_STATIQUE{MODELE=MODE, CHAM_MATER=CM, EXCIT={CHARGE=BC}}
R = CALC_CHAMP{reuse=R, RESULTAT=R, CONTRAINTE={'SIGM_ELNO', 'SIGM_NOEU'}}
F = R:getField('SIGM_ELNO', 0.0)
assert(#F:getValues() == 32 and F:getComponents()[3] == 'SIZZ')
C = CREA_CHAMP{TYPE_CHAM='ELNO_SIEF_R', OPERATION='EXTR', RESULTAT=R, NOM_CHAM='SIGM_ELNO'}
TEST_RESU{CHAM_ELEM={CHAM_GD=C, TYPE_TEST='SOMM', NOM_CMP='SIZZ', VALE_CALC=8 * 0.25 * 1000 / (1 - 0.0625) * 0.01}}
DETRUIRE{NOM={C, F}}
IMPR_RESU{FORMAT='RESULTAT', RESU={RESULTAT=R, NOM_CHAM={'SIGM_ELNO'}}}
)");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.ok, 1);
  std::string text;
  for (const auto& e : fs::recursive_directory_iterator(r.dir / "out"))
    if (e.path().string().find(".resu.txt") != std::string::npos) text = readFile(e.path());
  ASSERT_NE(text.find("CHAMP PAR ELEMENT AUX NOEUDS SIGM_ELNO DU RESULTAT R"), std::string::npos) << text;
  EXPECT_NE(text.find(" MAILLE   NOEUD "), std::string::npos) << text;
  // The first node of M6 and its four values.
  EXPECT_NE(text.find(" M6       N1         1.06666667E+01"), std::string::npos) << text;
  int rows = 0;
  for (std::size_t p = text.find(" M6 "); p != std::string::npos; p = text.find(" M6 ", p + 1)) ++rows;
  EXPECT_EQ(rows, 8) << text;
}
