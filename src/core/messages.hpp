// Messages in code_aster's habit: <F> fatal, <E> error, <A> alarm, <I> info.
#pragma once
#include <string>

namespace aster {

enum class Severity { Info, Alarm, Error, Fatal };

// Where messages go. Kernels print progress through this so that --quiet works.
class Messages {
 public:
  static void info(const std::string& text);  // silenced by --quiet
  static void alarm(const std::string& origin, const std::string& text);
  static void emit(Severity s, const std::string& origin, const std::string& text);
  static void setQuiet(bool quiet);
  static bool quiet();
  static int alarmCount();
};

}  // namespace aster
