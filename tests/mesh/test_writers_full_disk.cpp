// Mesh and result writers on a full disk (/dev/full: every write fails with
// ENOSPC) and past a file-size limit (RLIMIT_FSIZE: EFBIG): each throws
// aster::Error naming the file and the system's reason, instead of returning
// as if the file were whole (the close is checked, not only the writes).
#include <gtest/gtest.h>
#include <sys/resource.h>

#include <cerrno>
#include <csignal>
#include <cstring>
#include <filesystem>

#include "core/error.hpp"
#include "mesh/io/aster_format.hpp"
#include "mesh/io/med_format.hpp"
#include "mesh/io/msh2_writer.hpp"
#include "mesh/io/vtk_format.hpp"

using namespace aster::mesh;

namespace {

const std::string kMesh = std::string(ASTER_SOURCE_DIR) + "/meshes/ssnp150b.mail";  // one QUAD8

std::vector<FieldInstant> oneInstant(const Mesh& m) {
  NodalField depl{"DEPL", {"DX", "DY"}, std::vector<double>(2 * m.nodeCount(), 0.25)};
  return {FieldInstant{1, 0.5, {depl}}};
}

template <typename F>
std::string errorOf(F f) {
  try {
    f();
  } catch (const aster::Error& e) {
    return e.what();
  }
  return "no error";
}

void expectNamed(const std::string& what, const std::string& path, int error) {
  EXPECT_NE(what.find(path), std::string::npos) << what;
  EXPECT_NE(what.find(std::strerror(error)), std::string::npos) << what;
}

}  // namespace

TEST(FullDisk, VtuWriterReportsNoSpace) {
  const Mesh m = readAsterMesh(kMesh);
  expectNamed(errorOf([&] { writeVtu(m, "/dev/full", oneInstant(m)[0].fields); }), "/dev/full", ENOSPC);
}

TEST(FullDisk, PvdCollectionWriterReportsNoSpace) {
  expectNamed(errorOf([&] { writePvdCollection("/dev/full", {{0.0, "RESU_0.vtu"}, {1.0, "RESU_1.vtu"}}); }),
              "/dev/full", ENOSPC);
}

TEST(FullDisk, Msh2WriterReportsNoSpace) {
  const Mesh m = readAsterMesh(kMesh);
  expectNamed(errorOf([&] { writeMsh2(m, "/dev/full", oneInstant(m)); }), "/dev/full", ENOSPC);
}

TEST(FullDisk, MedWriterReportsTheFileSizeLimit) {
  const Mesh m = readAsterMesh(kMesh);
  const std::string path = std::string(ASTER_BINARY_DIR) + "/full_disk_limit.med";
  std::filesystem::remove(path);
  std::signal(SIGXFSZ, SIG_IGN);
  rlimit old;
  ASSERT_EQ(getrlimit(RLIMIT_FSIZE, &old), 0);
  rlimit limited = old;
  limited.rlim_cur = 4096;  // the file is about 16 kB
  ASSERT_EQ(setrlimit(RLIMIT_FSIZE, &limited), 0);
  const std::string what = errorOf([&] { writeMedResults(m, path, oneInstant(m)); });
  setrlimit(RLIMIT_FSIZE, &old);
  expectNamed(what, path, EFBIG);
}
