// Damaged MED files: every read ends with the mesh or an aster::Error that names
// the file, never with a crash of the program. HDF5 and the MED library crash on
// some damaged files, so the reader runs them in a child process
// (mesh/io/med_format.cpp); this test damages a small MED file written by
// aster-lite (64 zero bytes every 64 bytes, one byte inverted every 97 bytes,
// truncations) and reads each version.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <new>
#include <string>

#include "core/error.hpp"
#include "mesh/io/med_format.hpp"

using namespace aster::mesh;

namespace {

const std::string kTmp = std::string(ASTER_BINARY_DIR) + "/med_corruption/";

// Two QUAD4 and their edges, with cell and node groups and names: every kind
// of MED object the reader reads (coordinates, connectivities, names, families).
Mesh smallMesh() {
  Mesh m;
  m.setSpaceDimension(2);
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 3; ++i) m.addNode({1.0 * i, 1.0 * j, 0.0});
  m.addCell(CellType::QUAD4, std::vector<int>{0, 1, 4, 3});
  m.addCell(CellType::QUAD4, std::vector<int>{1, 2, 5, 4});
  m.addCell(CellType::SEG2, std::vector<int>{0, 1});
  m.addCell(CellType::SEG2, std::vector<int>{1, 2});
  m.addCellGroup("SURFACE", {0, 1});
  m.addCellGroup("BAS", {2, 3});
  m.addNodeGroup("COIN", {0});
  return m;
}

std::string readAll(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

struct Outcome {
  int read = 0, refused = 0;
};

// Reads the damaged file; a crash would end the test program here.
void readDamaged(const std::string& bytes, const std::string& what, Outcome& outcome) {
  const std::string path = kTmp + "damaged.med";
  std::ofstream(path, std::ios::binary | std::ios::trunc) << bytes;
  try {
    const Mesh m = readMedMesh(path);
    ++outcome.read;
    for (int c = 0; c < m.cellCount(); ++c)
      for (int n : m.cellNodes(c)) ASSERT_TRUE(n >= 0 && n < m.nodeCount()) << what;
  } catch (const aster::Error& e) {
    ++outcome.refused;
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << what << ": " << e.what();
  } catch (const std::exception& e) {
    ADD_FAILURE() << what << ": not an aster::Error: " << e.what();
  }
}

}  // namespace

TEST(MedCorruption, DamagedFilesAreReadOrRefusedWithTheirName) {
  std::filesystem::create_directories(kTmp);
  const std::string good = kTmp + "good.med";
  writeMedMesh(smallMesh(), good);
  ASSERT_EQ(readMedMesh(good).cellCount(), 4);
  const std::string bytes = readAll(good);
  ASSERT_GT(bytes.size(), 4000u);

  Outcome zeroed, inverted, truncated;
  for (std::size_t at = 0; at < bytes.size(); at += 64) {
    std::string b = bytes;
    for (std::size_t k = at; k < std::min(at + 64, b.size()); ++k) b[k] = 0;
    readDamaged(b, "64 zero bytes at " + std::to_string(at), zeroed);
  }
  for (std::size_t at = 3; at < bytes.size(); at += 97) {
    std::string b = bytes;
    b[at] = static_cast<char>(~b[at]);
    readDamaged(b, "byte " + std::to_string(at) + " inverted", inverted);
  }
  for (std::size_t size = 0; size < bytes.size(); size += 1024)
    readDamaged(bytes.substr(0, size), "truncated to " + std::to_string(size) + " bytes", truncated);
  // The damage was seen (the versions read lost bytes that the reader does not use).
  EXPECT_GT(zeroed.refused, 0);
  EXPECT_GT(inverted.refused, 0);
  EXPECT_EQ(truncated.read, 0);
}

// The child process itself: what it returns, throws, or how it dies.
TEST(MedCorruption, TheReadingProcessReportsHowItEnded) {
  const std::string path = "damaged.med";
  const std::string big(20'000'000, 'x');  // more than a pipe holds at once
  EXPECT_EQ(detail::readInChild(path, [&] { return big; }), big);
  auto errorOf = [&](const std::function<std::string()>& read) {
    try {
      detail::readInChild(path, read);
    } catch (const aster::Error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  const std::string expected = "expected a MED file written by Salome, code_aster or aster-lite";
  EXPECT_EQ(errorOf([&]() -> std::string { throw aster::Error(path + ": no mesh"); }), path + ": no mesh");
  EXPECT_EQ(errorOf([]() -> std::string { std::abort(); }),
            path + ": the MED library (HDF5) crashed reading the file (signal SIGABRT): a damaged MED file (" + expected +
                ")");
  EXPECT_EQ(errorOf([]() -> std::string { ::_exit(3); }),
            path + ": the process reading the MED file ended without a result (exit status 3): a damaged MED file? (" +
                expected + ")");
  EXPECT_EQ(errorOf([]() -> std::string { throw std::bad_alloc(); }),
            path + ": the MED file announces more data than memory can hold (a damaged file; " + expected + ")");
}
