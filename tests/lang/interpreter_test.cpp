// The Lua layer: commands as globals, file:line in messages, FIN, plain Lua.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "core/interrupt.hpp"
#include "lang/interpreter.hpp"

using namespace aster::lang;
namespace fs = std::filesystem;

namespace {

struct StudyRun {
  int status;
  std::string out, err;
};

struct Where {
  fs::path study = "etude.lua", output = "etude";
  bool unsafeLua = false;
};

StudyRun run(const std::string& code, const Where& where = {}) {
  Session session;
  session.studyPath = where.study;
  session.outputDir = where.output;
  session.unsafeLua = where.unsafeLua;
  Interpreter interpreter(session);
  testing::internal::CaptureStdout();
  testing::internal::CaptureStderr();
  const int status = interpreter.runString(code, "@" + where.study.filename().string());
  StudyRun r{status, testing::internal::GetCapturedStdout(), testing::internal::GetCapturedStderr()};
  return r;
}

}  // namespace

TEST(Interpreter, PlainLuaWorksInAStudy) {
  const StudyRun r = run("DEBUT{}\nlocal s = 0\nfor i = 1, 4 do s = s + i end\nprint(string.format('%d', s))\nFIN{}\n");
  EXPECT_EQ(r.status, 0);
  EXPECT_EQ(r.out, "10\n");
}

TEST(Interpreter, FinEndsTheStudy) {
  const StudyRun r = run("FIN{}\nerror('not reached')\n");
  EXPECT_EQ(r.status, 0);
  EXPECT_EQ(r.err, "");
}

TEST(Interpreter, DebutAndFinMayBeOmitted) { EXPECT_EQ(run("print('ok')").status, 0); }

TEST(Interpreter, RejectionNamesCommandFileLineKeywordAndExpectation) {
  const StudyRun r = run("DEBUT{}\n\nDEBUT{PAR_LOT = 'PEUT-ETRE'}\n");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err,
            "<F> <DEBUT> etude.lua:3: keyword PAR_LOT = 'PEUT-ETRE' is not allowed; allowed values: 'OUI', 'NON'\n");
}

TEST(Interpreter, FactorKeywordGivenAsTableListOrUnderscoreF) {
  EXPECT_EQ(run("DEBUT{CODE = {NIV_PUB_WEB = 'INTERNET'}}").status, 0);
  EXPECT_EQ(run("DEBUT{CODE = _F{NIV_PUB_WEB = 'INTERNET'}}").status, 0);
  EXPECT_EQ(run("DEBUT{CODE = {{NIV_PUB_WEB = 'INTERNET'}}}").status, 0);
  const StudyRun r = run("DEBUT{CODE = {{NIV_PUB_WEB = 'INTERNET'}, {NIV_PUB_WEB = 'INTRANET'}}}");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, "<F> <DEBUT> etude.lua:1: factor keyword CODE is given 2 times; expected at most 1\n");
}

TEST(Interpreter, UnknownCommandSuggestsTheClosest) {
  const StudyRun r = run("DEBUT{}\nDEBU{}\n");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, "<F> <LUA> etude.lua:2: 'DEBU' is not defined; did you mean DEBUT?\n");
}

TEST(Interpreter, CallWithoutATable) {
  const StudyRun r = run("DEBUT('OUI')\n");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, "<F> <DEBUT> etude.lua:1: DEBUT expects a table of keywords: DEBUT{KEY=value, ...}, got 'OUI'\n");
}

TEST(Interpreter, ReuseIsRefusedWhereTheCatalogueSaysSo) {
  const StudyRun r = run("DEBUT{reuse = 1}\n");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, "<F> <DEBUT> etude.lua:1: DEBUT does not accept reuse=\n");
}

TEST(Interpreter, LuaSyntaxAndRuntimeErrorsAreFatal) {
  StudyRun r = run("DEBUT{\n");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err.rfind("<F> <LUA> etude.lua:2:", 0), 0u) << r.err;
  r = run("local x = nil\nprint(x.y)\n");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err.rfind("<F> <LUA> etude.lua:2: attempt to index a nil value", 0), 0u) << r.err;
}

