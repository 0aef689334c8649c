// Scratch folders and file contents for tests that write files.
#pragma once
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace aster::test {

// An empty folder <build>/<suite>/<name>, emptied first if an earlier run left it.
inline std::filesystem::path freshDir(const std::string& suite, const std::string& name) {
  const std::filesystem::path dir = std::filesystem::path(ASTER_BINARY_DIR) / suite / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

// The whole content of a file ("" when it cannot be read).
inline std::string readFile(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

}  // namespace aster::test
