// The keywords every TEST_* command shares (C_TEST_REFERENCE: VALE_CALC[_I],
// VALE_REFE[_I], REFERENCE, PRECISION, CRITERE, TOLE_MACHINE, ORDRE_GRANDEUR,
// VALE_ABS, LEGENDE), read into a CheckSpec.
#pragma once
#include <string>
#include <utility>
#include <vector>

#include "lang/keywords.hpp"
#include "lang/session.hpp"
#include "post/check.hpp"

namespace aster::lang {

post::CheckSpec checkSpecOf(const Keywords& k);

// TEST_RESU's RESU: TOLE_MACHINE and CRITERE's second values (or their only one),
// with which INST is found in the result.
struct InstantLookup {
  double precision = 1e-6;
  std::string criterion = "RELATIF";
};
InstantLookup instantLookupOf(const Keywords& k);

using CheckWhat = std::vector<std::pair<std::string, std::string>>;

// Runs the comparison, prints and records it (header, result lines and the blank
// line code_aster writes after each check); `what` describes the tested quantity,
// `prefix` goes before the header.
void recordCheck(Session& session, double computed, const post::CheckSpec& spec, const CheckWhat& what,
                 bool headerLeadingBlank = true, const std::string& prefix = "");

// The same with the header written by the caller (`origin` names the check in alarms).
void recordCheckLines(Session& session, double computed, const post::CheckSpec& spec, const std::string& header,
                      const std::string& origin);

// One comparison for <output>/<study>.checks, the machine-readable record of the
// checks: one line per comparison, fields separated by tabs:
//   OK|NOOK|SKIP  command  file:line  reference  computed  expected
// (reference: NON_REGRESSION, ANALYTIQUE, ...; values as in the .resu).
struct CheckRecord {
  std::string diag, reference, computed, expected;
};
void appendCheckRecords(Session& session, const std::vector<CheckRecord>& records);

}  // namespace aster::lang