TEST(Interpreter, ErrorInsideAStudyFunctionPointsAtTheCall) {
  const StudyRun r = run("local function f()\n  DEBUT{LANG = 'DE'}\nend\nf()\n");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err.rfind("<F> <DEBUT> etude.lua:2:", 0), 0u) << r.err;
}

// DETRUIRE destroys: the variables holding the concept are unbound (the box is
// collected: a weak table loses it), the name can be reused, and any use of
// the concept, by its old name or through another variable, is a <F> that says
// where it was destroyed.
TEST(Interpreter, DetruireUnbindsTheConceptAndRefusesItsUse) {
  StudyRun r = run(
      "MAT = DEFI_MATERIAU{ELAS = {E = 1.0, NU = 0.3}}\n"
      "B = DEFI_MATERIAU{ELAS = {E = 2.0, NU = 0.3}}\n"
      "local weak = setmetatable({B}, {__mode = 'v'})\n"
      "DETRUIRE{CONCEPT = {NOM = {MAT, B}}}\n"
      "print(rawget(_G, 'MAT'), rawget(_G, 'B'), weak[1])\n"
      "MAT = DEFI_MATERIAU{ELAS = {E = 3.0, NU = 0.3}}\n"
      "print(MAT)\n");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out, "nil\tnil\tnil\n<mater_sdaster MAT>\n");
  r = run("MAT = DEFI_MATERIAU{ELAS = {E = 1.0, NU = 0.3}}\nDETRUIRE{NOM = MAT}\n"
          "local m = MAT\n");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, "<F> <LUA> etude.lua:3: 'MAT' was destroyed by DETRUIRE at etude.lua:2\n");
  r = run("F = DEFI_FONCTION{NOM_PARA = 'INST', VALE = {0, 0, 1, 1}}\nlocal G = F\nDETRUIRE{NOM = F}\n"
          "DETRUIRE{NOM = G}\n");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, "<F> <DETRUIRE> etude.lua:4: 'F' was destroyed by DETRUIRE at etude.lua:3\n");
  r = run("F = DEFI_FONCTION{NOM_PARA = 'INST', VALE = {0, 0, 1, 1}}\nlocal G = F\nDETRUIRE{NOM = F}\n"
          "print(G(0.5))\n");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, "<F> <F:__call> etude.lua:4: 'F' was destroyed by DETRUIRE at etude.lua:3\n");
  r = run("F = DEFI_FONCTION{NOM_PARA = 'INST', VALE = {0, 0, 1, 1}}\nlocal G = F\nDETRUIRE{NOM = F}\n"
          "print(G:getParameters())\n");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, "<F> <F> etude.lua:4: 'F' was destroyed by DETRUIRE at etude.lua:3\n");
}

TEST(Interpreter, StudiesRunSandboxed) {
  StudyRun r = run("assert(os.execute == nil and io.popen == nil and package.loadlib == nil)\n"
                   "assert(rawget(_G, 'debug') == nil and package.loaded.debug == nil and string.dump == nil)\n"
                   "assert(not pcall(require, 'debug'))\n"
                   "assert(load('return 2')() == 2)\n"
                   "assert(load('return x', 'chunk', 't', {x = 3})() == 3)\n"
                   "local pieces = {'return ', '4', '0 + 2'}\n"
                   "assert(load(function() return table.remove(pieces, 1) end)() == 42)\n"
                   "assert(getmetatable(_F) == nil)\n");
  EXPECT_EQ(r.status, 0) << r.err;
  r = run("os.execute('true')\n");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("attempt to call a nil value (field 'execute')"), std::string::npos) << r.err;
}

