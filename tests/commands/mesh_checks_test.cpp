// LIRE_MAILLAGE refuses coordinates that are not finite numbers whatever the
// format, naming the node: ASTER (text "nan"), MED and binary MSH 4.1 (written
// here with a NaN through the writers, which copy the coordinates as they are).
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <limits>
#include <string>

#include "lang/interpreter.hpp"
#include "mesh/io/gmsh_format.hpp"
#if __has_include("mesh/io/med_format.hpp")
#include "mesh/io/med_format.hpp"
#define ASTER_HAS_MED 1
#endif

using namespace aster;
namespace fs = std::filesystem;

namespace {

struct StudyRun {
  int status = 0;
  std::string err;
};

class MeshChecks : public testing::Test {
 protected:
  void SetUp() override {
    const auto* info = testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() / ("aster_mesh_checks_" + std::to_string(::getpid()) + "_" + info->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override {
    if (!HasFailure()) fs::remove_all(dir_);
  }

  // The unit square of two TRIA3, node N3 = (1, NaN).
  static mesh::Mesh squareWithNaN() {
    mesh::Mesh m;
    m.setSpaceDimension(2);
    for (auto p : {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 0, 0),
                   Eigen::Vector3d(1, std::numeric_limits<double>::quiet_NaN(), 0), Eigen::Vector3d(0, 1, 0)})
      m.addNode(p);
    m.addCell(mesh::CellType::TRIA3, {0, 1, 2});
    m.addCell(mesh::CellType::TRIA3, {0, 2, 3});
    m.addCellGroup("SURFACE", {0, 1});
    return m;
  }

  StudyRun read(const std::string& format, const fs::path& file) {
    lang::Session session;
    session.studyPath = dir_ / "etude.lua";
    session.outputDir = dir_ / "etude";
    session.units[20] = file;
    lang::Interpreter interpreter(session);
    testing::internal::CaptureStdout();
    testing::internal::CaptureStderr();
    StudyRun r;
    r.status = interpreter.runString("MA = LIRE_MAILLAGE{FORMAT = '" + format + "', UNITE = 20}\n", "@etude.lua");
    testing::internal::GetCapturedStdout();
    r.err = testing::internal::GetCapturedStderr();
    return r;
  }

  fs::path dir_;
};

}  // namespace

TEST_F(MeshChecks, NanInAnAsterMeshIsNamed) {
  const fs::path file = dir_ / "nan.mail";
  std::ofstream(file) << " COOR_2D\n N1 0 0\n N2 1 0\n N3 1 NaN\n FINSF\n TRIA3\n M1 N1 N2 N3\n FINSF\n FIN\n";
  const StudyRun r = read("ASTER", file);
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, "<F> <LIRE_MAILLAGE> etude.lua:1: " + file.string() +
                       ": node 'N3' has a coordinate that is not a finite number: (1, nan, 0)\n");
}

#ifdef ASTER_HAS_MED
TEST_F(MeshChecks, NanInAMedMeshIsNamed) {
  const fs::path file = dir_ / "nan.med";
  mesh::writeMedMesh(squareWithNaN(), file.string());
  const StudyRun r = read("MED", file);
  EXPECT_EQ(r.status, 2);
  // The MED reader itself names the node (before the check common to every format).
  EXPECT_NE(r.err.find(file.string() + ": node N3 of mesh 'MAIL' has a coordinate that is not a finite number"),
            std::string::npos)
      << r.err;
}
#endif

TEST_F(MeshChecks, NanInABinaryMshMeshIsNamed) {
  const fs::path file = dir_ / "nan.msh";
  mesh::GmshWriteOptions binary;
  binary.binary = true;
  mesh::writeGmshMesh(squareWithNaN(), file.string(), binary);
  const StudyRun r = read("GMSH", file);
  EXPECT_EQ(r.status, 2);
  // The binary MSH check names the node and its byte before gmsh reads the file.
  EXPECT_NE(r.err.find(file.string() + ": byte "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("node 3 has a coordinate that is not a finite number"), std::string::npos) << r.err;
}
