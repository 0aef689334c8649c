// An .export made ready to run: its command files in order, its data files bound
// to their units (the command line's -u first) and never written, what it cannot
// use refused with its line.
#include "lang/export_run.hpp"
#include "../support/scratch_files.hpp"

#include <gtest/gtest.h>

#include <fstream>

#include "core/error.hpp"

using namespace aster;
namespace fs = std::filesystem;

namespace {

void touch(const fs::path& p) { std::ofstream(p) << "x\n"; }

std::string errorOf(const std::string& exportText, const fs::path& dir) {
  lang::Session session;
  try {
    lang::prepareExportRun(parseExportFile(exportText, dir / "t.export"), session);
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(ExportRun, BindsDataFilesAndListsCommandFilesInOrder) {
  const fs::path dir = test::freshDir("export_run_test", "binds");
  for (const char* f : {"a.comm", "b.com1", "m.mail", "n.med", "data.txt", "t.export"}) touch(dir / f);
  lang::Session session;
  session.units[21] = "/given/with/-u.med";  // the command line wins
  const auto ex = parseExportFile(
      "F comm a.comm D 1\nF mail m.mail D 20\nF mmed n.med D 21\nF nom data.txt D 0\nF com1 b.com1 D 1\n"
      "F rmed out.med R 80\nF resu t.resu R 8\n",
      dir / "t.export");
  const auto comm = lang::prepareExportRun(ex, session);
  ASSERT_EQ(comm.size(), 2u);
  EXPECT_EQ(comm[0], (dir / "a.comm").string());
  EXPECT_EQ(comm[1], (dir / "b.com1").string());
  EXPECT_EQ(session.units.at(20), dir / "m.mail");
  EXPECT_EQ(session.units.at(21), fs::path("/given/with/-u.med"));
  EXPECT_EQ(session.units.at(80), dir / "out.med");  // written there by IMPR_RESU
  EXPECT_EQ(session.units.count(8), 0u);             // the .resu: copied after the run
  EXPECT_EQ(session.units.count(0), 0u);
  // Every file the .export reads is an input: no command writes over it.
  EXPECT_NE(session.inputOf(dir / "m.mail"), "");
  EXPECT_NE(session.inputOf(dir / "n.med"), "");  // read, though not bound (-u won)
  EXPECT_NE(session.inputOf(dir / "a.comm"), "");
  EXPECT_NE(session.inputOf(dir / "t.export"), "");
  EXPECT_EQ(session.inputOf(dir / "out.med"), "");
  session.outputDir = dir / "out";
  EXPECT_THROW(session.checkUnitWritable(20, session.units.at(20)), Error);
  EXPECT_NO_THROW(session.checkUnitWritable(80, session.units.at(80)));
}

TEST(ExportRun, RefusesWhatItCannotUseWithTheLine) {
  const fs::path dir = test::freshDir("export_run_test", "refuses");
  touch(dir / "a.comm");
  EXPECT_EQ(errorOf("F comm a.comm D 1\n\nF mail missing.mail D 20\n", dir),
            (dir / "t.export").string() + ":3: the file " + (dir / "missing.mail").string() + " does not exist");
  EXPECT_EQ(errorOf("F comm a.comm D 1\nR nom results D 0\n", dir),
            (dir / "t.export").string() + ":2: folders (R lines) are not supported: list the files of results one "
                                          "by one (F lines)");
  EXPECT_EQ(errorOf("F comm a.comm D 1\nF libr t.gz DC 24\n", dir),
            (dir / "t.export").string() + ":2: gzipped files (flag C) are not supported: gunzip t.gz and list it "
                                          "without C");
  EXPECT_EQ(errorOf("F mail a.comm D 20\n", dir),
            (dir / "t.export").string() + ": no command file (a line 'F comm <file> D 1') to run");
  fs::create_directories(dir / "folder.mail");
  EXPECT_EQ(errorOf("F comm a.comm D 1\nF mail folder.mail D 20\n", dir),
            (dir / "t.export").string() + ":2: " + (dir / "folder.mail").string() + " is not a regular file");
}