// Ctrl-C between two commands: the study stops before the next one, with exit
// status 130 and a <F> that names the command it did not run.
TEST(Interpreter, CtrlCStopsBeforeTheNextCommand) {
  aster::interrupt::request();
  const StudyRun r = run("print('before')\nDEBUT{}\nprint('after')\n");
  aster::interrupt::clear();
  EXPECT_EQ(r.status, kInterruptedStatus);
  EXPECT_EQ(r.status, 130);
  EXPECT_EQ(r.out, "before\n");
  EXPECT_NE(r.err.find("<F> <DEBUT> etude.lua:2: interrupted (SIGINT) before DEBUT"), std::string::npos) << r.err;
}

namespace {

// A scratch folder per test.
class Sandbox : public testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("aster_interpreter_" + std::to_string(::getpid()) + "_" +
            testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override {
    if (!HasFailure()) fs::remove_all(dir_);
  }
  Where at(bool unsafeLua = false) const { return {dir_ / "etude.lua", dir_ / "etude", unsafeLua}; }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  fs::path dir_;
};

std::string quoted(const std::string& s) { return "'" + s + "'"; }

}  // namespace

// Bytecode is not checked by Lua (crafted bytecode corrupts the memory): a
// sandboxed study loads text only, whatever the path.
TEST_F(Sandbox, NoBytecodeByAnyPath) {
  // The bytecode, made with --unsafe-lua (plain Lua): f.luac, and mod.lua for require.
  StudyRun r = run("local code = string.dump(function() return 'ran bytecode' end)\n"
                   "for _, name in ipairs({" + quoted(path("f.luac")) + ", " + quoted(path("mod.lua")) + "}) do\n"
                   "  local f = assert(io.open(name, 'wb')); f:write(code); f:close()\n"
                   "end\n"
                   "assert(load(code)() == 'ran bytecode')\n",
                   at(true));
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string refused = "attempt to load a binary chunk (mode is 't')";
  r = run("local f = assert(io.open(" + quoted(path("f.luac")) + ", 'rb')); local code = f:read('a'); f:close()\n"
          "local function refused(fn, err) assert(fn == nil and err:find([[" + refused + "]], 1, true), err) end\n"
          "refused(load(code))\n"
          "refused(load(code, 'x', 'b'))\n"
          "local once = code\n"
          "refused(load(function() local piece = once; once = nil; return piece end))\n"
          "refused(loadfile(" + quoted(path("f.luac")) + "))\n"
          "refused(loadfile(" + quoted(path("f.luac")) + ", 'b'))\n"
          "local ok, err = pcall(dofile, " + quoted(path("f.luac")) + ")\n"
          "assert(not ok and err:find([[" + refused + "]], 1, true), err)\n"
          "package.path = " + quoted(path("?.lua")) + "\n"
          "ok, err = pcall(require, 'mod')\n"
          "assert(not ok and err:find([[" + refused + "]], 1, true), err)\n"
          "print('all refused')\n",
          at());
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out, "all refused\n");
  // Nor is the study itself bytecode.
  std::ifstream in(path("f.luac"), std::ios::binary);
  const std::string bytecode((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  {
    Session session;
    session.studyPath = path("etude.lua");
    session.outputDir = path("etude");
    Interpreter interpreter(session);
    testing::internal::CaptureStdout();
    testing::internal::CaptureStderr();
    const int status = interpreter.runString(bytecode, "@etude.lua");
    const std::string out = testing::internal::GetCapturedStdout(), err = testing::internal::GetCapturedStderr();
    EXPECT_EQ(status, 2);
    EXPECT_EQ(out, "");
    EXPECT_NE(err.find("<F> <LUA> " + refused), std::string::npos) << err;
  }
}

TEST_F(Sandbox, RequireLoadsTextModules) {
  std::ofstream(path("helper.lua")) << "return {twice = function(x) return 2 * x end}\n";
  const StudyRun r = run("package.path = " + quoted(path("?.lua")) + "\n"
                         "print(require('helper').twice(21))\n"
                         "assert(not pcall(require, 'absent_module'))\n"
                         "assert(package.cpath == '' and #package.searchers == 2)\n",
                         at());
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out, "42\n");
}

