#include "comm/translate.hpp"

#include <exception>
#include <vector>

#include "comm/emitter.hpp"
#include "comm/error.hpp"
#include "comm/lexer.hpp"
#include "comm/parser.hpp"

namespace aster::comm {

Translation translateCommandFile(const std::string& text, const std::string& fileName) {
  Translation t;
  std::string body = text;
  if (body.rfind("\xEF\xBB\xBF", 0) == 0) body.erase(0, 3);  // a UTF-8 byte order mark
  std::vector<std::string> lines;
  std::size_t start = 0;
  while (start <= body.size()) {
    std::size_t end = body.find('\n', start);
    if (end == std::string::npos) end = body.size();
    std::string line = body.substr(start, end - start);
    if (!line.empty() && line.back() == '\r') line.pop_back();
    lines.push_back(std::move(line));
    start = end + 1;
  }
  if (lines.size() > 1 && lines.back().empty()) lines.pop_back();  // the text's final line break
  try {
    const LexedFile lexed = lex(body);
    const NodePtr tree = parse(lexed);
    t.lua = emitLua(*tree, lines, lexed.comments);
    t.ok = true;
  } catch (const TranslateError& e) {
    t.line = e.line;
    t.error = fileName + ":" + std::to_string(e.line) + ": " + e.what();
  } catch (const std::exception& e) {
    t.error = fileName + ": the translation failed: " + e.what();
  }
  return t;
}

bool isCommandFile(const std::string& path) {
  const auto slash = path.find_last_of('/');
  const auto dot = path.rfind('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return false;
  const std::string ext = path.substr(dot + 1);
  if (ext == "comm" || ext == "py") return true;
  return ext.size() == 4 && ext.compare(0, 3, "com") == 0 && ext[3] >= '0' && ext[3] <= '9';
}

}  // namespace aster::comm
