// STAT_NON_LINE's archive (RESU.pvd + RESU_<k>.vtu, written as instants converge)
// when the disk fills up (a file-size limit: writes fail with EFBIG) and in a
// folder an earlier run used: the .pvd always lists exactly the files on disk,
// each of them whole, and no file of an earlier run mixes with this run's.
#include "commands/result_archive.hpp"
#include "../support/scratch_files.hpp"

#include <gtest/gtest.h>
#include <sys/resource.h>

#include <cerrno>
#include <csignal>
#include <cstring>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>

#include "core/error.hpp"
#include "mesh/io/aster_format.hpp"

using namespace aster;
using namespace aster::lang;
namespace fs = std::filesystem;

using aster::test::readFile;

namespace {

fs::path freshDir(const std::string& name) { return test::freshDir("result_archive_test", name); }

void writeFile(const fs::path& p, const std::string& text) { std::ofstream(p, std::ios::binary) << text; }

ResultInstant instant(const mesh::Mesh& m, int k) {
  ResultInstant i;
  i.index = k;
  i.time = 0.1 * k;
  i.nodal.push_back({"DEPL", {"DX", "DY"}, std::vector<double>(2 * m.nodeCount(), 0.001 * k)});
  return i;
}

// The files RESU.pvd lists; fails the test when the .pvd is not whole.
std::vector<std::string> listed(const fs::path& pvd) {
  const std::string text = readFile(pvd);
  EXPECT_NE(text.find("</VTKFile>"), std::string::npos) << pvd << " is not whole:\n" << text;
  std::vector<std::string> files;
  const std::regex entry("file=\"([^\"]+)\"");
  for (auto it = std::sregex_iterator(text.begin(), text.end(), entry); it != std::sregex_iterator(); ++it)
    files.push_back((*it)[1]);
  return files;
}

// Every listed file is there and whole, in order RESU_0, RESU_1...; no other
// RESU_*.vtu and no temporary folder.
void expectConsistent(const fs::path& dir, std::size_t expected) {
  const auto files = listed(dir / "RESU.pvd");
  ASSERT_EQ(files.size(), expected);
  for (std::size_t k = 0; k < files.size(); ++k) {
    EXPECT_EQ(files[k], "RESU_" + std::to_string(k) + ".vtu");
    const std::string vtu = readFile(dir / files[k]);
    const std::string end = "</UnstructuredGrid>\n</VTKFile>\n";
    ASSERT_GE(vtu.size(), end.size());
    EXPECT_EQ(vtu.substr(vtu.size() - end.size()), end) << files[k] << " is not whole";
  }
  for (const auto& e : fs::directory_iterator(dir)) {
    const std::string name = e.path().filename().string();
    EXPECT_EQ(name.find(".partial-"), std::string::npos) << name;
    if (std::regex_match(name, std::regex("RESU_[0-9]+\\.vtu"))) {
      EXPECT_NE(std::find(files.begin(), files.end(), name), files.end()) << name << " is on disk, not listed";
    }
  }
}

template <typename F>
std::string underFileSizeLimit(rlim_t bytes, F f) {
  std::signal(SIGXFSZ, SIG_IGN);
  rlimit old;
  getrlimit(RLIMIT_FSIZE, &old);
  rlimit limited = old;
  limited.rlim_cur = bytes;
  setrlimit(RLIMIT_FSIZE, &limited);
  std::string what = "no error";
  try {
    f();
  } catch (const Error& e) {
    what = e.what();
  }
  setrlimit(RLIMIT_FSIZE, &old);
  return what;
}

const std::string kMesh = std::string(ASTER_SOURCE_DIR) + "/meshes/ssnp150b.mail";

}  // namespace