// Writing: below the output folder only, where a relative path is taken.
TEST_F(Sandbox, StudiesWriteBelowTheirOutputFolderOnly) {
  fs::create_directories(dir_ / "etude" / "sub");
  fs::create_symlink(dir_, dir_ / "etude" / "escape");
  fs::create_symlink(dir_ / "absent", dir_ / "etude" / "dangling");
  std::ofstream(path("outside.txt")) << "keep me\n";
  const std::string fatal = "<F> <LUA> etude.lua:";
  StudyRun r = run("local f = assert(io.open('table.csv', 'w')); f:write('1,2\\n'); f:close()\n"
                   "f = assert(io.open('sub/more.csv', 'a')); f:close()\n"
                   "assert(os.rename('sub/more.csv', 'renamed.csv'))\n"
                   "assert(os.remove('renamed.csv'))\n"
                   "io.output('log.txt'); io.write('logged\\n'); io.close(); io.output(io.stdout)\n"
                   "assert(io.open(" + quoted(path("etude/table.csv")) + "):read('a') == '1,2\\n')\n"
                   "f = assert(io.open(" + quoted(path("etude/table.csv")) + ", 'a')); f:close()\n"
                   "print(io.open(" + quoted(path("outside.txt")) + "):read('l'))\n",
                   at());
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out, "keep me\n");
  EXPECT_TRUE(fs::exists(dir_ / "etude" / "table.csv"));
  EXPECT_TRUE(fs::exists(dir_ / "etude" / "log.txt"));
  EXPECT_FALSE(fs::exists(dir_ / "etude" / "renamed.csv"));

  struct Refused {
    std::string code, message;
  };
  const std::string out = fs::weakly_canonical(dir_ / "etude").string();
  const std::string outside = "a sandboxed study writes files only below its output folder " + out +
                              " (a relative path is taken from there) (aster-lite --unsafe-lua lifts the sandbox)";
  for (const Refused& c : std::vector<Refused>{
           {"io.open('../outside.txt', 'w')", "io.open cannot write '../outside.txt': " + outside},
           {"io.open(" + quoted(path("outside.txt")) + ", 'r+')",
            "io.open cannot write '" + path("outside.txt") + "': " + outside},
           {"io.open('sub/../../outside.txt', 'a')", "io.open cannot write 'sub/../../outside.txt': " + outside},
           {"io.open('escape/outside.txt', 'w')", "io.open cannot write 'escape/outside.txt': " + outside},
           {"io.open('dangling', 'w')", "io.open cannot write 'dangling': " + out +
                                            "/dangling is a symbolic link (a sandboxed study does not write through links)"},
           {"io.open('.bashrc', 'w')", "io.open cannot write '.bashrc': a sandboxed study writes no hidden file"},
           {"io.open('.config/x', 'w')", "io.open cannot write '.config/x': a sandboxed study writes no hidden file"},
           {"io.open('sub', 'w')", ""},  // a folder: io.open itself fails, no <F>
           {"io.output('../outside.txt')", "io.output cannot write '../outside.txt': " + outside},
           {"os.remove(" + quoted(path("outside.txt")) + ")",
            "os.remove cannot delete '" + path("outside.txt") + "': " + outside},
           {"os.rename('table.csv', '../outside.txt')", "os.rename cannot replace '../outside.txt': " + outside},
           {"os.rename('../outside.txt', 'mine.txt')", "os.rename cannot move '../outside.txt': " + outside},
           {"os.tmpname()", "os.tmpname is not available to a sandboxed study"},
           {"os.setlocale('fr_FR.UTF-8')", "os.setlocale cannot change the locale of a sandboxed study"},
       }) {
    r = run(c.code + "\n", at());
    if (c.message.empty()) {
      EXPECT_EQ(r.status, 0) << c.code << "\n" << r.err;
      continue;
    }
    EXPECT_EQ(r.status, 2) << c.code;
    EXPECT_EQ(r.err.rfind(fatal + "1: " + c.message, 0), 0u) << c.code << "\n" << r.err;
  }
  std::ifstream in(path("outside.txt"));
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "keep me");
  EXPECT_EQ(run("print(os.setlocale())\n", at()).out, "C\n");
}

