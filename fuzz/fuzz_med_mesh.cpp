// libFuzzer target: the MED reader, readMedMesh. Any input must give a mesh or
// an aster::Error; a crash, a sanitizer report, another exception or a hang is
// a finding. HDF5 and the MED library (Debian's, not instrumented) run in the
// reader's child process, whose crashes on damaged files are turned into errors
// by design: what is instrumented is the reader's own code, in the parent and in
// the child. A sanitizer report in the child is passed on to stderr by the
// reader, and the child's sanitizers exit with status 86 here, which the reader
// reports as "ended without a result (exit status 86)": this target aborts on it.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include "core/error.hpp"
#include "mesh/io/med_format.hpp"

extern "C" const char* __asan_default_options() { return "exitcode=86"; }
extern "C" const char* __ubsan_default_options() { return "exitcode=86"; }

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const std::string path = "/tmp/aster-fuzz-med-" + std::to_string(::getpid()) + ".med";
  FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) return 0;
  std::fwrite(data, 1, size, f);
  std::fclose(f);
  try {
    aster::mesh::readMedMesh(path);
  } catch (const aster::Error& e) {
    if (std::strstr(e.what(), "(exit status 86)")) {
      std::fprintf(stderr, "fuzz_med_mesh: a sanitizer report in the MED reading process (above)\n");
      std::abort();
    }
  }
  return 0;
}
