// Evaluations per second of SSNP150's body force: the FORMULE compiled by
// aster-lite (postfix code evaluated natively) against the same expression as
// a Lua function called through the Lua C API, as a study's FORMULE{VALE =
// function(X, Y) ... end} would be.
#include <lua.hpp>

#include <chrono>
#include <cstdio>

#include "expr/expression.hpp"

namespace {

// SSNP150's body force FX for NU = 0 (sympy, tools/derive_ssnp150b_formulas.py).
const char* kFx =
    "0.0015*X**5*Y-0.00375*X**4*Y+0.648*X**3*Y**5+0.008*X**3*Y**3+0.0075*X**3*Y**2-0.05565*X**3*Y-0.0025*X**3"
    "-0.972*X**2*Y**5-0.012*X**2*Y**3-0.01125*X**2*Y**2+0.087225*X**2*Y+0.00375*X**2+0.168*X*Y**7+0.488*X*Y**5"
    "-0.956*X*Y**4-0.091*X*Y**3-0.093475*X*Y**2+0.52397875*X*Y+0.037625*X-0.084*Y**7-0.082*Y**5+0.478*Y**4"
    "+0.0475*Y**3+0.0486125*Y**2-0.276651875*Y-0.0194375";

double now() { return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count(); }

}  // namespace

int main() {
  const int n = 2000000;
  const auto f = aster::expr::Expression::compile(kFx, {"X", "Y"});
  double sum = 0;
  double t0 = now();
  for (int i = 0; i < n; ++i) {
    const double args[2] = {i * 1e-6, 0.5 - i * 1e-7};
    sum += f->evaluate(args);
  }
  const double compiled = n / (now() - t0);

  lua_State* L = luaL_newstate();
  luaL_openlibs(L);
  std::string chunk = std::string("function fx(X, Y) return ") + kFx + " end";
  for (std::size_t p; (p = chunk.find("**")) != std::string::npos;) chunk.replace(p, 2, "^");
  if (luaL_dostring(L, chunk.c_str()) != LUA_OK) {
    std::fprintf(stderr, "%s\n", lua_tostring(L, -1));
    return 1;
  }
  double sumLua = 0;
  t0 = now();
  for (int i = 0; i < n; ++i) {
    lua_getglobal(L, "fx");
    lua_pushnumber(L, i * 1e-6);
    lua_pushnumber(L, 0.5 - i * 1e-7);
    lua_pcall(L, 2, 1, 0);
    sumLua += lua_tonumber(L, -1);
    lua_pop(L, 1);
  }
  const double lua = n / (now() - t0);
  lua_close(L);
  std::printf("SSNP150 body force FX, %d evaluations\n", n);
  std::printf("  compiled FORMULE : %10.3g evaluations/s\n", compiled);
  std::printf("  Lua function     : %10.3g evaluations/s  (%.1f times slower)\n", lua, compiled / lua);
  std::printf("  same values: %s (sums %.12g and %.12g)\n",
              std::abs(sum - sumLua) <= 1e-9 * std::abs(sum) ? "yes" : "NO", sum, sumLua);
  return 0;
}
