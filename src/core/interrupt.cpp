#include "core/interrupt.hpp"

#include <csignal>

namespace aster::interrupt {
namespace {

volatile std::sig_atomic_t pending = 0;

extern "C" void onSigint(int) {
  pending = 1;
  std::signal(SIGINT, SIG_DFL);  // the next Ctrl-C is not polite any more
}

}  // namespace

void install() {
  // A run that inherited SIGINT ignored (started in the background of a script)
  // keeps ignoring it, as Unix programs do.
  if (std::signal(SIGINT, onSigint) == SIG_IGN) std::signal(SIGINT, SIG_IGN);
}
bool requested() { return pending != 0; }
void clear() { pending = 0; }
void request() { pending = 1; }

}  // namespace aster::interrupt
