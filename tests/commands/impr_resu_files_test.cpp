// Where IMPR_RESU, IMPR_TABLE and IMPR_FONCTION write, run through the
// interpreter on meshes/ssnp150b.mail (one QUAD8 on the unit square): a second
// write to one unit adds to the file (MED, text) or goes to a file of its own
// (GMSH, VTK), as code_aster does per unit, and no file the study read is ever
// written over, even with the output folder set to the study's own folder.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "lang/interpreter.hpp"
#include "mesh/io/aster_format.hpp"
#include "mesh/io/med_format.hpp"
#include "../support/scratch_files.hpp"

using namespace aster;
using namespace aster::lang;
namespace fs = std::filesystem;

using aster::test::readFile;

namespace {

const std::string kMesh = std::string(ASTER_SOURCE_DIR) + "/meshes/ssnp150b.mail";

struct StudyRun {
  int status;
  std::string out, err;
};

fs::path freshDir(const std::string& name) { return test::freshDir("impr_resu_files_test", name); }

StudyRun run(const fs::path& dir, const fs::path& outputDir, const std::string& code) {
  Session session;
  session.studyPath = dir / "etude.lua";
  session.outputDir = outputDir;
  Interpreter interpreter(session);
  testing::internal::CaptureStdout();
  testing::internal::CaptureStderr();
  const int status = interpreter.runString(code, "@etude.lua");
  return {status, testing::internal::GetCapturedStdout(), testing::internal::GetCapturedStderr()};
}

// Two linear elastic results on the square, the second with twice the imposed
// displacement of the first: its DEPL is twice the first's.
std::string twoResults(const std::string& meshUnit) {
  return "MAIL = LIRE_MAILLAGE{FORMAT='ASTER', UNITE=" + meshUnit + R"(}
MODELE = AFFE_MODELE{MAILLAGE=MAIL, AFFE={GROUP_MA='SURFACE', PHENOMENE='MECANIQUE', MODELISATION='D_PLAN'}}
MAT = DEFI_MATERIAU{ELAS={E=1.0, NU=0.3}}
CHMAT = AFFE_MATERIAU{MAILLAGE=MAIL, AFFE={TOUT='OUI', MATER=MAT}}
BLOC = AFFE_CHAR_CINE{MODELE=MODELE, MECA_IMPO={{GROUP_MA='BAS', DX=0.0, DY=0.0}}}
TIRE1 = AFFE_CHAR_CINE{MODELE=MODELE, MECA_IMPO={{GROUP_MA='HAUT', DY=0.01}}}
TIRE2 = AFFE_CHAR_CINE{MODELE=MODELE, MECA_IMPO={{GROUP_MA='HAUT', DY=0.02}}}
LINST = DEFI_LIST_REEL{DEBUT=0.0, INTERVALLE={JUSQU_A=1.0, NOMBRE=1}}
RESU = STAT_NON_LINE{MODELE=MODELE, CHAM_MATER=CHMAT, EXCIT={{CHARGE=BLOC}, {CHARGE=TIRE1}}, INCREMENT={LIST_INST=LINST}}
RESU2 = STAT_NON_LINE{MODELE=MODELE, CHAM_MATER=CHMAT, EXCIT={{CHARGE=BLOC}, {CHARGE=TIRE2}}, INCREMENT={LIST_INST=LINST}}
)";
}

}  // namespace

