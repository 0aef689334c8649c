// The one generic validator: checks a command call against its catalogue entry
// before any kernel runs, fills the defaults, and types the numbers.
#pragma once
#include <string>

#include "core/error.hpp"
#include "lang/catalogue.hpp"
#include "lang/keywords.hpp"

namespace aster::lang {

// A rejected call. `keyword` is the path of the keyword at fault ("AFFE[2]/MODELISATION"),
// empty when the fault is the call as a whole.
class ValidationError : public Error {
 public:
  ValidationError(std::string keyword, const std::string& what) : Error(what), keyword(std::move(keyword)) {}
  std::string keyword;
};

// Returns the validated tree: every keyword of the catalogue that applies, with
// defaults, numbers typed as the catalogue says. Throws ValidationError.
Keywords validate(const CommandSpec& spec, const Keywords& call);

}  // namespace aster::lang