// The .pvd grows by an entry per instant and passes the limit first: the
// instant whose .pvd could not be written is not on disk at all.
TEST(ResultArchive, CollectionPastTheLimitKeepsTheInstantsBefore) {
  const mesh::Mesh m = mesh::readAsterMesh(kMesh);
  const fs::path dir = freshDir("pvd_fails");
  std::uintmax_t vtuSize;
  {
    ResultArchive probe(m, dir / "PROBE.pvd");
    probe.add(instant(m, 0));
    vtuSize = fs::file_size(dir / "PROBE_0.vtu");
  }
  ResultArchive archive(m, dir / "RESU.pvd");
  int added = 0;
  const std::string what = underFileSizeLimit(vtuSize + 600, [&] {
    for (int k = 0; k < 100; ++k) {
      archive.add(instant(m, k));
      ++added;
    }
  });
  ASSERT_NE(what, "no error");
  EXPECT_NE(what.find("cannot write " + (dir / "RESU.pvd").string() + ": " + std::strerror(EFBIG)),
            std::string::npos)
      << what;
  EXPECT_GT(added, 2);
  expectConsistent(dir, static_cast<std::size_t>(added));
}

// An instant's .vtu past the limit: nothing of it reaches the folder.
TEST(ResultArchive, InstantPastTheLimitLeavesNoTruncatedFile) {
  const mesh::Mesh m = mesh::readAsterMesh(kMesh);
  const fs::path dir = freshDir("vtu_fails");
  ResultArchive archive(m, dir / "RESU.pvd");
  archive.add(instant(m, 0));
  archive.add(instant(m, 1));
  const std::string what = underFileSizeLimit(600, [&] { archive.add(instant(m, 2)); });
  EXPECT_NE(what.find("cannot write " + (dir / "RESU_2.vtu").string() + ": " + std::strerror(EFBIG)),
            std::string::npos)
      << what;
  expectConsistent(dir, 2);
}

// A folder an earlier run used: its RESU files go (ParaView would group them with
// this run's), the other files stay.
TEST(ResultArchive, EarlierRunsFilesOfThatNameAreRemoved) {
  const mesh::Mesh m = mesh::readAsterMesh(kMesh);
  const fs::path dir = freshDir("stale");
  const std::vector<std::string> stale{"RESU.pvd", "RESU_0.vtu", "RESU_1.vtu", "RESU_2.vtu", "RESU_3.vtu",
                                       "RESU-2.pvd", "RESU-2_0.vtu", "RESU-2_7.vtu"};
  const std::vector<std::string> others{"RESU_notes.txt", "OTHER_1.vtu", "RESUX_1.vtu", "RESU_1.vtu.bak",
                                        "OTHER.pvd"};
  for (const auto& f : stale) writeFile(dir / f, "earlier run");
  for (const auto& f : others) writeFile(dir / f, "not ours");
  ResultArchive archive(m, dir / "RESU.pvd");
  archive.add(instant(m, 0));
  expectConsistent(dir, 1);
  std::set<std::string> present;
  for (const auto& e : fs::directory_iterator(dir)) present.insert(e.path().filename().string());
  std::set<std::string> expected(others.begin(), others.end());
  expected.insert("RESU.pvd");
  expected.insert("RESU_0.vtu");
  EXPECT_EQ(present, expected);
  for (const auto& f : others) EXPECT_EQ(readFile(dir / f), "not ours");
}

// Inputs of the study and files this run wrote are never taken for an earlier run's.
TEST(ResultArchive, KeepsInputsAndThisRunsFiles) {
  const mesh::Mesh m = mesh::readAsterMesh(kMesh);
  const fs::path dir = freshDir("inputs");
  writeFile(dir / "RESU_5.vtu", "read by the study");
  writeFile(dir / "RESU.pvd", "written by IMPR_RESU in this run");
  RunFiles files;
  files.addInput(dir / "RESU_5.vtu", "LIRE_MAILLAGE");
  files.addWritten(dir / "RESU.pvd");
  ResultArchive archive(m, dir / "RESU.pvd", &files);
  EXPECT_EQ(archive.path(), dir / "RESU-2.pvd");  // the next free name
  archive.add(instant(m, 0));
  EXPECT_EQ(archive.stored(), 1u);
  EXPECT_EQ(readFile(dir / "RESU_5.vtu"), "read by the study");
  EXPECT_EQ(readFile(dir / "RESU.pvd"), "written by IMPR_RESU in this run");
  EXPECT_TRUE(fs::exists(dir / "RESU-2_0.vtu"));
}
