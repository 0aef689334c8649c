#include "commands/result_archive.hpp"

#include <cctype>

#include "commands/field_output.hpp"
#include "core/error.hpp"
#include "core/messages.hpp"

namespace aster::lang {

namespace fs = std::filesystem;

namespace {

// "RESU-2" -> true: the name of a later result of that name in one run.
bool hasRunSuffix(const std::string& stem) {
  const auto dash = stem.rfind('-');
  if (dash == std::string::npos || dash + 1 == stem.size()) return false;
  for (std::size_t i = dash + 1; i < stem.size(); ++i)
    if (!std::isdigit(static_cast<unsigned char>(stem[i]))) return false;
  return true;
}

// "<stem>-<n><rest>" with n a number.
bool isLaterOf(const std::string& name, const std::string& stem, std::string& rest) {
  if (name.compare(0, stem.size() + 1, stem + "-") != 0) return false;
  std::size_t i = stem.size() + 1;
  const std::size_t digits = i;
  while (i < name.size() && std::isdigit(static_cast<unsigned char>(name[i]))) ++i;
  if (i == digits) return false;
  rest = name.substr(i);
  return true;
}

}  // namespace

ResultArchive::ResultArchive(const mesh::Mesh& mesh, fs::path pvd, RunFiles* files, std::string command)
    : mesh_(mesh), pvd_(std::move(pvd)), files_(files), command_(std::move(command)) {
  const fs::path folder = pvd_.parent_path();
  const std::string stem = pvd_.stem().string();
  if (files_) {
    // Another command of this run wrote that .pvd (or one of its .vtu), or the
    // study read it: take the next free name.
    auto taken = [&](const std::string& name) {
      bool found = false;
      std::error_code ec;
      for (fs::directory_iterator it(folder, ec), end; !ec && it != end && !found; it.increment(ec)) {
        const std::string f = it->path().filename().string();
        if (isNumberedFile(f, name, ".vtu") && (files_->written(it->path()) || !files_->inputOf(it->path()).empty()))
          found = true;
      }
      return found;
    };
    pvd_ = files_->fresh(folder, stem, ".pvd", taken);
  }
  // What an earlier run left under these names: the .pvd first, so that no
  // collection ever lists a file that is gone.
  const std::string name = pvd_.stem().string();
  const bool first = !hasRunSuffix(name);
  RunFiles none;
  const RunFiles& guard = files_ ? *files_ : none;
  auto removed = guard.removeStale(folder, [&](const std::string& f) {
    std::string rest;
    return f == name + ".pvd" || (first && isLaterOf(f, name, rest) && rest == ".pvd");
  });
  for (const auto& f : guard.removeStale(folder, [&](const std::string& f) {
         std::string rest;
         if (isNumberedFile(f, name, ".vtu")) return true;
         if (!first || !isLaterOf(f, name, rest)) return false;
         return isNumberedFile("x" + rest, "x", ".vtu");
       }))
    removed.push_back(f);
  if (fs::exists(pvd_)) throw Error("cannot replace the result file " + pvd_.string());
  if (!removed.empty()) {
    std::string list;
    for (std::size_t i = 0; i < removed.size() && i < 3; ++i) list += (i ? ", " : "") + removed[i];
    if (removed.size() > 3) list += ", ...";
    Messages::info(command_ + ": " + std::to_string(removed.size()) + " file(s) an earlier run wrote for " + name +
                   " removed from " + folder.string() + " (" + list + ")");
  }
}

std::string ResultArchive::storedNote(const std::string& when) const {
  return "; " + std::to_string(stored()) + " instant(s) were stored " + when + ", in " + pvd_.string();
}

void ResultArchive::add(const ResultInstant& instant) {
  const fs::path vtu = pvd_.parent_path() / (pvd_.stem().string() + "_" + std::to_string(instant.index) + ".vtu");
  std::vector<mesh::CellValues> cellFields;
  for (const auto& c : instant.cells) {
    cellFields.push_back(cellValuesOf(mesh_, c));
    nameInternalVariables(c.name, cellFields.back().components, variableNames_);
  }
  writeAtomically(vtu, [&](const fs::path& tmp) { mesh::writeVtu(mesh_, tmp.string(), instant.nodal, cellFields); },
                  files_);
  entries_.push_back({instant.time, vtu.filename().string()});
  try {
    writeAtomically(pvd_, [&](const fs::path& tmp) { mesh::writePvdCollection(tmp.string(), entries_); }, files_);
  } catch (...) {
    // The .pvd on disk lists the earlier instants: this one's file goes too.
    entries_.pop_back();
    std::error_code ec;
    fs::remove(vtu, ec);
    throw;
  }
}

}  // namespace aster::lang