// With the output folder where the inputs are, the inputs are not writable.
TEST_F(Sandbox, StudiesNeverReplaceTheirInputs) {
  std::ofstream(path("etude.lua")) << "-- the study\n";
  std::ofstream(path("mesh.mail")) << "COOR_2D\n";
  std::ofstream(path("data.txt")) << "1 2 3\n";
  Where here{dir_ / "etude.lua", dir_, false};
  StudyRun r = run("io.open('etude.lua', 'w')\n", here);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("io.open cannot write 'etude.lua': " + fs::weakly_canonical(dir_ / "etude.lua").string() +
                       " is the study file itself"),
            std::string::npos)
      << r.err;
  r = run("DEFI_FICHIER{ACTION='ASSOCIER', UNITE=20, FICHIER='mesh.mail'}\nos.remove('mesh.mail')\n", here);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("is bound to unit 20"), std::string::npos) << r.err;
  r = run("for l in io.lines(" + quoted(path("data.txt")) + ") do end\nio.open('data.txt', 'w')\n", here);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("is an input of the study (it read the file)"), std::string::npos) << r.err;
  // What the study wrote itself it may read back and write again.
  r = run("io.open('mine.txt', 'w'):close()\nio.open(" + quoted(path("mine.txt")) + "):close()\n"
          "io.open('mine.txt', 'w'):close()\n",
          here);
  EXPECT_EQ(r.status, 0) << r.err;
  std::ifstream in(path("etude.lua"));
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "-- the study");
}

TEST(Interpreter, GetmetatableGivesNamesOnly) {
  const StudyRun r = run("F = FORMULE{VALE = 'X', NOM_PARA = 'X'}\n"
                         "print(getmetatable(F), getmetatable(CO('A')))\n"
                         "assert(not pcall(setmetatable, F, {}))\n");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out, "aster-lite concept\taster-lite CO name\n");
}

// A <F> is fatal even when the study catches it; FIN and os.exit cannot be caught.
TEST(Interpreter, FatalErrorsStayFatal) {
  StudyRun r = run("local ok, err = pcall(DEBUT, {PAR_LOT = 'PEUT-ETRE'})\nprint(ok, err.aster_fatal ~= nil)\n");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.out, "false\ttrue\n");
  EXPECT_EQ(r.err,
            "<F> <DEBUT> etude.lua:1: keyword PAR_LOT = 'PEUT-ETRE' is not allowed; allowed values: 'OUI', 'NON'\n"
            "<F> <LUA> the study went on after 1 fatal error (caught with pcall or in a coroutine): a fatal error "
            "ends the run with exit status 2\n");
  // Caught, then raised again by the study: printed once.
  r = run("local ok, err = pcall(DEBUT, {PAR_LOT = 'PEUT-ETRE'})\nerror(err)\n");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err,
            "<F> <DEBUT> etude.lua:1: keyword PAR_LOT = 'PEUT-ETRE' is not allowed; allowed values: 'OUI', 'NON'\n");
  // In a coroutine.
  r = run("local co = coroutine.create(function() DEBUT{LANG = 'DE'} end)\nprint(coroutine.resume(co) == false)\n");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.out, "true\n");
  EXPECT_EQ(r.err.rfind("<F> <DEBUT> etude.lua:1:", 0), 0u) << r.err;
  // A plain Lua error caught by pcall is the study's business.
  EXPECT_EQ(run("assert(not pcall(error, 'mine'))\n").status, 0);
  // Nothing runs after FIN or os.exit(), caught or not; os.exit(failure) is a fatal error.
  r = run("pcall(FIN)\nprint('after FIN')\n");
  EXPECT_EQ(r.status, 0);
  EXPECT_EQ(r.out, "");
  r = run("local co = coroutine.wrap(function() pcall(os.exit, true) end)\npcall(co)\nprint('after exit')\n");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out, "");
  r = run("pcall(os.exit, false)\nprint('after exit')\n");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.out, "");
  EXPECT_EQ(r.err, "<F> <LUA> etude.lua:1: the study called os.exit(false): it ends as a failure\n");
}

