// A result on disk as it is computed: each converged instant of STAT_NON_LINE (and
// each instant of a MECA_STATIQUE of several) is written at once to
// <output-dir>/<NAME>_<k>.vtu (its nodal fields as point data, its cell fields as
// cell data: writeVtu), then <NAME>.pvd (ParaView's
// collection) is rewritten to list it. Both are renamed into place when
// complete, so after a fatal error, Ctrl-C or even a kill, the .pvd on disk
// lists exactly the converged instants and every file it names is whole. A
// write that fails (full disk) leaves the files of the earlier instants as they
// were and no file the .pvd does not list.
#pragma once
#include <filesystem>
#include <string>
#include <vector>

#include "commands/result_concepts.hpp"
#include "core/atomic_write.hpp"
#include "mesh/io/vtk_format.hpp"

namespace aster::lang {

class ResultArchive {
 public:
  // Removes what an earlier run left under this name first (<NAME>.pvd and
  // <NAME>_<k>.vtu; for a first result of its name also <NAME>-<n>.pvd and
  // <NAME>-<n>_<k>.vtu, the names of later results of that name), so that the
  // folder never mixes two runs. With `files`, never an input of the study nor a
  // file this run wrote: a .pvd of that name written by another command of the
  // run makes the archive take the next free name (path() says which).
  // `command` names the operator in the messages.
  ResultArchive(const mesh::Mesh& mesh, std::filesystem::path pvd, RunFiles* files = nullptr,
                std::string command = "STAT_NON_LINE");
  // On failure (aster::Error, naming the file and the system's reason) the
  // instant is not on disk and the .pvd still lists the earlier ones.
  void add(const ResultInstant& instant);
  const std::filesystem::path& path() const { return pvd_; }
  // The laws' names of the internal variables, given to the VARI components in the files.
  void setVariableNames(std::vector<std::string> names) { variableNames_ = std::move(names); }
  // The instants on disk, listed by the .pvd.
  std::size_t stored() const { return entries_.size(); }
  // "; N instant(s) were stored <when>, in <pvd>": what a fatal error adds.
  std::string storedNote(const std::string& when) const;

 private:
  const mesh::Mesh& mesh_;
  std::filesystem::path pvd_;
  RunFiles* files_;
  std::string command_;
  std::vector<mesh::PvdEntry> entries_;
  std::vector<std::string> variableNames_;
};

}  // namespace aster::lang
