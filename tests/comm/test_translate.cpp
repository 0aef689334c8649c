// The translator from code_aster command files to Lua: the text it writes for each
// construct, and what that text does when Lua runs it, against Python's own results
// (worked out by hand from Python's rules, given in the comments).
#include <gtest/gtest.h>

#include <lua.hpp>
#include <string>

#include "comm/translate.hpp"

namespace {

using aster::comm::translateCommandFile;

std::string lua(const std::string& python) {
  const auto t = translateCommandFile(python, "t.comm");
  EXPECT_TRUE(t.ok) << t.error;
  return t.lua;
}

std::string error(const std::string& python) {
  const auto t = translateCommandFile(python, "t.comm");
  EXPECT_FALSE(t.ok) << t.lua;
  return t.error;
}

int capture(lua_State* L) {
  std::string* out = static_cast<std::string*>(lua_touserdata(L, lua_upvalueindex(1)));
  for (int i = 1; i <= lua_gettop(L); ++i) {
    if (i > 1) *out += '\t';
    *out += luaL_tolstring(L, i, nullptr);
    lua_pop(L, 1);
  }
  *out += '\n';
  return 0;
}

// Translates and runs in a bare Lua state; returns what print wrote (or the Lua error).
std::string run(const std::string& python) {
  const std::string code = lua(python);
  lua_State* L = luaL_newstate();
  luaL_openlibs(L);
  // Commands, as aster-lite's interpreter gives them: here functions returning their keywords.
  luaL_dostring(L, "setmetatable(_G, {__index = function(_, k) if k:match('^[A-Z][A-Z0-9_]*$') then "
                   "return function(t) return t end end end})");
  std::string out;
  lua_pushlightuserdata(L, &out);
  lua_pushcclosure(L, capture, 1);
  lua_setglobal(L, "print");
  if (luaL_loadbuffer(L, code.data(), code.size(), "@t.comm") != LUA_OK || lua_pcall(L, 0, 0, 0) != LUA_OK)
    out += std::string("ERROR: ") + lua_tostring(L, -1);
  lua_close(L);
  return out;
}

std::string line(const std::string& text, int n) {
  std::size_t start = 0;
  for (int i = 1; i < n; ++i) start = text.find('\n', start) + 1;
  return text.substr(start, text.find('\n', start) - start);
}

int lineCount(const std::string& text) {
  int n = 0;
  for (char c : text) n += c == '\n';
  return n;
}

TEST(Translate, CommandCallsBecomeTableCalls) {
  const std::string out = lua("MA = LIRE_MAILLAGE(FORMAT='MED', UNITE=20)\n"
                              "MA = MODI_MAILLAGE(reuse=MA, MAILLAGE=MA, ORIE_PEAU=_F(GROUP_MA_PEAU=('A', 'B'),),)\n"
                              "FIN()\n");
  EXPECT_EQ(line(out, 1), "MA = LIRE_MAILLAGE{FORMAT = 'MED', UNITE = 20}");
  EXPECT_EQ(line(out, 2), "MA = MODI_MAILLAGE{reuse = MA, MAILLAGE = MA, ORIE_PEAU = {GROUP_MA_PEAU = {'A', 'B'}}}");
  EXPECT_EQ(line(out, 3), "FIN{}");
}

TEST(Translate, KeepsEveryLineWhereItWas) {
  const std::string src =
      "# header\n"
      "CH = AFFE_CHAR_MECA(MODELE=MO,\n"
      "    DDL_IMPO=(_F(GROUP_NO='A', DX=0.),  # fixed\n"
      "              _F(GROUP_NO='B', DY=0.)),\n"
      "    )\n"
      "\n"
      "x = undefined + 1\n";
  const std::string out = lua(src);
  EXPECT_EQ(lineCount(out), 7);
  EXPECT_EQ(line(out, 1), "-- header");
  EXPECT_EQ(line(out, 2), "CH = AFFE_CHAR_MECA{MODELE = MO,");
  EXPECT_EQ(line(out, 3), "    DDL_IMPO = {{GROUP_NO = 'A', DX = 0.0}, -- fixed");
  EXPECT_EQ(line(out, 4), "              {GROUP_NO = 'B', DY = 0.0}}}");
  EXPECT_EQ(line(out, 5), "");  // the closing bracket ends the call on the line of its last argument
  // Lua's own messages name the command file's line.
  EXPECT_NE(run(src).find("t.comm:7:"), std::string::npos) << run(src);
}

TEST(Translate, CommentsStayLineComments) {
  // "#[[" must not open a Lua long comment that would swallow the next lines.
  EXPECT_EQ(run("#[[ not a block\nx = 1 #[==[\nprint(x)\n"), "1\n");
  // A string used as a block comment: its source lines, escapes and all, as comments.
  const std::string out = lua("'''\nf.write('%E\\n' % x)\n'''\ny = 2\n");
  EXPECT_EQ(line(out, 2), "-- f.write('%E\\n' % x)");
  EXPECT_EQ(line(out, 4), "y = 2");
}

TEST(Translate, FortranExponentsAndIntegers) {
  const std::string out = lua("a = 1.D-3\nb = 1.d0\nc = 2.E+5\nd = 10\ne = .5\n");
  EXPECT_EQ(line(out, 1), "a = 1.0e-3");
  EXPECT_EQ(line(out, 2), "b = 1.0e0");
  EXPECT_EQ(line(out, 3), "c = 2.0e+5");
  EXPECT_EQ(line(out, 4), "d = 10");
  // Python prints 0.001 1.0 200000.0 10 0.5: ints stay ints, floats print as Python does.
  EXPECT_EQ(run("a = 1.D-3\nb = 1.d0\nc = 2.E+5\nd = 10\ne = .5\nprint(a, b, c, d, e)\n"), "0.001 1.0 200000.0 10 0.5\n");
}

TEST(Translate, StringLiteralsOfEveryKind) {
  // r'\n' is two characters, '\n' one; adjacent literals join; u and b prefixes are plain strings.
  EXPECT_EQ(run("print(len(r'a\\n'), len('a\\n'), 'ab' \"cd\", u'x', b'y', '\\x41\\101\\u00e9')\n"), "3 2 abcd x y AA\xC3\xA9\n");
  const std::string src = "t = '''one\ntwo'''\ns = ('a'\n     'b')\nprint(t + s)\n";
  const std::string out = lua(src);
  EXPECT_EQ(lineCount(out), 5);
  EXPECT_EQ(line(out, 1).substr(line(out, 1).rfind("t = ")), "t = 'one\\n' ..");
  EXPECT_EQ(line(out, 2), "'two'");
  EXPECT_EQ(run(src), "one\ntwoab\n");
  EXPECT_EQ(run("s = 'a' \\\n    'b'\nprint(s)\n"), "ab\n");
  EXPECT_EQ(error("x = 1\ny = f'{x}'\n"), "t.comm:2: f-strings are not supported");
}

TEST(Translate, FormulePassesItsTextThrough) {
  EXPECT_EQ(line(lua("F = FORMULE(VALE='X**2 + 1.D0*Y', NOM_PARA=('X', 'Y'))\n"), 1),
            "F = FORMULE{VALE = 'X**2 + 1.D0*Y', NOM_PARA = {'X', 'Y'}}");
  // SSNP152 A: pow imported from math, used in a FORMULE's text (kept for the formula
  // language) and in Python (translated).
  const std::string out = lua("from math import pow\nEXP = FORMULE(VALE='pow(10,INST-1.1)', NOM_PARA='INST',)\n");
  EXPECT_EQ(line(out, 2), "EXP = FORMULE{VALE = 'pow(10,INST-1.1)', NOM_PARA = 'INST'}");
  EXPECT_EQ(run("from math import pow\nprint(pow(10, 2), pow(2, -1))\n"), "100.0 0.5\n");
}

TEST(Translate, RangeEndsAreExclusive) {
  const std::string src =
      "def show(n, a=None, b=None):\n"
      "    s = ''\n"
      "    return s\n"
      "r = ''\n"
      "for i in range(4): r = r + str(i)\n"
      "r = r + '|'\n"
      "for i in range(2, 5): r = r + str(i)\n"
      "r = r + '|'\n"
      "for i in range(10, 0, -3): r = r + str(i) + ','\n"
      "r = r + '|'\n"
      "for i in range(0, 10, 3): r = r + str(i)\n"
      "r = r + '|'\n"
      "n = 3\n"
      "for i in range(n): r = r + str(i)\n"
      "k = -2\n"
      "for i in range(6, 0, k): r = r + str(i)\n"
      "for i in range(0): r = r + 'never'\n"
      "print(r)\n";
  // Python: 0123|234|10,7,4,1,|0369|012642
  EXPECT_EQ(run(src), "0123|234|10,7,4,1,|0369|012642\n");
  EXPECT_EQ(line(lua("for i in range(4):\n    pass\n"), 1), "for i = 0, 3 do");
  EXPECT_EQ(line(lua("n = 4\nfor i in range(1, n):\n    pass\n"), 2), "for i = 1, n - 1 do");
}

TEST(Translate, ListsAreIndexedFromZero) {
  const std::string src =
      "L = [10, 20, 30]\n"
      "i = 1\n"
      "print(L[0], L[-1], L[i], L[-2], L[1:], L[::-1])\n"
      "for j in range(3):\n"
      "    L[j] = L[j] + j\n"
      "print(L, len(L), 'abc'[1], 'abc'[-1])\n"
      "def get(seq, k):\n"
      "    return seq[k]\n"
      "print(get(L, 0), get(L, -1), get('xyz', 2))\n";
  // Python: 10 30 20 20 [20, 30] [30, 20, 10] / [10, 21, 32] 3 b c / 10 32 z
  EXPECT_EQ(run(src), "10 30 20 20 [20, 30] [30, 20, 10]\n[10, 21, 32] 3 b c\n10 32 z\n");
  EXPECT_EQ(line(lua("L = [1, 2]\nx = L[0] * 2.5 - L[-1]\n"), 2), "x = L[1] * 2.5 - L[#L]");
}

TEST(Translate, PercentFormattingAndFormat) {
  EXPECT_EQ(run("print('%d|%5.2f|%s|%r|%-3s|%e|%%' % (3, 3.14159, 'a', 'b', 'x', 1234.5))\n"),
            "3| 3.14|a|'b'|x  |1.234500e+03|%\n");
  EXPECT_EQ(run("print('n=%d' % 7, 'v=%g' % 0.5)\n"), "n=7 v=0.5\n");
  // A list after % is one value (a tuple holds the arguments): Python prints L=[5] and 1-2.
  EXPECT_EQ(run("print('L=%s' % [5], '%d-%d' % (1, 2))\n"), "L=[5] 1-2\n");
  EXPECT_EQ(run("print('{} {:>5} {:.2e} {name} {0}'.format(1, 'x', 12345.678, name='n'))\n"), "1     x 1.23e+04 n 1\n");
  EXPECT_EQ(run("print('{:6.3f}|{:<4}|{:03d}'.format(3.14159, 'ab', 7))\n"), " 3.142|ab  |007\n");
  // x % y with x unknown: decided when the study runs (format for strings, modulo for numbers).
  EXPECT_EQ(run("def f(a, b):\n    return a % b\nprint(f('%d!', 3), f(7, 3), f(-7, 3), f(7.5, 2))\n"), "3! 1 2 1.5\n");
}

TEST(Translate, PlusOnStringsAndNumbers) {
  EXPECT_EQ(line(lua("a = 'x' + 'y'\n"), 1), "a = 'x' .. 'y'");
  EXPECT_EQ(line(lua("n = 2\nb = n + 1\n"), 2), "b = n + 1");
  // Types known only at run time: a helper with Python's rules.
  EXPECT_EQ(run("def f(a, b):\n    return a + b\nprint(f('a', 'b'), f(1, 2), f([1], [2]))\n"), "ab 3 [1, 2]\n");
  EXPECT_NE(run("def f(a, b):\n    return a + b\nprint(f('a', 1))\n").find("ERROR"), std::string::npos);
  EXPECT_EQ(run("print('-' * 3, [0] * 2, 3 * 2)\n"), "--- [0, 0] 6\n");
}

TEST(Translate, ArithmeticFollowsPython) {
  // Python: 3 -4 2 -2 1024 1.4142135623730951 2 4 -3 0.1 0.3333333333333333 8.0 3.5 -9, and 2 ** 64
  // beyond 64-bit integers: Python's unbounded integer, here the nearest float (never a wrapped one).
  EXPECT_EQ(run("print(7 // 2, -7 // 2, -7 % 3, 7 % -3, 2 ** 10, 2 ** 0.5, round(2.5), round(3.5), int(-3.7),"
                " str(0.1), str(1 / 3), 2.0 ** 3, 7 / 2, -3 ** 2, 2 ** 64)\n"),
            "3 -4 2 -2 1024 1.4142135623730951 2 4 -3 0.1 0.3333333333333333 8.0 3.5 -9 1.8446744073709552e+19\n");
  EXPECT_EQ(run("x = 2\nprint(1 < x < 3, 1 < x < 2, x != 2, not x == 3, x if x > 1 else -x)\n"), "True False False True 2\n");
  EXPECT_EQ(run("print(abs(-2), min(3, 1, 2), max([4, 9, 2]), float('2.5'), int('12'), round(2.675, 2), sum([1, 2, 3]))\n"),
            "2 1 9 2.5 12 2.67 6\n");
  EXPECT_EQ(run("print(True, False, None, [1, 'a', 2.0], 1e16, 1.5e-7, -0.0)\n"),
            "True False None [1, 'a', 2.0] 1e+16 1.5e-07 -0.0\n");
}

TEST(Translate, MixedConstructsAgainstPython) {
  // Python 3 prints: 1 2 3 3 None 3 2 abcc 3 5 False 1 A-5    x|y  |x 5.5 [0, 0, 0, 1] ABCx1-22
  const std::string src =
      "x = -(-1); y = - -2\n"
      "a = b = 3\n"
      "if x: pass\n"
      "def f(): pass\n"
      "def g(n):\n"
      "    if n > 1:\n"
      "        return n\n"
      "    return -n\n"
      "for i in range(3): continue\n"
      "while False: break\n"
      "s = 'a' 'b' + \"c\" * 2\n"
      "v = {'a': 1, 'b c': 2}\n"
      "w = v['a'] + v['b c']\n"
      "z = [1, 2][0] + (3, 4)[-1]\n"
      "k = not (x == 1)\n"
      "m = x if y else (z if a else b)\n"
      "n = \"%(a)s-%(b)d\" % {'a': 'A', 'b': 5}\n"
      "o = '{0:>4}|{1:<3}|{0}'.format('x', 'y')\n"
      "p = 10 % 3 + 10.5 // 2 - 2 ** -1\n"
      "q = [0] * 3 + [1]\n"
      "r = 'abc'.upper() + ' x '.strip() + '-'.join(['1', '2']) + str(len('abc'.split('b')))\n"
      "print(x, y, a, b, f(), g(3), g(-2), s, w, z, k, m, n, o, p, q, r)\n";
  EXPECT_EQ(run(src), "1 2 3 3 None 3 2 abcc 3 5 False 1 A-5    x|y  |x 5.5 [0, 0, 0, 1] ABCx1-22\n");
}

TEST(Translate, MathModule) {
  EXPECT_EQ(run("import math\nprint(math.sqrt(4.), math.pi == 3.141592653589793, math.log10(100.), math.fabs(-3),"
                " math.degrees(math.pi), math.pow(2, 3), math.atan2(1., 1.) * 4 == math.pi, math.floor(2.5), math.e)\n"),
            "2.0 True 2.0 3.0 180.0 8.0 True 2 2.718281828459045\n");
  EXPECT_EQ(run("from math import *\nprint(sqrt(9.), cos(0.), pi > 3, exp(0.))\n"), "3.0 1.0 True 1.0\n");
  // Without an import too, as code_aster runs command files; a name the file binds is its own.
  EXPECT_EQ(run("print(sqrt(4.), pi > 3)\ne = 5\nprint(e)\n"), "2.0 True\n5\n");
  EXPECT_EQ(line(lua("from math import *\nx = sqrt(2.) * pi\n"), 2), "x = math.sqrt(2.0) * math.pi");
  EXPECT_EQ(error("import math\nx = math.gamma(2.)\n"), "t.comm:2: math.gamma is not supported");
}

TEST(Translate, TruthinessOfNonBooleans) {
  // Python: 0, '', [] and None are false; Lua's if would take them as true.
  const std::string src =
      "r = ''\n"
      "for v in [0, 1, '', 'a', [], [0], None]:\n"
      "    if v:\n"
      "        r = r + 'T'\n"
      "    else:\n"
      "        r = r + 'F'\n"
      "print(r, 0 or 'd', 2 and 3, [] or [5], not '')\n";
  EXPECT_EQ(run("x = 0\nr = 'yes' if x else 'no'\nprint(r)\n"), "no\n");
  EXPECT_EQ(lua("x = 1\nif x > 0:\n    pass\n").find("py_truth"), std::string::npos);  // a comparison is boolean
  EXPECT_NE(error(src).find("t.comm:2: None inside a list"), std::string::npos);
  EXPECT_EQ(run("r = ''\nfor v in [0, 1, '', 'a', [], [0]]:\n    if v:\n        r = r + 'T'\n    else:\n        r = r + 'F'\n"
                "print(r, 0 or 'd', 2 and 3, [] or [5], not '')\n"),
            "FTFTFT d 3 [5] True\n");
}

TEST(Translate, LoopsBreakContinueWhile) {
  const std::string src =
      "r = ''\n"
      "for x in (1, 2, 3, 4, 5):\n"
      "    if x == 2:\n"
      "        continue\n"
      "    if x == 5:\n"
      "        break\n"
      "    r = r + str(x)\n"
      "k = 0\n"
      "while True:\n"
      "    k += 1\n"
      "    if k % 2: continue\n"
      "    if k > 6: break\n"
      "    r += str(k)\n"
      "for i, v in enumerate(['a', 'b']):\n"
      "    r += str(i) + v\n"
      "for a, b in zip([1, 2], ['x', 'y']):\n"
      "    r += str(a) + b\n"
      "for c in 'hi':\n"
      "    r += c\n"
      "print(r)\n";
  // Python: 134 246 0a1b 1x2y hi
  EXPECT_EQ(run(src), "1342460a1b1x2yhi\n");
}

TEST(Translate, LoopVariablesOutliveTheirLoop) {
  // Python: the loop variable keeps its last value after the loop (also in a function).
  const std::string src =
      "for i in range(3):\n"
      "    pass\n"
      "for x in ['a', 'b']:\n"
      "    pass\n"
      "def f():\n"
      "    for k in range(1, 5):\n"
      "        if k == 3:\n"
      "            break\n"
      "    return k\n"
      "L = [i * 10 for i in range(2)]\n"
      "print(i, x, f(), L)\n";
  EXPECT_EQ(run(src), "2 b 3 [0, 10]\n");
  EXPECT_EQ(line(lua("for i in range(3):\n    pass\n"), 1), "for i = 0, 2 do");  // not read after: plain
}

TEST(Translate, FunctionsWithLocalsDefaultsAndKeywords) {
  const std::string src =
      "y = 100\n"
      "def f(a, b=2, c=3):\n"
      "    if a > 0:\n"
      "        y = a * b\n"
      "    else:\n"
      "        y = -1\n"
      "    return y + c\n"
      "print(f(1), f(1, c=10), f(a=2, b=5), f(-1), y)\n";
  // Python: y inside f is f's own local: 5 12 13 2 100
  EXPECT_EQ(run(src), "5 12 13 2 100\n");
  EXPECT_EQ(line(lua(src), 2), "function f(a, b, c) local y if b == nil then b = 2 end if c == nil then c = 3 end");
}

TEST(Translate, LuaKeywordsAsNamesAreRenamed) {
  EXPECT_EQ(run("end = 3\nlocal = end + 1\nnil = local * 2\nfunction = [end, local, nil]\nprint(function)\n"), "[3, 4, 8]\n");
  EXPECT_EQ(line(lua("end = 3\n"), 1), "end_ = 3");
  // Python's non-ASCII names, which Lua has not.
  EXPECT_EQ(run("d\xC3\xA9placement = 2\nprint(d\xC3\xA9placement * 3)\n"), "6\n");
}

TEST(Translate, KeywordsNamedLikeLuaKeywordsStayKeys) {
  EXPECT_EQ(line(lua("X = CMD(end=1, and_=2)\n"), 1), "X = CMD{['end'] = 1, and_ = 2}");
}

TEST(Translate, KeywordUnpackingInCommandCalls) {
  EXPECT_EQ(line(lua("TEST_RESU(**motclf)\n"), 1).substr(line(lua("TEST_RESU(**motclf)\n"), 1).rfind("TEST_RESU")),
            "TEST_RESU(py_kwargs({}, motclf))");
  // The command receives the keywords of the call and of the dict together.
  EXPECT_EQ(run("d = {'A': 1}\nX = CMD(B=2, **d)\nY = _F(**d)\nprint(X['A'] + X['B'], Y['A'])\n"), "3 1\n");
  EXPECT_NE(run("d = {'A': 1}\nX = CMD(A=2, **d)\n").find("multiple values for keyword argument 'A'"), std::string::npos);
  EXPECT_EQ(error("def f(a):\n    return a\nx = f(**d)\n"), "t.comm:3: ** argument unpacking is only supported in command calls");
}

TEST(Translate, CoAndPositionalCalls) {
  EXPECT_EQ(line(lua("MACRO(RESU=CO('R'))\n"), 1), "MACRO{RESU = CO('R')}");
  EXPECT_EQ(line(lua("DETRUIRE(CONCEPT=_F(NOM=(A, B)))\n"), 1), "DETRUIRE{CONCEPT = {NOM = {A, B}}}");
}

TEST(Translate, ListComprehensions) {
  // Python: [0.5, 0.25, 0.125] [1, 9] ['a!', 'b!']
  EXPECT_EQ(run("N = 3\nT = [(1. / 2. ** (i + 1)) for i in range(N)]\nO = [x * x for x in [1, 2, 3] if x % 2 if x > 0]\n"
                "print(T, O, [s + '!' for s in ('a', 'b')])\n"),
            "[0.5, 0.25, 0.125] [1, 9] ['a!', 'b!']\n");
}

TEST(Translate, TableCellsByColumnAndRow) {
  // code_aster's T['PARA', row] counts rows from 1, as aster-lite's TABLE:get.
  EXPECT_EQ(line(lua("v = TAB['VALE_NORM', 1]\n"), 1), "v = TAB:get('VALE_NORM', 1)");
  EXPECT_EQ(error("v = A[:, 0]\n"), "t.comm:1: multi-dimensional indexing is not supported");
}

TEST(Translate, OptionalImportRunsItsHandler) {
  // sympy never exists for a translated study: the except ImportError block is what runs,
  // and the blocks guarded by the flag it sets are kept as comments.
  const std::string src =
      "try:\n"
      "    import sympy\n"
      "    ok = True\n"
      "except ImportError:\n"
      "    ok = False\n"
      "if ok:\n"
      "    X = sympy.symbols('X')\n"
      "else:\n"
      "    X = 'none'\n"
      "print(ok, X)\n";
  EXPECT_EQ(run(src), "False none\n");
  const std::string out = lua(src);
  EXPECT_EQ(line(out, 7), "--     X = sympy.symbols('X')");
  EXPECT_EQ(error("try:\n    x = 1\nexcept:\n    pass\n"), "t.comm:1: try/except is not supported");
  EXPECT_EQ(error("try:\n    import math\nexcept ImportError:\n    pass\n"), "t.comm:1: try/except is not supported");
}

TEST(Translate, NoneSlotsFilledByIndex) {
  EXPECT_EQ(run("M = [None] * 3\nfor i in range(3):\n    M[i] = i * i\nprint(M, len(M))\n"), "[0, 1, 4] 3\n");
}

TEST(Translate, RefusesWhatItCannotTranslateWithFileAndLine) {
  EXPECT_EQ(error("x = 1\nimport numpy as np\n"), "t.comm:2: numpy is not supported");
  EXPECT_EQ(error("import os\n"), "t.comm:1: import of os is not supported (only math and code_aster's commands)");
  EXPECT_EQ(error("\nclass A:\n    pass\n"), "t.comm:2: class definitions are not supported");
  EXPECT_EQ(error("L = [i * j for i in range(3)\n     for j in range(2)]\n"),
            "t.comm:1: list comprehensions with more than one for are not supported");
  EXPECT_EQ(error("try:\n    x = 1\nexcept:\n    pass\n"), "t.comm:1: try/except is not supported");
  EXPECT_EQ(error("INCLUDE(UNITE=91)\n"), "t.comm:1: INCLUDE is not supported");
  EXPECT_EQ(error("EXEC_LOGICIEL(LOGICIEL='ls')\n"), "t.comm:1: EXEC_LOGICIEL is not supported");
  EXPECT_EQ(error("T = TAB.EXTR_TABLE()\n"), "t.comm:1: the method .EXTR_TABLE() is not supported");
  EXPECT_EQ(error("v = R.getValues()\n"), "t.comm:1: the method .getValues() is not supported");
  EXPECT_EQ(error("f = lambda x: x\n"), "t.comm:1: lambda is not supported");
  EXPECT_EQ(error("x = helper(a=1)\n"),
            "t.comm:1: keyword arguments to helper(), which is neither a command nor a function of this file");
  EXPECT_EQ(error("def f():\n    global a\n"), "t.comm:2: global declarations are not supported");
  EXPECT_EQ(error("x = (1 +\n 2j)\n"), "t.comm:2: complex numbers are not supported");
  EXPECT_EQ(error("print 'a'\n"), "t.comm:1: the Python 2 print statement is not supported (print(...) is)");
  EXPECT_EQ(error("x = (1,\n"), "t.comm:1: a bracket opened here is never closed");
  EXPECT_EQ(error("x = 1\n  y = 2\n"), "t.comm:2: unexpected indentation");
  EXPECT_EQ(error("s = 'abc\n"), "t.comm:1: a string literal is never closed on its line");
}

TEST(Translate, DeepNestingIsRefusedNotAStackOverflow) {
  const std::string deep = "x = " + std::string(100000, '(') + "1" + std::string(100000, ')') + "\n";
  EXPECT_NE(error(deep).find("t.comm:1: nesting deeper than"), std::string::npos);
  std::string chain = "x = 1";
  for (int i = 0; i < 100000; ++i) chain += " + 1";
  EXPECT_NE(error(chain + "\n").find("nesting deeper than"), std::string::npos);
  std::string blocks;
  for (int i = 0; i < 5000; ++i) blocks += std::string(i, ' ') + "if x:\n";
  EXPECT_NE(error(blocks).find("nesting deeper than"), std::string::npos);
}

TEST(Translate, NeverThrowsOnAnyPrefixOfAFile) {
  const std::string src =
      "# c\nDEBUT(CODE=_F(NIV_PUB_WEB='INTERNET'))\nL = [1, 2.D0, 'a''b', r'''x\ny''']\n"
      "def f(a, b=(1, 2)):\n    if a: return a % b\n    elif not a: pass\n    else:\n        return [a][-1]\n"
      "for i in range(1, 3, 2):\n    print('%s' % i, '{:3d}'.format(i), L[i:], math.pi)\nFIN()\n";
  for (std::size_t n = 0; n <= src.size(); ++n) {
    const auto t = translateCommandFile(src.substr(0, n), "p.comm");
    EXPECT_TRUE(t.ok || t.error.rfind("p.comm:", 0) == 0) << n << ": " << t.error;
  }
}

TEST(Translate, CommandFileNames) {
  EXPECT_TRUE(aster::comm::isCommandFile("a/ssnp150a.comm"));
  EXPECT_TRUE(aster::comm::isCommandFile("x.com0"));
  EXPECT_TRUE(aster::comm::isCommandFile("x.com9"));
  EXPECT_TRUE(aster::comm::isCommandFile("x.py"));
  EXPECT_FALSE(aster::comm::isCommandFile("x.lua"));
  EXPECT_FALSE(aster::comm::isCommandFile("x.comx"));
  EXPECT_FALSE(aster::comm::isCommandFile("dir.comm/x"));
}

}  // namespace
