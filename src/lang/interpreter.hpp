// Runs a study: a Lua 5.4 state where every catalogue command is a global
// function, `X = CMD{KEY=value, ...}`, and concepts are typed userdata.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "lang/session.hpp"

namespace aster::lang {

// 128 + SIGINT: what shells and scripts expect of a program stopped by Ctrl-C.
constexpr int kInterruptedStatus = 130;

class Interpreter {
 public:
  explicit Interpreter(Session& session);
  ~Interpreter();
  Interpreter(const Interpreter&) = delete;
  Interpreter& operator=(const Interpreter&) = delete;

  // Exit status as the program returns it: 0 all checks OK, 1 a check NOOK, 2 fatal
  // error, kInterruptedStatus after Ctrl-C. DEBUT and FIN may be omitted. A code_aster
  // command file (.comm, .com0-9, .py) runs as its Lua translation (comm/translate.hpp).
  int runFile(const std::string& path);
  // Runs the files in order, each continuing the one before (POURSUITE): FIN
  // ends one file, the first failure ends the run, the checks cover them all.
  int runFiles(const std::vector<std::string>& paths);
  int runString(const std::string& code, const std::string& chunkName);

  struct State;

 private:
  int finish(int status);
  // Runs `code` under `chunkName`; messages quote the lines of `shown` (the command
  // file a translated chunk comes from).
  int runChunk(const std::string& code, const std::string& chunkName, const std::string& shown);
  std::unique_ptr<State> state_;
  bool moreFilesFollow_ = false;  // runFiles: the run goes on after this file
  Session& session_;
};

}  // namespace aster::lang
