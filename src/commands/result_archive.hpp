// A result on disk as it is computed: each converged instant of STAT_NON_LINE is
// written at once to <output-dir>/<NAME>_<k>.vtu, then <NAME>.pvd (ParaView's
// collection) is rewritten to list it. Both are renamed into place when
// complete, so after a fatal error, Ctrl-C or even a kill, the .pvd on disk
// lists exactly the converged instants and every file it names is whole.
#pragma once
#include <filesystem>
#include <vector>

#include "commands/result_concepts.hpp"
#include "mesh/io/vtk_format.hpp"

namespace aster::lang {

class ResultArchive {
 public:
  // Removes a collection of that name left by an earlier run first: the .pvd on
  // disk never mixes two runs.
  ResultArchive(const mesh::Mesh& mesh, std::filesystem::path pvd);
  void add(const ResultInstant& instant);
  const std::filesystem::path& path() const { return pvd_; }

 private:
  const mesh::Mesh& mesh_;
  std::filesystem::path pvd_;
  std::vector<mesh::PvdEntry> entries_;
};

}  // namespace aster::lang
