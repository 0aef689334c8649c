#include "core/messages.hpp"

#include <cstdio>

namespace aster {
namespace {
bool g_quiet = false;
int g_alarms = 0;
const char* tag(Severity s) {
  switch (s) {
    case Severity::Info: return "<I>";
    case Severity::Alarm: return "<A>";
    case Severity::Error: return "<E>";
    case Severity::Fatal: return "<F>";
  }
  return "";
}
}  // namespace

void Messages::info(const std::string& text) {
  if (!g_quiet) std::fprintf(stdout, "%s\n", text.c_str());
}

void Messages::alarm(const std::string& origin, const std::string& text) {
  emit(Severity::Alarm, origin, text);
}

void Messages::emit(Severity s, const std::string& origin, const std::string& text) {
  if (s == Severity::Alarm) ++g_alarms;
  if (s == Severity::Info && g_quiet) return;
  std::FILE* out = (s == Severity::Info) ? stdout : stderr;
  std::fflush(stdout);
  if (origin.empty())
    std::fprintf(out, "%s %s\n", tag(s), text.c_str());
  else
    std::fprintf(out, "%s <%s> %s\n", tag(s), origin.c_str(), text.c_str());
  std::fflush(out);
}

void Messages::setQuiet(bool quiet) { g_quiet = quiet; }
bool Messages::quiet() { return g_quiet; }
int Messages::alarmCount() { return g_alarms; }

}  // namespace aster
