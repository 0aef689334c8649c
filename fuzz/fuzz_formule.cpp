// libFuzzer target: the FORMULE compiler and evaluator. Input: one byte for
// the parameters (X, Y, INST: 0 to 3 of them), 3 doubles for their values, then
// the formula text. compile() either succeeds or throws aster::Error;
// evaluate() must agree with evaluateChecked() whenever the latter succeeds.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "expr/expression.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 1 + 3 * sizeof(double)) return 0;
  static const char* const names[] = {"X", "Y", "INST"};
  std::vector<std::string> params;
  for (int i = 0; i < (data[0] & 3) && i < 3; ++i) params.push_back(names[i]);
  double args[3];
  std::memcpy(args, data + 1, sizeof args);
  const std::string text(reinterpret_cast<const char*>(data) + 1 + sizeof args, size - 1 - sizeof args);
  std::shared_ptr<aster::expr::Expression> f;
  try {
    f = aster::expr::Expression::compile(text, params);
  } catch (const aster::Error&) {
    return 0;
  }
  const double plain = f->evaluate(args);
  try {
    const double checked = f->evaluateChecked(args);
    if (!(checked == plain || (std::isnan(checked) && std::isnan(plain)))) __builtin_trap();
    if (!std::isfinite(checked)) __builtin_trap();  // checked evaluation returns finite values only
  } catch (const aster::Error&) {
  }
  return 0;
}
