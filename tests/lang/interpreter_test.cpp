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
