// The Lua layer: commands as globals, file:line in messages, FIN, plain Lua.
#include <gtest/gtest.h>

#include "core/interrupt.hpp"
#include "lang/interpreter.hpp"

using namespace aster::lang;

namespace {

struct StudyRun {
  int status;
  std::string out, err;
};

StudyRun run(const std::string& code) {
  Session session;
  session.studyPath = "etude.lua";
  session.outputDir = "etude";
  Interpreter interpreter(session);
  testing::internal::CaptureStdout();
  testing::internal::CaptureStderr();
  const int status = interpreter.runString(code, "@etude.lua");
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
  EXPECT_EQ(r.err, "<F> <LUA> etude.lua:2: 'DEBU' is not defined; did you mean DEBUT or debug?\n");
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
                   "local f, err = load(string.dump(function() return 1 end))\n"
                   "assert(f == nil and err:find('binary'))\n"
                   "assert(load('return 2')() == 2)\n");
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