// code_aster: IMPR_RESU twice on unit 80 puts both results in the one MED file.
TEST(OutputFiles, MedTwiceToOneUnitKeepsBothResults) {
  const fs::path dir = freshDir("med_twice");
  const auto r = run(dir, dir / "out", "DEFI_FICHIER{UNITE=20, FICHIER='" + kMesh + "'}\n" + twoResults("20") + R"(
IMPR_RESU{FORMAT='MED', RESU={RESULTAT=RESU, NOM_CHAM='DEPL'}}
IMPR_RESU{FORMAT='MED', RESU={RESULTAT=RESU2, NOM_CHAM='DEPL'}}
FIN2 = MACR_ADAP_MAIL{ADAPTATION='RAFFINEMENT_UNIFORME', MAILLAGE_N=MAIL, GROUP_MA='SURFACE'}
GEOM2 = CREA_CHAMP{TYPE_CHAM='NOEU_GEOM_R', OPERATION='EXTR', MAILLAGE=FIN2, NOM_CHAM='GEOMETRIE'}
IMPR_RESU{FORMAT='MED', RESU={CHAM_GD=GEOM2}}
)");
  ASSERT_EQ(r.status, 0) << r.err << r.out;
  const fs::path med = dir / "out" / "etude.med";
  // Another mesh that would have the first one's name gets one of its own.
  EXPECT_NE(r.out.find("(added to the file of an earlier IMPR_RESU of this run: mesh MAIL_2, fields GEOM2)"),
            std::string::npos)
      << r.out;
  // The QUAD8 cut in 4 has 21 nodes (5 x 5 less the 4 cell centres), MAITRE's SEG3 its 3.
  EXPECT_EQ(mesh::readMedMesh(med.string(), "MAIL_2").nodeCount(), 24);
  EXPECT_NE(r.out.find("written to " + med.string() + " (added to the file of an earlier IMPR_RESU of this run: mesh "
                       "MAIL (already there), fields RESU2___DEPL)"),
            std::string::npos)
      << r.out;
  // code_aster's names: the result's name padded to 8 characters with '_', then the field's.
  const auto first = mesh::readMedNodalField(med.string(), "RESU____DEPL", 1);
  const auto second = mesh::readMedNodalField(med.string(), "RESU2___DEPL", 1);
  ASSERT_EQ(first.values.size(), second.values.size());
  double largest = 0;
  for (std::size_t i = 0; i < first.values.size(); ++i) {
    EXPECT_NEAR(second.values[i], 2 * first.values[i], 1e-12);
    largest = std::max(largest, std::fabs(first.values[i]));
  }
  EXPECT_NEAR(largest, 0.01, 1e-12);  // the imposed DY at HAUT
  EXPECT_EQ(mesh::readMedMesh(med.string()).nodeCount(), mesh::readAsterMesh(kMesh).nodeCount());
}

// GMSH and VTK files hold one write: the second goes to a file of its own.
TEST(OutputFiles, GmshAndVtkTwiceGoToTwoFiles) {
  const fs::path dir = freshDir("gmsh_twice");
  const auto r = run(dir, dir / "out", "DEFI_FICHIER{UNITE=20, FICHIER='" + kMesh + "'}\n" + twoResults("20") + R"(
IMPR_RESU{FORMAT='GMSH', RESU={RESULTAT=RESU, NOM_CHAM='DEPL'}}
IMPR_RESU{FORMAT='GMSH', RESU={RESULTAT=RESU2, NOM_CHAM='DEPL'}}
IMPR_RESU{FORMAT='VTK', RESU={RESULTAT=RESU, NOM_CHAM='DEPL'}}
IMPR_RESU{FORMAT='VTK', RESU={RESULTAT=RESU2, NOM_CHAM='DEPL'}}
)");
  ASSERT_EQ(r.status, 0) << r.err << r.out;
  const fs::path out = dir / "out";
  for (const char* f : {"etude.msh", "etude-2.msh", "etude.pvd", "etude_0.vtu", "etude_1.vtu", "etude-2.pvd",
                        "etude-2_0.vtu", "etude-2_1.vtu"})
    EXPECT_TRUE(fs::exists(out / f)) << f;
  EXPECT_NE(r.out.find("written to " + (out / "etude-2.msh").string() + " (etude.msh holds an earlier IMPR_RESU of "
                       "this run)"),
            std::string::npos)
      << r.out;
  EXPECT_NE(readFile(out / "etude.msh"), readFile(out / "etude-2.msh"));
}