// Ctrl-C reaches Lua code within a thousand instructions, and pcall does not stop it.
TEST(Interpreter, CtrlCStopsLuaCode) {
  for (const char* code : {
           "while true do end\n",
           "while true do pcall(function() while true do end end) end\n",
           "while true do pcall(error, 'x') end\n",
           "while true do xpcall(function() while true do end end, function(m) return m end) end\n",
           "coroutine.wrap(function() while true do end end)()\n",
           "while true do coroutine.resume(coroutine.create(function() while true do end end)) end\n",
           "F = FORMULE{VALE = function(x) while true do end end, NOM_PARA = 'X'}\nF(1.0)\n",
       }) {
    aster::interrupt::request();
    const StudyRun r = run(code);
    aster::interrupt::clear();
    EXPECT_EQ(r.status, kInterruptedStatus) << code << r.err;
    EXPECT_NE(r.err.find("interrupted (SIGINT)"), std::string::npos) << code << r.err;
  }
}

// The name a result is assigned to is read from the calling line; a 100 000-character
// name overflowed the stack of the std::regex that read it.
TEST(Interpreter, LongVariableNameOnTheLeftOfACommand) {
  const std::string name(100000, 'A');
  const StudyRun r = run(name + " = DEBUT{}; local " + name + "B = DEBUT(); print('ok')\n");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out, "ok\n");
}

// Keyword tables too deep or cyclic are refused by the validator's message,
// before the reading overflows the Lua stack (40 levels) or recurses forever.
TEST(Interpreter, DeepOrCyclicKeywordTablesAreRefused) {
  StudyRun r = run("local t = {NIV_PUB_WEB = 'INTERNET'}\nfor _ = 1, 40 do t = {CODE = t} end\nDEBUT(t)\n");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err.rfind("<F> <DEBUT> etude.lua:3: keyword CODE/CODE/", 0), 0u) << r.err;
  EXPECT_NE(r.err.find(" is nested 20 tables deep; a command's keywords are at most 3 deep\n"), std::string::npos)
      << r.err;
  r = run("local code = {}\ncode.NIV_PUB_WEB = code\nDEBUT{CODE = code}\n");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, "<F> <DEBUT> etude.lua:3: keyword CODE/NIV_PUB_WEB is CODE again: a table of keywords cannot "
                   "contain itself\n");
  // The same table twice, side by side, is no cycle.
  r = run("local code = {NIV_PUB_WEB = 'INTERNET'}\nDEBUT{CODE = code}\nDEBUT{CODE = {code}}\n");
  EXPECT_EQ(r.status, 0) << r.err;
}

// Lua strings may hold NUL bytes; names and texts would be cut at the first one.
TEST(Interpreter, NulBytesInKeysTextsAndNamesAreRefused) {
  StudyRun r = run("DEBUT{CODE = {['NIV_PUB_WEB\\0X'] = 'INTERNET'}}\n");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, "<F> <DEBUT> etude.lua:1: keyword name 'NIV_PUB_WEB\\0X' in CODE contains a NUL byte ('\\0')\n");
  r = run("DEBUT{CODE = {NIV_PUB_WEB = 'INTERNET\\0'}}\n");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, "<F> <DEBUT> etude.lua:1: CODE: keyword NIV_PUB_WEB = 'INTERNET\\0' contains a NUL byte ('\\0')\n");
  r = run("local x = 1\nlocal name = CO('RES\\0U')\n");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, "<F> <CO> etude.lua:2: the name 'RES\\0U' contains a NUL byte ('\\0')\n");
  r = run("local name = CO({})\n");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, "<F> <CO> etude.lua:1: CO expects the name of the concept to create, CO('NAME'), got a table\n");
}
