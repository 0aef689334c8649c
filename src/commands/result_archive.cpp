#include "commands/result_archive.hpp"

#include "core/atomic_write.hpp"
#include "core/error.hpp"

namespace aster::lang {

namespace fs = std::filesystem;

ResultArchive::ResultArchive(const mesh::Mesh& mesh, fs::path pvd) : mesh_(mesh), pvd_(std::move(pvd)) {
  std::error_code ec;
  fs::remove(pvd_, ec);
  if (ec) throw Error("cannot replace the result file " + pvd_.string() + ": " + ec.message());
}

void ResultArchive::add(const ResultInstant& instant) {
  const fs::path vtu = pvd_.parent_path() / (pvd_.stem().string() + "_" + std::to_string(instant.index) + ".vtu");
  writeAtomically(vtu, [&](const fs::path& tmp) { mesh::writeVtu(mesh_, tmp.string(), instant.nodal); });
  entries_.push_back({instant.time, vtu.filename().string()});
  writeAtomically(pvd_, [&](const fs::path& tmp) { mesh::writePvdCollection(tmp.string(), entries_); });
}

}  // namespace aster::lang
