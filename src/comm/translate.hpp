// code_aster command files (Python syntax) to aster-lite Lua studies, line for line.
#pragma once
#include <string>

namespace aster::comm {

struct Translation {
  bool ok = false;
  std::string lua;    // the study, when ok: Lua line N is the command file's line N
  std::string error;  // otherwise "file:line: reason"
  int line = 0;
};

// Never throws: what cannot be translated comes back as the error.
Translation translateCommandFile(const std::string& text, const std::string& fileName);

// .comm, .com0 to .com9 and .py: the names code_aster gives command files.
bool isCommandFile(const std::string& path);

}  // namespace aster::comm
