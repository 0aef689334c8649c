// Ctrl-C (SIGINT) as a polite request: the handler only raises a flag, and the
// program stops at the next safe point (between commands, between Newton
// iterations, within a thousand Lua instructions), after every converged instant
// is already on disk. A second Ctrl-C while the first is pending kills the
// program at once, as usual.
#pragma once
#include <string>

#include "core/error.hpp"

namespace aster {

namespace interrupt {
void install();    // sets the SIGINT handler and starts the watchdog (the program calls it once)
bool requested();  // a Ctrl-C arrived and has not been cleared
void clear();      // tests: forget a request
void request();    // tests: as if Ctrl-C had been pressed

// The study's Lua code checks the flag every thousand instructions, but one call
// into a library (string.find with a pathological pattern, a blocking io.read, a
// finalizer, which runs without checks) may never come back. Code of that kind
// runs under Watch(true); code that reaches its safe points runs under
// Watch(false) (commands, concept methods). When a Ctrl-C is still unanswered
// after kWatchdogGrace spent watched, the watchdog thread started by install()
// calls the handler given here (the interpreter: it ends the run and the
// process); without a handler it ends the process with exit status 130.
constexpr double kWatchdogGrace = 0.5;  // seconds
class Watch {
 public:
  explicit Watch(bool watched);
  ~Watch();
  Watch(const Watch&) = delete;
  Watch& operator=(const Watch&) = delete;

 private:
  bool previous_;
};
void setWatchdogHandler(void (*handler)(void* context), void* context);
}  // namespace interrupt

// Thrown at a safe point after Ctrl-C: the study stops, results stay on disk.
class Interrupted : public Error {
 public:
  explicit Interrupted(const std::string& what) : Error(what) {}
};

}  // namespace aster
