// Files that are either complete or absent: a writer works in a private folder
// beside the target and what it made is renamed into place afterwards, so a
// run that is interrupted or killed never leaves a half-written result.
#pragma once
#include <filesystem>
#include <functional>

namespace aster {

// Runs write(<private folder>/<target file name>) and then renames every file it
// made into the target's folder, the target itself last (a .pvd names its .vtu
// files: they are in place before it is). On failure nothing is renamed and the
// private folder is removed; the error (aster::Error) says what failed.
void writeAtomically(const std::filesystem::path& target,
                     const std::function<void(const std::filesystem::path&)>& write);

}  // namespace aster
