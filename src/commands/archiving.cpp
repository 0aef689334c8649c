#include "commands/archiving.hpp"

#include <algorithm>
#include <cmath>

#include "commands/function_concepts.hpp"

namespace aster::lang {

Archiving::Archiving(const Keywords& k, const std::vector<double>& computed) : keep_(computed.size(), 1) {
  if (k.has("CHAM_EXCLU")) excluded_ = k.texts("CHAM_EXCLU");
  if (k.has("PAS_ARCH")) {
    const long long every = k.integer("PAS_ARCH");
    for (std::size_t i = 0; i < computed.size(); ++i) keep_[i] = i % every == 0;
  } else if (k.has("LIST_INST") || k.has("INST")) {
    const std::vector<double> wanted =
        k.has("INST") ? k.reals("INST") : k.concept<RealListConcept>("LIST_INST")->values;
    const double precision = k.real("PRECISION");
    const bool absolute = k.text("CRITERE") == "ABSOLU";
    std::fill(keep_.begin(), keep_.end(), 0);
    // An instant asked for that is not computed (beyond INST_FIN, say) is not stored.
    for (double t : wanted) {
      const double tol = absolute ? precision : precision * std::fabs(t);
      for (std::size_t i = 0; i < computed.size(); ++i)
        if (std::fabs(computed[i] - t) <= tol) keep_[i] = 1;
    }
  }
  keep_.front() = 1;
  keep_.back() = 1;
}

void Archiving::strip(ResultInstant& instant) const {
  if (excluded_.empty()) return;
  instant.excluded = excluded_;
  auto excluded = [&](const std::string& name) {
    return std::find(excluded_.begin(), excluded_.end(), name) != excluded_.end();
  };
  instant.nodal.erase(std::remove_if(instant.nodal.begin(), instant.nodal.end(),
                                     [&](const mesh::NodalField& f) { return excluded(f.name); }),
                      instant.nodal.end());
  instant.cells.erase(
      std::remove_if(instant.cells.begin(), instant.cells.end(), [&](const CellField& f) { return excluded(f.name); }),
      instant.cells.end());
}

}  // namespace aster::lang
