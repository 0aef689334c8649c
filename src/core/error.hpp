// Errors raised by kernels and operators. A kernel throws aster::Error with what
// went wrong; the language layer adds the command name and the study's file:line.
#pragma once
#include <stdexcept>
#include <string>

namespace aster {

// A fatal error (<F>): the study stops, results computed so far stay on disk.
class Error : public std::runtime_error {
 public:
  explicit Error(const std::string& what) : std::runtime_error(what) {}
};

}  // namespace aster
