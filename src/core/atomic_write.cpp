#include "core/atomic_write.hpp"

#include <unistd.h>

#include <algorithm>
#include <string>
#include <vector>

#include "core/error.hpp"

namespace aster {

namespace fs = std::filesystem;

void writeAtomically(const fs::path& target, const std::function<void(const fs::path&)>& write) {
  const fs::path dir = target.has_parent_path() ? target.parent_path() : fs::path(".");
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) throw Error("cannot create the folder " + dir.string() + ": " + ec.message());
  static unsigned counter = 0;
  const fs::path tmp = dir / ("." + target.filename().string() + ".partial-" + std::to_string(::getpid()) + "-" +
                              std::to_string(++counter));
  fs::create_directory(tmp, ec);
  if (ec) throw Error("cannot create the temporary folder " + tmp.string() + ": " + ec.message());
  try {
    write(tmp / target.filename());
    std::vector<fs::path> made;
    for (const auto& e : fs::directory_iterator(tmp)) made.push_back(e.path());
    std::sort(made.begin(), made.end(), [&](const fs::path& a, const fs::path& b) {
      const bool at = a.filename() == target.filename(), bt = b.filename() == target.filename();
      return at != bt ? bt : a < b;
    });
    if (made.empty() || made.back().filename() != target.filename())
      throw Error("internal error: the writer made no file " + target.filename().string());
    for (const auto& p : made) {
      fs::rename(p, dir / p.filename(), ec);
      if (ec) throw Error("cannot move " + p.string() + " to " + (dir / p.filename()).string() + ": " + ec.message());
    }
  } catch (...) {
    std::error_code ignored;
    fs::remove_all(tmp, ignored);
    throw;
  }
  fs::remove_all(tmp, ec);
}

}  // namespace aster
