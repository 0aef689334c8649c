// ARCHIVAGE of STAT_NON_LINE: which converged instants enter the result, and which fields
// they hold. The initial state and the last instant computed are always stored; with
// LIST_INST or INST only those instants besides (looked up with CRITERE and PRECISION),
// with PAS_ARCH every PAS_ARCH-th instant of the list computed; CHAM_EXCLU names fields
// stored at no instant.
#pragma once
#include <string>
#include <vector>

#include "commands/result_concepts.hpp"
#include "lang/keywords.hpp"

namespace aster::lang {

class Archiving {
 public:
  // `archivage`: the ARCHIVAGE occurrence; `computed`: the instants of the run, the initial one first.
  Archiving(const Keywords& archivage, const std::vector<double>& computed);

  // The computed instant of index `step` (1 for the first after the initial one) is stored.
  bool stored(std::size_t step) const { return keep_[step] != 0; }
  // Removes the excluded fields from an instant about to be stored.
  void strip(ResultInstant& instant) const;
  const std::vector<std::string>& excluded() const { return excluded_; }

 private:
  std::vector<char> keep_;  // per computed instant
  std::vector<std::string> excluded_;
};

}  // namespace aster::lang
