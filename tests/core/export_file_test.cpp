// code_aster's .export format: what each line means, and every malformed line
// refused with the file and line that holds it.
#include "core/export_file.hpp"

#include <gtest/gtest.h>

#include "core/error.hpp"

using namespace aster;
namespace fs = std::filesystem;

namespace {

std::string errorOf(const std::string& text) {
  try {
    parseExportFile(text, "dir/t.export");
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(ExportFile, ReadsParametersFilesAndCommandFilesInOrder) {
  const auto ex = parseExportFile(
      "P time_limit 60\n"
      "P memory_limit 256\n"
      "P testlist ci verification sequential\n"
      "\n"
      "# a comment\n"
      "  # an indented comment\n"
      "A args --max_base=100\n"
      "F comm part1.comm D 1\n"
      "F mail mesh.mail D 20\n"
      "F com1 part2.com1 D 1\n"
      "F rmed out.med R 80\n"
      "F libr /abs/table.txt DR 38\n"
      "F nom data.txt D 0\n",
      "dir/t.export");
  ASSERT_EQ(ex.parameters.size(), 3u);
  EXPECT_EQ(ex.parameters[2].name, "testlist");
  EXPECT_EQ(ex.parameters[2].values, (std::vector<std::string>{"ci", "verification", "sequential"}));
  EXPECT_EQ(ex.parameters[2].line, 3);
  ASSERT_TRUE(ex.timeLimit());
  EXPECT_EQ(*ex.timeLimit(), 60.0);
  EXPECT_EQ(ex.arguments, (std::vector<std::string>{"args", "--max_base=100"}));
  ASSERT_EQ(ex.entries.size(), 6u);

  const auto comm = ex.commandFiles();
  ASSERT_EQ(comm.size(), 2u);
  EXPECT_EQ(comm[0]->path, "part1.comm");
  EXPECT_EQ(comm[1]->path, "part2.com1");
  EXPECT_EQ(ex.resolve(*comm[1]), fs::path("dir/part2.com1"));

  const auto& mesh = ex.entries[1];
  EXPECT_EQ(mesh.type, "mail");
  EXPECT_TRUE(mesh.data);
  EXPECT_FALSE(mesh.result);
  EXPECT_EQ(mesh.unit, 20);
  EXPECT_EQ(mesh.line, 9);
  EXPECT_FALSE(mesh.isCommandFile());

  const auto& med = ex.entries[3];
  EXPECT_FALSE(med.data);
  EXPECT_TRUE(med.result);
  EXPECT_EQ(med.unit, 80);

  const auto& both = ex.entries[4];
  EXPECT_TRUE(both.data && both.result);
  EXPECT_EQ(ex.resolve(both), fs::path("/abs/table.txt"));  // absolute paths stay as written
  EXPECT_EQ(ex.entries[5].unit, 0);
}

TEST(ExportFile, PathsMayHoldSpacesAndFoldersAreRLines) {
  const auto ex = parseExportFile("F mail my mesh.mail   D   20  \nR nom results D 0\nF libr t.gz DC 24\n", "t.export");
  ASSERT_EQ(ex.entries.size(), 3u);
  EXPECT_EQ(ex.entries[0].path, "my mesh.mail");
  EXPECT_EQ(ex.entries[0].unit, 20);
  EXPECT_TRUE(ex.entries[1].folder);
  EXPECT_EQ(ex.entries[1].path, "results");
  EXPECT_TRUE(ex.entries[2].compressed && ex.entries[2].data);
  EXPECT_EQ(ex.folder(), fs::path("."));  // no folder in the name: the current one
  EXPECT_FALSE(ex.timeLimit());
}

TEST(ExportFile, CommandFilesAreCommAndComDigitReadFiles) {
  const auto ex = parseExportFile("F comm a.py D 1\nF com0 b D 1\nF comx c D 2\nF comm d R 1\nF com12 e D 3\n", "t");
  const auto comm = ex.commandFiles();
  ASSERT_EQ(comm.size(), 2u);
  EXPECT_EQ(comm[0]->path, "a.py");
  EXPECT_EQ(comm[1]->path, "b");
}

TEST(ExportFile, MalformedLinesAreRefusedWithFileAndLine) {
  EXPECT_EQ(errorOf("P time_limit 60\nX comm a D 1\n"),
            "dir/t.export:2: unknown line kind 'X': a line is P (parameter), A (arguments), F (file) or R (folder)");
  EXPECT_EQ(errorOf("F comm a.comm D\n"), "dir/t.export:1: 'F' expects: F type path D|R|DR unit");
  EXPECT_EQ(errorOf("\n\nF mail a.mail X 20\n"),
            "dir/t.export:3: flags 'X': expected D (read), R (written) or DR, with C when gzipped");
  EXPECT_EQ(errorOf("F mail a.mail DD 20\n"),
            "dir/t.export:1: flags 'DD': expected D (read), R (written) or DR, with C when gzipped");
  EXPECT_EQ(errorOf("F mail a.mail C 20\n"), "dir/t.export:1: flags 'C': a file is read (D), written (R) or both (DR)");
  EXPECT_EQ(errorOf("F mail a.mail D -3\n"), "dir/t.export:1: unit '-3': expected a whole number from 0 up");
  EXPECT_EQ(errorOf("F mail a.mail D 2x\n"), "dir/t.export:1: unit '2x': expected a whole number from 0 up");
  EXPECT_EQ(errorOf("F mail a.mail D 99999999999\n"),
            "dir/t.export:1: unit '99999999999': expected a whole number from 0 up");
  EXPECT_EQ(errorOf("P\n"), "dir/t.export:1: 'P' needs a name: P name [value ...]");
  EXPECT_EQ(errorOf("P time_limit soon\n"), "dir/t.export:1: P time_limit expects one positive number of seconds");
  EXPECT_EQ(errorOf("P time_limit 0\n"), "dir/t.export:1: P time_limit expects one positive number of seconds");
  EXPECT_EQ(errorOf("F mail a.mail D 20\nF mail b.mail D 20\n"),
            "dir/t.export:2: unit 20 is already bound to a.mail (line 1)");
  EXPECT_EQ(errorOf("F mail a.mail D 20\nF rmed ./a.mail R 80\n"),
            "dir/t.export:2: ./a.mail is read (D) and written (R) on two lines (line 1): the run never writes over a "
            "file it reads");
  EXPECT_EQ(errorOf("F rmed a.med R 80\nF mmed a.med D 20\n"),
            "dir/t.export:2: a.med is read (D) and written (R) on two lines (line 1): the run never writes over a "
            "file it reads");
}

TEST(ExportFile, OneFileTwiceOnOneUnitOrOnTwoUnitsIsFine) {
  const auto ex = parseExportFile("F mail a.mail D 20\nF mail ./a.mail D 20\nF mail a.mail D 21\n", "t.export");
  EXPECT_EQ(ex.entries.size(), 3u);
}

TEST(ExportFile, UnreadableFileIsAnError) {
  try {
    readExportFile("/nonexistent/folder/t.export");
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_STREQ(e.what(), "cannot read the .export file /nonexistent/folder/t.export");
  }
}
