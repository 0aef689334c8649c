#include "expr/real_list.hpp"
#include "core/number_format.hpp"

#include <cmath>
#include <string>

#include "core/error.hpp"
#include "expr/function.hpp"

namespace aster::expr {

std::vector<double> realList(double start, const std::vector<ListInterval>& intervals) {
  if (!std::isfinite(start)) throw Error("DEBUT = " + format::shortest(start) + " is not finite");
  std::vector<double> list{start};
  for (std::size_t k = 0; k < intervals.size(); ++k) {
    const ListInterval& in = intervals[k];
    const std::string which = "INTERVALLE " + std::to_string(k + 1);
    const double from = list.back(), length = in.upTo - from;
    if (!std::isfinite(in.upTo) || !(length > 0))
      throw Error(which + ": JUSQU_A = " + format::shortest(in.upTo) + " must be greater than " +
                  format::shortest(from));
    const bool byCount = in.count != 0, byStep = in.step != 0.0;
    if (byCount == byStep)
      throw Error(which + ": give exactly one of NOMBRE and PAS");
    long steps = 0;
    if (byCount) {
      if (in.count < 1) throw Error(which + ": NOMBRE = " + std::to_string(in.count) + " must be >= 1");
      steps = in.count;
    } else {
      if (!(in.step > 0)) throw Error(which + ": PAS = " + format::shortest(in.step) + " must be positive");
      const double ratio = length / in.step;
      steps = std::lround(ratio);
      if (steps < 1 || std::abs(steps * in.step - length) > 1e-6 * length)
        throw Error(which + ": PAS = " + format::shortest(in.step) + " does not divide [" +
                    format::shortest(from) + ", " + format::shortest(in.upTo) + "] (" + format::shortest(ratio) +
                    " steps)");
    }
    for (long i = 1; i < steps; ++i) list.push_back(from + length * (double(i) / double(steps)));
    list.push_back(in.upTo);
  }
  return list;
}

}  // namespace aster::expr
