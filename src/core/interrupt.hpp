// Ctrl-C (SIGINT) as a polite request: the handler only raises a flag, and the
// program stops at the next safe point (between commands, between Newton
// iterations), after every converged instant is already on disk. A second
// Ctrl-C while the first is pending kills the program at once, as usual.
#pragma once
#include <string>

#include "core/error.hpp"

namespace aster {

namespace interrupt {
void install();    // sets the SIGINT handler (the program calls it once)
bool requested();  // a Ctrl-C arrived and has not been cleared
void clear();      // tests: forget a request
void request();    // tests: as if Ctrl-C had been pressed
}  // namespace interrupt

// Thrown at a safe point after Ctrl-C: the study stops, results stay on disk.
class Interrupted : public Error {
 public:
  explicit Interrupted(const std::string& what) : Error(what) {}
};

}  // namespace aster