// The issue's case: --output-dir set to the study's folder, the mesh read by
// default from <study>.med there, IMPR_RESU{FORMAT='MED'} without a unit.
TEST(OutputFiles, InputMeshInTheOutputFolderIsNeverWrittenOver) {
  const fs::path dir = freshDir("input_in_output_dir");
  mesh::writeMedMesh(mesh::readAsterMesh(kMesh), (dir / "etude.med").string());
  const std::string before = readFile(dir / "etude.med");
  const auto r = run(dir, dir, R"(
MAIL = LIRE_MAILLAGE{FORMAT='MED'}
IMPR_RESU{FORMAT='MED', RESU={MAILLAGE=MAIL}}
IMPR_RESU{FORMAT='MED', RESU={MAILLAGE=MAIL}}
)");
  ASSERT_EQ(r.status, 0) << r.err << r.out;
  EXPECT_EQ(readFile(dir / "etude.med"), before);
  EXPECT_NE(r.out.find("written to " + (dir / "etude-2.med").string() +
                       " (etude.med is an input of the study, never written over)"),
            std::string::npos)
      << r.out;
  EXPECT_EQ(mesh::readMedMesh((dir / "etude-2.med").string()).cellCount(), mesh::readAsterMesh(kMesh).cellCount());
}

// A unit bound to a file the study read: a clear <F>, the file untouched.
TEST(OutputFiles, UnitBoundToAnInputIsRefused) {
  const fs::path dir = freshDir("bound_to_input");
  fs::copy_file(kMesh, dir / "carre.mail");
  const std::string before = readFile(dir / "carre.mail");
  for (const std::string& command : {std::string("IMPR_RESU{FORMAT='RESULTAT', UNITE=20, RESU={MAILLAGE=MAIL}}"),
                                     std::string("IMPR_TABLE{TABLE=T, UNITE=20}"),
                                     std::string("IMPR_FONCTION{UNITE=20, COURBE={ABSCISSE={0, 1}, ORDONNEE={0, 1}}}")}) {
    const auto r = run(dir, dir / "out", R"(
DEFI_FICHIER{UNITE=20, FICHIER='carre.mail'}
MAIL = LIRE_MAILLAGE{FORMAT='ASTER', UNITE=20}
T = CREA_TABLE{LISTE={{PARA='N', LISTE_I={1, 2}}}}
)" + command + "\n");
    EXPECT_EQ(r.status, 2) << command << r.out;
    EXPECT_NE(r.err.find("etude.lua:5: UNITE=20"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("UNITE=20 is bound to " + (dir / "carre.mail").string() +
                         ", an input of the study (read by LIRE_MAILLAGE at etude.lua:3)"),
              std::string::npos)
        << r.err;
    EXPECT_EQ(readFile(dir / "carre.mail"), before) << command;
  }
}

// A unit bound with DEFI_FICHIER{ACCES='OLD'} is for reading.
TEST(OutputFiles, UnitBoundForReadingIsRefused) {
  const fs::path dir = freshDir("bound_old");
  std::ofstream(dir / "donnees.txt") << "data\n";
  const auto r = run(dir, dir / "out", R"(
DEFI_FICHIER{UNITE=30, FICHIER='donnees.txt', ACCES='OLD'}
IMPR_FONCTION{UNITE=30, COURBE={ABSCISSE={0, 1}, ORDONNEE={0, 1}}}
)");
  EXPECT_EQ(r.status, 2) << r.out;
  EXPECT_NE(r.err.find("an input of the study (bound for reading by DEFI_FICHIER at etude.lua:2)"), std::string::npos)
      << r.err;
  EXPECT_EQ(readFile(dir / "donnees.txt"), "data\n");
}

// Two IMPR_TABLE of one table: the second follows the first in <table>.tab.
TEST(OutputFiles, TableTwiceKeepsBoth) {
  const fs::path dir = freshDir("table_twice");
  const auto r = run(dir, dir / "out", R"(
T = CREA_TABLE{LISTE={{PARA='N', LISTE_I={1, 2}}, {PARA='H', LISTE_R={0.5, 0.25}}}}
IMPR_TABLE{TABLE=T, FORMAT='CSV', NOM_PARA='N'}
IMPR_TABLE{TABLE=T, FORMAT='CSV', NOM_PARA='H', FORMAT_R='F5.2'}
)");
  ASSERT_EQ(r.status, 0) << r.err << r.out;
  EXPECT_EQ(readFile(dir / "out" / "T.csv"), "N\n1\n2\nH\n0.50\n0.25\n");
}

// Two plots to one unit: each gets its image, script and data (gnuplot draws
// both at the end of the run; before, the second replaced the first's data).
TEST(OutputFiles, TwoPlotsToOneUnitKeepBoth) {
  const fs::path dir = freshDir("plots_one_unit");
  const auto r = run(dir, dir / "out", R"(
DEFI_FICHIER{UNITE=29, FICHIER='out/courbe.svg'}
IMPR_FONCTION{FORMAT='SVG', UNITE=29, COURBE={ABSCISSE={0, 1}, ORDONNEE={0, 1}}}
IMPR_FONCTION{FORMAT='SVG', UNITE=29, COURBE={ABSCISSE={0, 1}, ORDONNEE={0, 2}}}
)");
  ASSERT_EQ(r.status, 0) << r.err << r.out;
  EXPECT_EQ(readFile(dir / "out" / "courbe_1.dat"), "0 0\n1 1\n");
  EXPECT_EQ(readFile(dir / "out" / "courbe-2_1.dat"), "0 0\n1 2\n");
  EXPECT_GT(fs::file_size(dir / "out" / "courbe.svg"), 100u);
  EXPECT_GT(fs::file_size(dir / "out" / "courbe-2.svg"), 100u);
}

// A uniform plane strain state (GAUCHE: DX = 0, BAS: DY = 0, HAUT: DY = 0.01 on
// the 2 x 1 rectangle, E = 100, NU = 0.3): SIYY = E eps / (1 - NU^2), SIZZ = NU
// SIYY, SIXX = SIXY = 0 at every Gauss point. IMPR_RESU in MED writes it under
// code_aster's name RESU____SIEF_ELGA, read back with mdump.
TEST(OutputFiles, MedWritesTheStressAtGaussPointsUnderCodeAstersName) {
  if (std::system("command -v mdump > /dev/null") != 0) GTEST_SKIP() << "mdump (libmed-tools) is not installed";
  const fs::path dir = freshDir("med_sief_elga");
  const std::string mesh = std::string(ASTER_SOURCE_DIR) + "/tests/bad_input/base.mail";
  const auto r = run(dir, dir / "out", "DEFI_FICHIER{UNITE=20, FICHIER='" + mesh + R"('}
MAIL = LIRE_MAILLAGE{FORMAT='ASTER', UNITE=20}
MODELE = AFFE_MODELE{MAILLAGE=MAIL, AFFE={TOUT='OUI', PHENOMENE='MECANIQUE', MODELISATION='D_PLAN'}}
MAT = DEFI_MATERIAU{ELAS={E=100.0, NU=0.3}}
CHMAT = AFFE_MATERIAU{MAILLAGE=MAIL, AFFE={TOUT='OUI', MATER=MAT}}
CHARGE = AFFE_CHAR_CINE{MODELE=MODELE, MECA_IMPO={{GROUP_MA='GAUCHE', DX=0.0}, {GROUP_MA='BAS', DY=0.0},
                                                  {GROUP_MA='HAUT', DY=0.01}}}
RESU = MECA_STATIQUE{MODELE=MODELE, CHAM_MATER=CHMAT, EXCIT={CHARGE=CHARGE}}
IMPR_RESU{FORMAT='MED', RESU={RESULTAT=RESU, NOM_CHAM={'DEPL', 'SIEF_ELGA'}}}
SIG = CREA_CHAMP{TYPE_CHAM='ELGA_SIEF_R', OPERATION='EXTR', RESULTAT=RESU, NOM_CHAM='SIEF_ELGA'}
IMPR_RESU{FORMAT='MED', RESU={CHAM_GD=SIG, NOM_CMP='SIYY'}}
IMPR_RESU{FORMAT='GMSH', RESU={RESULTAT=RESU, NOM_CHAM='SIEF_ELGA', NOM_CMP='SIYY'}}
)");
  ASSERT_EQ(r.status, 0) << r.err << r.out;
  const fs::path med = dir / "out" / "etude.med";
  FILE* p = popen(("printf '1\\n1\\n1\\n' | mdump " + med.string() + " 2>&1").c_str(), "r");
  ASSERT_NE(p, nullptr);
  std::string dump;
  char buffer[4096];
  for (std::size_t n; (n = fread(buffer, 1, sizeof buffer, p)) > 0;) dump.append(buffer, n);
  pclose(p);
  EXPECT_NE(dump.find("CHAMP |RESU____DEPL|"), std::string::npos) << dump;
  const auto at = dump.find("CHAMP |RESU____SIEF_ELGA|");
  ASSERT_NE(at, std::string::npos) << dump;
  EXPECT_NE(dump.find("|QU4_____RIGI| de dimension 2 avec 4 pts de GAUSS"), std::string::npos) << dump;
  const auto values = dump.find("- Valeurs :", at);
  ASSERT_NE(values, std::string::npos);
  std::string line = dump.substr(values + 12, dump.find('\n', values + 13) - values - 12);
  for (char& c : line)
    if (c == '|') c = ' ';
  std::istringstream in(line);
  std::vector<double> v;
  for (double x; in >> x;) v.push_back(x);
  ASSERT_EQ(v.size(), 2u * 4 * 4);  // 2 QUAD4, 4 points, SIXX SIYY SIZZ SIXY
  const double siyy = 100 * 0.01 / (1 - 0.3 * 0.3);
  for (std::size_t k = 0; k < v.size(); k += 4) {
    EXPECT_NEAR(v[k], 0, 1e-6);
    EXPECT_NEAR(v[k + 1], siyy, 1e-6);
    EXPECT_NEAR(v[k + 2], 0.3 * siyy, 1e-6);
    EXPECT_NEAR(v[k + 3], 0, 1e-6);
  }
  // The cham_elem SIG, its component SIYY only, under its concept's name.
  const auto sig = dump.find("CHAMP |SIG|");
  ASSERT_NE(sig, std::string::npos) << dump;
  EXPECT_NE(dump.find("Nom des composantes : |SIYY", sig), std::string::npos);
  // GMSH: the mean over each cell's Gauss points, one scalar per cell.
  const std::string msh = readFile(dir / "out" / "etude.msh");
  const std::string header = "$ElementData\n1\n\"SIEF_ELGA_MEAN\"\n1\n0\n3\n0\n1\n2\n";  // 1 component, 2 cells
  const auto view = msh.find(header);
  ASSERT_NE(view, std::string::npos) << msh;
  std::istringstream cells(msh.substr(view + header.size()));
  for (int cell = 1; cell <= 2; ++cell) {
    int tag = 0;
    double mean = 0;
    cells >> tag >> mean;
    EXPECT_EQ(tag, cell);
    EXPECT_NEAR(mean, siyy, 1e-12);
  }
}

// Two results' SIEF_ELGA written to one MED file by two IMPR_RESU: the second
// takes the Gauss point localization the file holds (the same points and
// weights), as code_aster does, rather than a copy of it.
TEST(OutputFiles, MedTwiceKeepsOneLocalizationPerCellType) {
  if (std::system("command -v mdump > /dev/null") != 0) GTEST_SKIP() << "mdump (libmed-tools) is not installed";
  const fs::path dir = freshDir("med_twice_localization");
  const auto r = run(dir, dir / "out", "DEFI_FICHIER{UNITE=20, FICHIER='" + kMesh + "'}\n" + twoResults("20") + R"(
IMPR_RESU{FORMAT='MED', RESU={RESULTAT=RESU, NOM_CHAM='SIEF_ELGA'}}
IMPR_RESU{FORMAT='MED', RESU={RESULTAT=RESU2, NOM_CHAM='SIEF_ELGA'}}
)");
  ASSERT_EQ(r.status, 0) << r.err << r.out;
  FILE* p = popen(("printf '1\\n1\\n1\\n' | mdump " + (dir / "out" / "etude.med").string() + " 2>&1").c_str(), "r");
  ASSERT_NE(p, nullptr);
  std::string dump;
  char buffer[4096];
  for (std::size_t n; (n = fread(buffer, 1, sizeof buffer, p)) > 0;) dump.append(buffer, n);
  pclose(p);
  EXPECT_NE(dump.find("Nombre de localisations stockees : 1\n"), std::string::npos) << dump;
  EXPECT_NE(dump.find("|QU8_____RIGI| de dimension 2 avec 9 pts de GAUSS"), std::string::npos) << dump;
  EXPECT_NE(dump.find("CHAMP |RESU____SIEF_ELGA|"), std::string::npos);
  EXPECT_NE(dump.find("CHAMP |RESU2___SIEF_ELGA|"), std::string::npos);
}
