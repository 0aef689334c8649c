// One instance of Debian's sequential MUMPS in a given arithmetic (DMUMPS_STRUC_C with
// dmumps_c, SMUMPS_STRUC_C with smumps_c): its control and information arrays by MUMPS's
// own 1-based numbers, started with SYM fixed for its life, ended (JOB = -2) with it.
// Included by the .cpp files only, after the arithmetic's MUMPS header.
#pragma once
#include <string>

namespace aster::linalg {

template <class Struc, void (*Call)(Struc*)>
struct MumpsInstance {
  Struc id{};
  bool started = false;

  int icntl(int i) const { return id.icntl[i - 1]; }
  int& icntl(int i) { return id.icntl[i - 1]; }
  int infog(int i) const { return id.infog[i - 1]; }
  auto rinfog(int i) const { return id.rinfog[i - 1]; }
  void run(int job) {
    id.job = job;
    Call(&id);
  }
  // A new instance (JOB = -1) on one process, the host working; INFOG(1) < 0 if it failed.
  void start(int sym) {
    stop();
    id = Struc{};
    id.comm_fortran = -987654;  // MUMPS's code for MPI_COMM_WORLD (the sequential stand-in)
    id.par = 1;
    id.sym = sym;
    run(-1);
    started = true;
  }
  void stop() {
    if (started) run(-2);
    started = false;
  }
  ~MumpsInstance() { stop(); }
};

// The name of the ordering MUMPS used (INFOG(7)).
inline std::string mumpsOrderingName(int icntl7) {
  switch (icntl7) {
    case 0: return "AMD";
    case 2: return "AMF";
    case 3: return "SCOTCH";
    case 4: return "PORD";
    case 5: return "METIS";
    case 6: return "QAMD";
    default: return "other";
  }
}

}  // namespace aster::linalg
