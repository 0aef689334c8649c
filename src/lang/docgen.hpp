// docs/commands.md: the command reference, generated from the catalogue.
#pragma once
#include <string>

#include "lang/catalogue.hpp"

namespace aster::lang {

std::string commandReference(const Catalogue& catalogue);

}  // namespace aster::lang
