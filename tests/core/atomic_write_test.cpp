// The checked, atomic write path every output goes through: a write or close that
// fails (full disk: /dev/full gives ENOSPC; a file-size limit gives EFBIG) is an
// aster::Error naming the file and the system's reason, the file in place stays
// as it was, and no file the study read is ever written over.
#include "core/atomic_write.hpp"
#include "../support/scratch_files.hpp"

#include <gtest/gtest.h>
#include <sys/resource.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstring>
#include <fstream>
#include <sstream>

#include "core/error.hpp"

using namespace aster;
namespace fs = std::filesystem;

using aster::test::readFile;

namespace {

fs::path freshDir(const std::string& name) { return test::freshDir("atomic_write_test", name); }

template <typename F>
std::string errorOf(F f) {
  try {
    f();
  } catch (const Error& e) {
    return e.what();
  }
  return "no error";
}

// Runs f with every file limited to `bytes` (writes past it fail with EFBIG).
template <typename F>
void withFileSizeLimit(rlim_t bytes, F f) {
  std::signal(SIGXFSZ, SIG_IGN);
  rlimit old;
  ASSERT_EQ(getrlimit(RLIMIT_FSIZE, &old), 0);
  rlimit limited = old;
  limited.rlim_cur = bytes;
  ASSERT_EQ(setrlimit(RLIMIT_FSIZE, &limited), 0);
  f();
  setrlimit(RLIMIT_FSIZE, &old);
}

bool hasPartialFolder(const fs::path& dir) {
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().filename().string().find(".partial-") != std::string::npos) return true;
  return false;
}

}  // namespace

TEST(OutputFile, FullDiskIsAnErrorNamingTheFileAndTheReason) {
  // Small enough to stay in the buffer: the failure shows at close().
  OutputFile out("/dev/full");
  out.stream() << "a few bytes";
  const std::string what = errorOf([&] { out.close(); });
  EXPECT_NE(what.find("cannot write /dev/full"), std::string::npos) << what;
  EXPECT_NE(what.find(std::strerror(ENOSPC)), std::string::npos) << what;
}

TEST(OutputFile, WriteAndPrintfAreChecked) {
  const std::string big(1 << 20, 'x');  // past the buffer: write() fails at once
  OutputFile out("/dev/full");
  EXPECT_NE(errorOf([&] { out.write(big); }).find(std::strerror(ENOSPC)), std::string::npos);
  OutputFile again("/dev/full");
  again.printf("%d %s\n", 42, "text");
  EXPECT_NE(errorOf([&] { again.close(); }).find(std::strerror(ENOSPC)), std::string::npos);
}

TEST(OutputFile, WritesWhatItIsGiven) {
  const fs::path dir = freshDir("plain");
  OutputFile out(dir / "a.txt");
  out.write("one ");
  out.printf("%.17g %s", 0.1, std::string(300, 'y').c_str());
  out.put('\n');
  out.stream() << "two\n";
  out.close();
  EXPECT_EQ(readFile(dir / "a.txt"), "one 0.10000000000000001 " + std::string(300, 'y') + "\ntwo\n");
}

TEST(WriteAtomically, FileSizeLimitKeepsThePreviousFile) {
  const fs::path dir = freshDir("limit");
  const fs::path target = dir / "RESU.pvd";
  writeTextFile(target, "the good one\n");
  std::string what;
  withFileSizeLimit(4096, [&] {
    what = errorOf([&] {
      writeAtomically(target, [](const fs::path& tmp) { writeTextFile(tmp, std::string(10000, 'z')); });
    });
  });
  // Named where it was going, not by the private folder.
  EXPECT_NE(what.find("cannot write " + target.string() + ": " + std::strerror(EFBIG)), std::string::npos) << what;
  EXPECT_EQ(readFile(target), "the good one\n");
  EXPECT_FALSE(hasPartialFolder(dir));
}

