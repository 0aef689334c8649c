// The one way a translation stops: the line of the command file and the reason.
#pragma once
#include <stdexcept>
#include <string>

namespace aster::comm {

struct TranslateError : std::runtime_error {
  TranslateError(int line, const std::string& reason) : std::runtime_error(reason), line(line) {}
  int line;
};

}  // namespace aster::comm
