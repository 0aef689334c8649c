// libFuzzer target: the GMSH reader path aster-lite owns, i.e. checkMshFile,
// the check every .msh file passes before it reaches the gmsh library, and its
// promise that gmsh never crashes on a file it lets through. Any input must
// either throw aster::Error from the check, or be read by gmsh (readGmshMesh)
// in a child process that ends normally, with a mesh or an error; a crash, a
// sanitizer report, another exception or a hang is a finding.
// gmsh runs in a child because it is Debian's library, not instrumented: it
// leaks what it has read when it gives up on a malformed file, which is not a
// finding; its crashes are (the child dies by a signal and this target aborts),
// and so is a sanitizer report in the child (it exits with a nonzero status),
// or a hang (the child's alarm kills it).
#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "core/error.hpp"
#include "mesh/io/gmsh_format.hpp"
#include "mesh/io/msh_check.hpp"

// The child's time limit, below the -timeout=10 given to libFuzzer (fuzz/CMakeLists.txt).
constexpr unsigned kChildSeconds = 7;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const std::string path = "/tmp/aster-fuzz-gmsh-" + std::to_string(::getpid()) + ".msh";
  FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) return 0;
  std::fwrite(data, 1, size, f);
  std::fclose(f);
  try {
    aster::mesh::checkMshFile(path);
  } catch (const aster::Error&) {
    return 0;
  }
  std::fflush(nullptr);
  const pid_t pid = ::fork();
  if (pid < 0) return 0;
  if (pid == 0) {
    // stderr is kept for sanitizer reports (gmsh prints nothing: General.Terminal = 0).
    const int null = ::open("/dev/null", O_WRONLY);
    if (null >= 0) ::dup2(null, STDOUT_FILENO);
    // libFuzzer's handlers are inherited: a hang must kill the child by SIGALRM
    // (reported below as signal 14), before libFuzzer's -timeout=10 reports the
    // parent as hung in waitpid; Ctrl-C is for the parent.
    std::signal(SIGALRM, SIG_DFL);
    std::signal(SIGINT, SIG_IGN);
    ::alarm(kChildSeconds);
    try {
      aster::mesh::readGmshMesh(path);
    } catch (const aster::Error&) {
    }
    ::_exit(0);
  }
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) return 0;
  }
  if (WIFSIGNALED(status) || WEXITSTATUS(status) != 0) {
    std::fprintf(stderr, "fuzz_gmsh_mesh: reading a file that checkMshFile accepted, gmsh %s %d\n",
                 WIFSIGNALED(status) ? "died of signal" : "exited with status",
                 WIFSIGNALED(status) ? WTERMSIG(status) : WEXITSTATUS(status));
    std::abort();
  }
  return 0;
}
