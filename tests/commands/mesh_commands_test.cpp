// Mesh commands driven through the interpreter, as a study runs them:
// LIRE_MAILLAGE, MODI_MAILLAGE, DEFI_GROUP, MACR_ADAP_MAIL, IMPR_RESU.
// Expected numbers come from the geometry, by hand:
//  - ssnp150b.mail: 11 nodes (8 of the QUAD8, 3 of the master SEG3), 6 cells
//    (4 edge SEG3, MAITRE, SURFACE); the edges are listed clockwise.
//  - N x N QUAD8 on the unit square: (N+1)^2 vertices + 2 N (N+1) mid-edge
//    nodes; N = 16: 289 + 544 = 833, plus the 3 nodes of MAITRE = 836.
//    Cells: 256 QUAD8 + 4 x 16 edge SEG3 + MAITRE = 321.
//    Four uniform refinements of ssnp150b (1 QUAD8) give the same N = 16 grid.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

#include "lang/interpreter.hpp"

using namespace aster::lang;
namespace fs = std::filesystem;

namespace {

struct StudyRun {
  int status = 0;
  std::string out, err;
  std::map<std::string, std::string> shown;  // the "@key=value" lines the study printed
};

// A scratch folder per test: the study file's place and its output folder.
class MeshCommands : public testing::Test {
 protected:
  void SetUp() override {
    const auto* info = testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() /
           ("aster_mesh_commands_" + std::to_string(::getpid()) + "_" + info->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override {
    if (!HasFailure()) fs::remove_all(dir_);
  }

  // Runs `code` as <dir>/etude.lua, unit 20 bound to ssnp150b.mail, with a
  // helper show(key, value) printing "@key=value" (lists joined by spaces).
  StudyRun run(const std::string& code, bool unsafeLua = false) {
    Session session;
    session.studyPath = dir_ / "etude.lua";
    session.outputDir = dir_ / "etude";
    session.unsafeLua = unsafeLua;
    Interpreter interpreter(session);
    const std::string prelude =
        "local function show(k, v) if type(v) == 'table' then v = table.concat(v, ' ') end "
        "print('@' .. k .. '=' .. tostring(v)) end "
        "local function xs(M, nodes) local c, out = M:getCoordinates(), {} "
        "for i, n in ipairs(nodes) do out[i] = string.format('%.6f', c[3 * n - 2]) end return out end "
        "DEFI_FICHIER{ACTION='ASSOCIER', UNITE=20, FICHIER='" + ssnp150b() + "'} ";
    testing::internal::CaptureStdout();
    testing::internal::CaptureStderr();
    StudyRun r;
    r.status = interpreter.runString(prelude + code, "@etude.lua");
    r.out = testing::internal::GetCapturedStdout();
    r.err = testing::internal::GetCapturedStderr();
    std::istringstream lines(r.out);
    for (std::string line; std::getline(lines, line);) {
      if (line.empty() || line[0] != '@') continue;
      const auto eq = line.find('=');
      r.shown[line.substr(1, eq - 1)] = line.substr(eq + 1);
    }
    return r;
  }

  static std::string ssnp150b() { return std::string(ASTER_SOURCE_DIR) + "/meshes/ssnp150b.mail"; }
  static std::string ssnp150geo() { return std::string(ASTER_SOURCE_DIR) + "/meshes/ssnp150.geo"; }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }

  fs::path dir_;
};

#define EXPECT_STUDY_OK(r) EXPECT_EQ((r).status, 0) << (r).err << (r).out

TEST_F(MeshCommands, LireMaillageAsterAndMeshMethods) {
  StudyRun r = run(R"(
MAIL = LIRE_MAILLAGE{FORMAT='ASTER', UNITE=20}
show('nodes', MAIL:getNumberOfNodes())
show('cells', MAIL:getNumberOfCells())
show('grma', MAIL:getGroupsOfCells())
show('grno', #MAIL:getGroupsOfNodes())
show('surface', MAIL:getCells('SURFACE'))
show('bas', MAIL:getNodes('BAS'))
)");
  EXPECT_STUDY_OK(r);
  EXPECT_EQ(r.shown["nodes"], "11");
  EXPECT_EQ(r.shown["cells"], "6");
  EXPECT_EQ(r.shown["grma"], "GAUCHE HAUT DROITE BAS MAITRE SURFACE");
  EXPECT_EQ(r.shown["grno"], "0");
  EXPECT_EQ(r.shown["surface"], "6");   // M6, the 6th cell
  EXPECT_EQ(r.shown["bas"], "4 1 10");  // M4 = N4 N1 N10 as written
}

TEST_F(MeshCommands, LireMaillageGmshGeoDefaultN) {
  StudyRun r = run("DEFI_FICHIER{ACTION='ASSOCIER', UNITE=19, FICHIER='" + ssnp150geo() + R"('}
MAIL = LIRE_MAILLAGE{FORMAT='GMSH', UNITE=19}
show('nodes', MAIL:getNumberOfNodes())
show('cells', MAIL:getNumberOfCells())
show('surface', #MAIL:getCells('SURFACE'))
show('bas', #MAIL:getCells('BAS'))
show('basNodes', #MAIL:getNodes('BAS'))
show('maitre', #MAIL:getCells('MAITRE'))
)", true);  // a .geo script: --unsafe-lua
  EXPECT_STUDY_OK(r);
  EXPECT_EQ(r.shown["nodes"], "836");
  EXPECT_EQ(r.shown["cells"], "321");
  EXPECT_EQ(r.shown["surface"], "256");
  EXPECT_EQ(r.shown["bas"], "16");
  EXPECT_EQ(r.shown["basNodes"], "33");  // 17 vertices + 16 middles
  EXPECT_EQ(r.shown["maitre"], "1");
}

TEST_F(MeshCommands, LireMaillageMissingFileNamesUnitAndPath) {
  StudyRun r = run("DEFI_FICHIER{ACTION='ASSOCIER', UNITE=21, FICHIER='absent.mail'}\n"
                         "MAIL = LIRE_MAILLAGE{FORMAT='ASTER', UNITE=21}\n");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("<F> <LIRE_MAILLAGE> etude.lua:2:"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("UNITE=21"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(path("absent.mail")), std::string::npos) << r.err;
}

TEST_F(MeshCommands, ModiMaillageOrientsBasOutwards) {
  // BAS is M4 = N4 (1,0) -> N1 (0,0): walking it, the square is on the right,
  // so its normal (dy, -dx) = (0, 1) points inside; reversed it is N1 N4 N10.
  StudyRun r = run(R"(
MAIL = LIRE_MAILLAGE{FORMAT='ASTER'}
MAIL = MODI_MAILLAGE{reuse=MAIL, MAILLAGE=MAIL, ORIE_PEAU={GROUP_MA_PEAU='BAS'}}
show('bas', MAIL:getNodes('BAS'))
show('haut', MAIL:getNodes('HAUT'))
MODI_MAILLAGE{reuse=MAIL, MAILLAGE=MAIL, ORIE_PEAU_2D={{GROUP_MA={'HAUT', 'DROITE'}}, {GROUP_MA='GAUCHE'}}}
show('haut2', MAIL:getNodes('HAUT'))
show('gauche2', MAIL:getNodes('GAUCHE'))
MODI_MAILLAGE{reuse=MAIL, MAILLAGE=MAIL, ORIE_PEAU={GROUP_MA_PEAU={'BAS', 'HAUT', 'DROITE', 'GAUCHE'}}}
show('bas3', MAIL:getNodes('BAS'))
)");
  EXPECT_STUDY_OK(r);
  EXPECT_EQ(r.shown["bas"], "1 4 10");
  EXPECT_EQ(r.shown["haut"], "2 3 8");     // untouched
  EXPECT_EQ(r.shown["haut2"], "3 2 8");    // (1,1) -> (0,1)
  EXPECT_EQ(r.shown["gauche2"], "2 1 7");  // (0,1) -> (0,0)
  EXPECT_EQ(r.shown["bas3"], "1 4 10");    // already outward: unchanged
  EXPECT_NE(r.out.find("1 of the 1 segments of BAS reversed"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("0 of the 4 segments of BAS, HAUT, DROITE, GAUCHE reversed"), std::string::npos) << r.out;
}

TEST_F(MeshCommands, ModiMaillageWithWrittenFileReadBack) {
  // The orientation survives writing (RESULTAT text = ASTER format) and re-reading.
  StudyRun r = run("DEFI_FICHIER{ACTION='ASSOCIER', UNITE=30, FICHIER='" + path("etude/orie.mail") + R"('}
MAIL = LIRE_MAILLAGE{FORMAT='ASTER'}
MODI_MAILLAGE{reuse=MAIL, MAILLAGE=MAIL, ORIE_PEAU={GROUP_MA_PEAU={'BAS', 'DROITE'}}}
IMPR_RESU{FORMAT='RESULTAT', UNITE=30, RESU={MAILLAGE=MAIL}}
MA2 = LIRE_MAILLAGE{FORMAT='ASTER', UNITE=30}
show('nodes', MA2:getNumberOfNodes())
show('bas', MA2:getNodes('BAS'))
show('droite', MA2:getNodes('DROITE'))
)");
  EXPECT_STUDY_OK(r);
  EXPECT_EQ(r.shown["nodes"], "11");
  EXPECT_EQ(r.shown["bas"], "1 4 10");
  EXPECT_EQ(r.shown["droite"], "4 3 9");  // (1,0) -> (1,1)
}

TEST_F(MeshCommands, DefiGroupNoeudOrdo) {
  StudyRun r = run(R"(
MAIL = LIRE_MAILLAGE{FORMAT='ASTER'}
DEFI_GROUP{reuse=MAIL, MAILLAGE=MAIL, CREA_GROUP_NO={
  {OPTION='NOEUD_ORDO', NOM='BAS_O', GROUP_MA='BAS'},
  {NOM='ORIG', NOEUD='N1'},
}}
DEFI_GROUP{reuse=MAIL, MAILLAGE=MAIL, CREA_GROUP_NO={
  {OPTION='NOEUD_ORDO', NOM='BAS_1', GROUP_MA='BAS', GROUP_NO_ORIG='ORIG'},
  {OPTION='NOEUD_ORDO', NOM='BAS_E', GROUP_MA='BAS', GROUP_NO_EXTR='ORIG'},
  {OPTION='NOEUD_ORDO', NOM='BAS_X', GROUP_MA='BAS', NOEUD_EXTR='N4'},
}}
show('bas_x', MAIL:getNodes('BAS_X'))
show('bas_o', MAIL:getNodes('BAS_O'))
show('bas_1', MAIL:getNodes('BAS_1'))
show('bas_e', MAIL:getNodes('BAS_E'))
-- One refinement: BAS is two SEG3, five nodes from x = 0 to x = 1.
MA1 = MACR_ADAP_MAIL{ADAPTATION='RAFFINEMENT_UNIFORME', MAILLAGE_N=MAIL, MAILLAGE_NP1=CO('MA1')}
DEFI_GROUP{reuse=MA1, MAILLAGE=MA1, DETR_GROUP_NO={NOM={'BAS_O', 'BAS_1', 'BAS_E', 'BAS_X'}},
           CREA_GROUP_NO={OPTION='NOEUD_ORDO', NOM='BAS_O', GROUP_MA='BAS', NOEUD_ORIG='N1'}}
show('x', xs(MA1, MA1:getNodes('BAS_O')))
show('grno', MA1:getGroupsOfNodes())
)");
  EXPECT_STUDY_OK(r);
  EXPECT_EQ(r.shown["bas_o"], "4 10 1");  // the first cell's direction, N4 -> N1
  EXPECT_EQ(r.shown["bas_1"], "1 10 4");
  EXPECT_EQ(r.shown["bas_e"], "4 10 1");
  EXPECT_EQ(r.shown["bas_x"], "1 10 4");
  EXPECT_EQ(r.shown["x"], "0.000000 0.250000 0.500000 0.750000 1.000000");
  EXPECT_EQ(r.shown["grno"], "ORIG BAS_O");
}

TEST_F(MeshCommands, DefiGroupCellGroupsCopiesAndDeletes) {
  StudyRun r = run(R"(
MAIL = LIRE_MAILLAGE{FORMAT='ASTER'}
MAIL2 = DEFI_GROUP{MAILLAGE=MAIL, CREA_GROUP_MA={
  {NOM='BORD', UNION={'BAS', 'HAUT', 'GAUCHE', 'DROITE'}},
  {NOM='TOUT_1D', TOUT='OUI', TYPE_MAILLE='1D'},
  {NOM='RIEN', INTERSEC={'BAS', 'HAUT'}},
  {NOM='SANS_BAS', DIFFE={'BORD', 'BAS'}},
  {NOM='DEUX', MAILLE={'M1', 'M6'}},
}, CREA_GROUP_NO={TOUT_GROUP_MA='OUI'}}
show('mail', #MAIL:getGroupsOfCells())
show('mail2', #MAIL2:getGroupsOfCells())
show('bord', MAIL2:getCells('BORD'))
show('tout1d', MAIL2:getCells('TOUT_1D'))
show('rien', #MAIL2:getCells('RIEN'))
show('sans_bas', MAIL2:getCells('SANS_BAS'))
show('deux', MAIL2:getCells('DEUX'))
show('grno', #MAIL2:getGroupsOfNodes())
show('no_surface', #MAIL2:getNodes('SURFACE'))
DEFI_GROUP{reuse=MAIL2, MAILLAGE=MAIL2, DETR_GROUP_MA={NOM={'RIEN', 'DEUX'}},
           CREA_GROUP_NO={NOM='SOMMETS', GROUP_MA='SURFACE', CRIT_NOEUD='SOMMET'}}
show('after', #MAIL2:getGroupsOfCells())
show('sommets', MAIL2:getNodes('SOMMETS'))
)");
  EXPECT_STUDY_OK(r);
  EXPECT_EQ(r.shown["mail"], "6");
  EXPECT_EQ(r.shown["mail2"], "11");
  EXPECT_EQ(r.shown["bord"], "4 2 1 3");
  EXPECT_EQ(r.shown["tout1d"], "1 2 3 4 5");
  EXPECT_EQ(r.shown["rien"], "0");
  EXPECT_EQ(r.shown["sans_bas"], "2 1 3");
  EXPECT_EQ(r.shown["deux"], "1 6");
  EXPECT_EQ(r.shown["grno"], "11");
  EXPECT_EQ(r.shown["no_surface"], "8");
  EXPECT_EQ(r.shown["after"], "9");
  EXPECT_EQ(r.shown["sommets"], "1 4 3 2");
}

TEST_F(MeshCommands, DefiGroupUnknownGroupSuggests) {
  StudyRun r = run(R"(
MAIL = LIRE_MAILLAGE{FORMAT='ASTER'}
DEFI_GROUP{reuse=MAIL, MAILLAGE=MAIL, CREA_GROUP_NO={NOM='B', GROUP_MA='BASS'}}
)");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("<F> <DEFI_GROUP> etude.lua:3: CREA_GROUP_NO:"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("'BASS' not found"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("did you mean 'BAS'"), std::string::npos) << r.err;
}

TEST_F(MeshCommands, DefiGroupExistingGroupIsAnError) {
  StudyRun r = run(R"(
MAIL = LIRE_MAILLAGE{FORMAT='ASTER'}
DEFI_GROUP{reuse=MAIL, MAILLAGE=MAIL, CREA_GROUP_MA={NOM='BAS', GROUP_MA='HAUT'}}
)");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("<F> <DEFI_GROUP> etude.lua:3: CREA_GROUP_MA: NOM='BAS'"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("already exists"), std::string::npos) << r.err;
}

TEST_F(MeshCommands, MacrAdapMailFourTimesGivesTheN16Grid) {
  StudyRun r = run(R"(
MAIL = LIRE_MAILLAGE{FORMAT='ASTER'}
MACR_ADAP_MAIL{ADAPTATION='RAFFINEMENT_UNIFORME', GROUP_MA={'SURFACE', 'BAS', 'HAUT', 'GAUCHE', 'DROITE'},
               MAILLAGE_N=MAIL, MAILLAGE_NP1=CO('MA1')}
MA2 = MACR_ADAP_MAIL{ADAPTATION='RAFFINEMENT_UNIFORME', MAILLAGE_N=MA1, MAILLAGE_NP1=CO('MA2')}
show('ma1', MA1:getNumberOfNodes())
MACR_ADAP_MAIL{ADAPTATION='RAFFINEMENT_UNIFORME', GROUP_MA='SURFACE', MAILLAGE_N=MA2, MAILLAGE_NP1=CO('MA3')}
MACR_ADAP_MAIL{ADAPTATION='RAFFINEMENT_UNIFORME', GROUP_MA='SURFACE', MAILLAGE_N=MA3, MAILLAGE_NP1=CO('MA4')}
show('nodes', MA4:getNumberOfNodes())
show('cells', MA4:getNumberOfCells())
show('surface', #MA4:getCells('SURFACE'))
show('bas', #MA4:getCells('BAS'))
show('basNodes', #MA4:getNodes('BAS'))
show('maitre', MA4:getNodes('MAITRE'))
show('mail', MAIL:getNumberOfNodes())
)");
  EXPECT_STUDY_OK(r);
  EXPECT_EQ(r.shown["ma1"], "24");  // 9 vertices + 12 middles + 3 of MAITRE
  EXPECT_EQ(r.shown["nodes"], "836");
  EXPECT_EQ(r.shown["cells"], "321");
  EXPECT_EQ(r.shown["surface"], "256");
  EXPECT_EQ(r.shown["bas"], "16");
  EXPECT_EQ(r.shown["basNodes"], "33");
  EXPECT_EQ(r.shown["maitre"], "6 5 11");  // not refined: no 2D cell on it
  EXPECT_EQ(r.shown["mail"], "11");        // the source mesh is unchanged
}

TEST_F(MeshCommands, MacrAdapMailOtherAdaptationsAreNotAvailable) {
  StudyRun r = run(R"(
MAIL = LIRE_MAILLAGE{FORMAT='ASTER'}
MACR_ADAP_MAIL{ADAPTATION='DERAFFINEMENT_UNIFORME', MAILLAGE_N=MAIL, MAILLAGE_NP1=CO('MA1')}
)");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("<F> <MACR_ADAP_MAIL> etude.lua:3: ADAPTATION='DERAFFINEMENT_UNIFORME'"), std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("only ADAPTATION='RAFFINEMENT_UNIFORME'"), std::string::npos) << r.err;
}

TEST_F(MeshCommands, ImprResuMedReadBack) {
  StudyRun r = run("DEFI_FICHIER{ACTION='ASSOCIER', UNITE=80, FICHIER='" + path("etude/fine.med") + R"('}
MAIL = LIRE_MAILLAGE{FORMAT='ASTER'}
MA1 = MAIL
for i = 1, 4 do
  MA1 = MACR_ADAP_MAIL{ADAPTATION='RAFFINEMENT_UNIFORME', MAILLAGE_N=MA1, MAILLAGE_NP1=CO('FIN' .. i)}
end
IMPR_RESU{FORMAT='MED', UNITE=80, RESU={MAILLAGE=MA1}}
MA2 = LIRE_MAILLAGE{FORMAT='MED', UNITE=80}
show('nodes', MA2:getNumberOfNodes())
show('cells', MA2:getNumberOfCells())
show('grma', MA2:getGroupsOfCells())
show('bas', #MA2:getCells('BAS'))
show('surface', #MA2:getCells('SURFACE'))
-- Unbound unit: <output>/<study>.med
IMPR_RESU{FORMAT='MED', UNITE=81, RESU={MAILLAGE=MAIL}}
)");
  EXPECT_STUDY_OK(r);
  EXPECT_EQ(r.shown["nodes"], "836");
  EXPECT_EQ(r.shown["cells"], "321");
  EXPECT_EQ(r.shown["bas"], "16");
  EXPECT_EQ(r.shown["surface"], "256");
  for (const char* g : {"GAUCHE", "HAUT", "DROITE", "BAS", "MAITRE", "SURFACE"})
    EXPECT_NE((" " + r.shown["grma"] + " ").find(std::string(" ") + g + " "), std::string::npos) << r.shown["grma"];
  EXPECT_TRUE(fs::exists(dir_ / "etude" / "fine.med"));
  EXPECT_TRUE(fs::exists(dir_ / "etude" / "etude.med"));
  // Nothing half-written left behind.
  for (const auto& e : fs::directory_iterator(dir_))
    EXPECT_EQ(e.path().filename().string().find(".partial-"), std::string::npos) << e.path();
}

TEST_F(MeshCommands, ImprResuGmshAndVtkOfAMesh) {
  StudyRun r = run("DEFI_FICHIER{ACTION='ASSOCIER', UNITE=37, FICHIER='" + path("etude/mail.msh") + R"('}
MAIL = LIRE_MAILLAGE{FORMAT='ASTER'}
MA1 = MACR_ADAP_MAIL{ADAPTATION='RAFFINEMENT_UNIFORME', MAILLAGE_N=MAIL, MAILLAGE_NP1=CO('MA1')}
IMPR_RESU{FORMAT='GMSH', UNITE=37, RESU={MAILLAGE=MA1}}
MA2 = LIRE_MAILLAGE{FORMAT='GMSH', UNITE=37}
show('nodes', MA2:getNumberOfNodes())
show('cells', MA2:getNumberOfCells())
show('bas', #MA2:getCells('BAS'))
IMPR_RESU{FORMAT='VTK', RESU={MAILLAGE=MA1}}
)");
  EXPECT_STUDY_OK(r);
  // One refinement: 3 x 3 vertices + 12 middles + 3 of MAITRE; 4 QUAD8 + 4 x 2 SEG3 + MAITRE.
  EXPECT_EQ(r.shown["nodes"], "24");
  EXPECT_EQ(r.shown["cells"], "13");
  EXPECT_EQ(r.shown["bas"], "2");
  EXPECT_TRUE(fs::exists(dir_ / "etude" / "etude.vtu"));
}

TEST_F(MeshCommands, ImprResuOfAResultInEveryFormat) {
  // The unit square, E = 1, NU = 0, fixed in X on GAUCHE and in Y on BAS, pulled
  // by FX = 1 per unit length on DROITE: DX = x, DY = 0, SIXX = 1 exactly.
  StudyRun r = run("DEFI_FICHIER{ACTION='ASSOCIER', UNITE=8, FICHIER='" + path("etude/depl.txt") + R"('}
MAIL = LIRE_MAILLAGE{FORMAT='ASTER'}
MODE = AFFE_MODELE{MAILLAGE=MAIL, AFFE={GROUP_MA='SURFACE', PHENOMENE='MECANIQUE', MODELISATION='D_PLAN'}}
MAT = DEFI_MATERIAU{ELAS={E=1.0, NU=0.0}}
CHMAT = AFFE_MATERIAU{MAILLAGE=MAIL, AFFE={TOUT='OUI', MATER=MAT}}
CHAR = AFFE_CHAR_MECA{MODELE=MODE, DDL_IMPO={{GROUP_MA='GAUCHE', DX=0.0}, {GROUP_MA='BAS', DY=0.0}},
                      FORCE_CONTOUR={GROUP_MA='DROITE', FX=1.0}}
L = DEFI_LIST_REEL{DEBUT=0.0, INTERVALLE={JUSQU_A=1.0, NOMBRE=2}}
RESU = STAT_NON_LINE{MODELE=MODE, CHAM_MATER=CHMAT, EXCIT={CHARGE=CHAR}, INCREMENT={LIST_INST=L}}
IMPR_RESU{RESU={RESULTAT=RESU, NOM_CHAM='DEPL', INST=1.0, GROUP_MA='BAS', NOM_CMP='DX', VALE_MAX='OUI'}}
IMPR_RESU{RESU={RESULTAT=RESU, NOM_CHAM='SIEF_ELGA', NUME_ORDRE=2}}
IMPR_RESU{FORMAT='MED', RESU={RESULTAT=RESU}}
IMPR_RESU{FORMAT='GMSH', RESU={RESULTAT=RESU, NOM_CHAM='DEPL'}}
IMPR_RESU{FORMAT='VTK', RESU={RESULTAT=RESU, NOM_CHAM='DEPL', TOUT_ORDRE='OUI'}}
)");
  EXPECT_STUDY_OK(r);
  std::ifstream in(dir_ / "etude" / "depl.txt");
  std::map<std::string, std::vector<double>> dx;  // node or cell -> values of its rows
  bool depl = false;
  for (std::string line; std::getline(in, line);) {
    std::istringstream words(line);
    std::string first;
    words >> first;
    if (first == "CHAMP") depl = line.find(" DEPL ") != std::string::npos;
    if (first.empty() || !(first[0] == 'N' || first[0] == 'M') || first == "NOEUD" || first == "MAILLE") continue;
    std::vector<double> v;
    for (double x; words >> x;) v.push_back(x);
    if (!v.empty()) dx[(depl ? "D:" : "S:") + first] = v;
  }
  // BAS after the one DX column: N4 (x = 1), N1 (x = 0), N10 (x = 0.5).
  ASSERT_EQ(dx.count("D:N4"), 1u);
  EXPECT_EQ(dx["D:N4"].size(), 1u);
  EXPECT_NEAR(dx["D:N4"][0], 1.0, 1e-12);
  EXPECT_NEAR(dx["D:N1"][0], 0.0, 1e-12);
  EXPECT_NEAR(dx["D:N10"][0], 0.5, 1e-12);
  EXPECT_EQ(dx.count("D:N3"), 0u);  // not on BAS
  // SIEF_ELGA of M6 at its last Gauss point: point number, SIXX, SIYY, SIZZ, SIXY.
  ASSERT_EQ(dx["S:M6"].size(), 5u);
  EXPECT_NEAR(dx["S:M6"][1], 1.0, 1e-9);
  // Every instant (0, 0.5, 1) in the VTK collection.
  std::ifstream pvd(dir_ / "etude" / "etude.pvd");
  std::stringstream text;
  text << pvd.rdbuf();
  for (const char* vtu : {"etude_0.vtu", "etude_1.vtu", "etude_2.vtu"}) {
    EXPECT_NE(text.str().find(vtu), std::string::npos) << text.str();
    EXPECT_TRUE(fs::exists(dir_ / "etude" / vtu)) << vtu;
  }
  EXPECT_TRUE(fs::exists(dir_ / "etude" / "etude.med"));
  EXPECT_TRUE(fs::exists(dir_ / "etude" / "etude.msh"));
  for (const auto& e : fs::directory_iterator(dir_ / "etude"))
    EXPECT_EQ(e.path().filename().string().find(".partial-"), std::string::npos) << e.path();
}

}  // namespace