TEST(WriteAtomically, NeverWritesOverAnInput) {
  const fs::path dir = freshDir("input");
  const fs::path mesh = dir / "etude.med";
  writeTextFile(mesh, "the study's mesh\n");
  RunFiles files;
  files.addInput(mesh, "read by LIRE_MAILLAGE at etude.lua:2");
  auto attempt = [&](const fs::path& target) {
    return errorOf([&] {
      writeAtomically(target, [](const fs::path& tmp) { writeTextFile(tmp, "results\n"); }, &files);
    });
  };
  const std::string what = attempt(mesh);
  EXPECT_NE(what.find(mesh.string() + " is an input of the study (read by LIRE_MAILLAGE at etude.lua:2)"),
            std::string::npos)
      << what;
  // Another spelling of the same file, and a hard link to it.
  fs::create_directories(dir / "sub");
  EXPECT_NE(attempt(dir / "sub" / ".." / "etude.med").find("is an input"), std::string::npos);
  fs::create_hard_link(mesh, dir / "link.med");
  EXPECT_NE(attempt(dir / "link.med").find("is an input"), std::string::npos);
  EXPECT_EQ(readFile(mesh), "the study's mesh\n");
  EXPECT_FALSE(hasPartialFolder(dir));
  // Other files are written and recorded.
  EXPECT_EQ(attempt(dir / "etude-2.med"), "no error");
  EXPECT_TRUE(files.written(dir / "etude-2.med"));
}

TEST(RunFiles, FreshNamesSkipInputsAndWhatTheRunWrote) {
  const fs::path dir = freshDir("fresh");
  RunFiles files;
  EXPECT_EQ(files.fresh(dir, "etude", ".med"), dir / "etude.med");
  writeTextFile(dir / "etude.med", "mesh");
  files.addInput(dir / "etude.med", "LIRE_MAILLAGE");
  files.addWritten(dir / "etude-2.med");
  EXPECT_EQ(files.fresh(dir, "etude", ".med"), dir / "etude-3.med");
  EXPECT_EQ(files.fresh(dir, "etude", ".med", [](const std::string& n) { return n == "etude-3"; }),
            dir / "etude-4.med");
}

TEST(RunFiles, RemoveStaleTakesOnlyMatchingFilesOfEarlierRuns) {
  const fs::path dir = freshDir("stale");
  for (const char* f : {"RESU_0.vtu", "RESU_1.vtu", "RESU_2.vtu", "RESU_notes.txt", "OTHER_1.vtu", "RESU_x.vtu"})
    writeTextFile(dir / f, "x");
  RunFiles files;
  files.addWritten(dir / "RESU_0.vtu");        // this run's
  files.addInput(dir / "RESU_2.vtu", "read");  // the study's
  const auto removed =
      files.removeStale(dir, [](const std::string& name) { return isNumberedFile(name, "RESU", ".vtu"); });
  EXPECT_EQ(removed, std::vector<std::string>{"RESU_1.vtu"});
  for (const char* f : {"RESU_0.vtu", "RESU_2.vtu", "RESU_notes.txt", "OTHER_1.vtu", "RESU_x.vtu"})
    EXPECT_TRUE(fs::exists(dir / f)) << f;
}

TEST(RunFiles, IsNumberedFile) {
  EXPECT_TRUE(isNumberedFile("RESU_12.vtu", "RESU", ".vtu"));
  EXPECT_FALSE(isNumberedFile("RESU_.vtu", "RESU", ".vtu"));
  EXPECT_FALSE(isNumberedFile("RESU_1_2.vtu", "RESU", ".vtu"));
  EXPECT_FALSE(isNumberedFile("RESU-2_1.vtu", "RESU", ".vtu"));
  EXPECT_FALSE(isNumberedFile("RESU_1.pvd", "RESU", ".vtu"));
  EXPECT_FALSE(isNumberedFile("XRESU_1.vtu", "RESU", ".vtu"));
}

TEST(AppendAtomically, AddsOrStartsAfresh) {
  const fs::path dir = freshDir("append");
  const fs::path f = dir / "T.tab";
  writeTextFile(f, "from an earlier run\n");
  appendAtomically(f, "first\n", false, nullptr);
  appendAtomically(f, "second\n", true, nullptr);
  EXPECT_EQ(readFile(f), "first\nsecond\n");
  std::string what;
  withFileSizeLimit(8, [&] { what = errorOf([&] { appendAtomically(f, "third\n", true, nullptr); }); });
  EXPECT_NE(what.find(std::strerror(EFBIG)), std::string::npos) << what;
  EXPECT_EQ(readFile(f), "first\nsecond\n");
}
