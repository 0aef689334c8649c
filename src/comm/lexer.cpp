#include "comm/lexer.hpp"

#include <cctype>
#include <cerrno>
#include <cstring>
#include <cstdint>
#include <cstdlib>

#include "comm/error.hpp"

namespace aster::comm {
namespace {

bool isNameStart(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_' || (c & 0x80); }
bool isNameChar(char c) { return isNameStart(c) || std::isdigit(static_cast<unsigned char>(c)); }

void appendUtf8(std::string& out, std::uint32_t cp) {
  if (cp < 0x80) {
    out += static_cast<char>(cp);
  } else if (cp < 0x800) {
    out += static_cast<char>(0xC0 | (cp >> 6));
    out += static_cast<char>(0x80 | (cp & 0x3F));
  } else if (cp < 0x10000) {
    out += static_cast<char>(0xE0 | (cp >> 12));
    out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (cp & 0x3F));
  } else {
    out += static_cast<char>(0xF0 | (cp >> 18));
    out += static_cast<char>(0x80 | ((cp >> 12) & 0x3F));
    out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (cp & 0x3F));
  }
}

// Longest first: the operators and delimiters of the subset (and a few refused later).
const char* const kOperators[] = {"**=", "//=", ">>=", "<<=", "...", "->", ":=", "**", "//", "==", "!=", "<=",
                                  ">=", "+=", "-=", "*=", "/=", "%=", "&=", "|=", "^=", "<<", ">>", "+",
                                  "-", "*", "/", "%", "<", ">", "=", "(", ")", "[", "]", "{", "}", ",",
                                  ":", ".", ";", "@", "&", "|", "^", "~"};

class Lexer {
 public:
  explicit Lexer(const std::string& text) : s_(text) {}

  LexedFile run() {
    indents_.push_back(0);
    atLineStart_ = true;
    while (pos_ < s_.size()) {
      if (atLineStart_ && depth_ == 0) {
        if (!indentation()) continue;
      }
      atLineStart_ = false;  // a line continued inside brackets has no indentation of its own
      const char c = s_[pos_];
      if (c == '\n') {
        if (depth_ == 0 && !out_.tokens.empty() && out_.tokens.back().kind != Token::Kind::Newline)
          push(Token::Kind::Newline, "");
        ++pos_;
        ++line_;
        atLineStart_ = true;
        continue;
      }
      if (c == ' ' || c == '\t' || c == '\f' || c == '\r') {
        ++pos_;
        continue;
      }
      if (c == '#') {
        comment();
        continue;
      }
      if (c == '\\') {
        std::size_t p = pos_ + 1;
        while (p < s_.size() && s_[p] == '\r') ++p;
        if (p < s_.size() && s_[p] == '\n') {
          pos_ = p + 1;
          ++line_;
          continue;
        }
        throw TranslateError(line_, "a backslash outside a string must end the line");
      }
      if (isNameStart(c)) {
        nameOrString();
        continue;
      }
      if (std::isdigit(static_cast<unsigned char>(c)) ||
          (c == '.' && pos_ + 1 < s_.size() && std::isdigit(static_cast<unsigned char>(s_[pos_ + 1])))) {
        number();
        continue;
      }
      if (c == '\'' || c == '"') {
        string("", line_);
        continue;
      }
      op();
    }
    if (depth_ > 0) throw TranslateError(openLine_, "a bracket opened here is never closed");
    if (!out_.tokens.empty() && out_.tokens.back().kind != Token::Kind::Newline) push(Token::Kind::Newline, "");
    while (indents_.size() > 1) {
      indents_.pop_back();
      push(Token::Kind::Dedent, "");
    }
    push(Token::Kind::End, "");
    return std::move(out_);
  }

 private:
  // Measures the indentation of a logical line; false when the line is blank or a comment.
  bool indentation() {
    int width = 0;
    std::size_t p = pos_;
    while (p < s_.size() && (s_[p] == ' ' || s_[p] == '\t' || s_[p] == '\f')) {
      width = s_[p] == '\t' ? (width / 8 + 1) * 8 : width + 1;
      ++p;
    }
    std::size_t q = p;
    while (q < s_.size() && s_[q] == '\r') ++q;
    if (q >= s_.size() || s_[q] == '\n' || s_[q] == '#') {
      pos_ = q;  // blank or comment line: no structure
      if (q < s_.size() && s_[q] == '#') comment();
      if (pos_ < s_.size() && s_[pos_] == '\n') {
        ++pos_;
        ++line_;
      }
      return false;
    }
    pos_ = p;
    atLineStart_ = false;
    if (width > indents_.back()) {
      indents_.push_back(width);
      push(Token::Kind::Indent, "");
    } else {
      while (width < indents_.back()) {
        indents_.pop_back();
        push(Token::Kind::Dedent, "");
      }
      if (width != indents_.back()) throw TranslateError(line_, "the indentation matches no outer block");
    }
    return true;
  }

  void comment() {
    std::size_t e = s_.find('\n', pos_);
    if (e == std::string::npos) e = s_.size();
    std::string text = s_.substr(pos_ + 1, e - pos_ - 1);
    while (!text.empty() && (text.back() == '\r' || text.back() == ' ')) text.pop_back();
    out_.comments[line_] = text;
    pos_ = e;
  }

  void push(Token::Kind kind, std::string text) {
    Token t;
    t.kind = kind;
    t.text = std::move(text);
    t.line = line_;
    out_.tokens.push_back(std::move(t));
  }

  void nameOrString() {
    std::size_t p = pos_;
    while (p < s_.size() && isNameChar(s_[p])) ++p;
    std::string word = s_.substr(pos_, p - pos_);
    if (p < s_.size() && (s_[p] == '\'' || s_[p] == '"') && word.size() <= 2) {
      std::string lower;
      for (char ch : word) lower += static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
      if (lower == "r" || lower == "b" || lower == "u" || lower == "f" || lower == "rb" || lower == "br" ||
          lower == "fr" || lower == "rf") {
        const int line = line_;
        pos_ = p;
        string(lower, line);
        return;
      }
    }
    pos_ = p;
    push(Token::Kind::Name, word);
  }

  void number() {
    const int line = line_;
    std::size_t p = pos_;
    std::string digits;
    bool isFloat = false;
    if (s_[p] == '0' && p + 1 < s_.size() && std::strchr("xXoObB", s_[p + 1])) {
      const char base = static_cast<char>(std::tolower(static_cast<unsigned char>(s_[p + 1])));
      p += 2;
      while (p < s_.size() && (std::isxdigit(static_cast<unsigned char>(s_[p])) || s_[p] == '_')) {
        if (s_[p] != '_') digits += s_[p];
        ++p;
      }
      const int radix = base == 'x' ? 16 : base == 'o' ? 8 : 2;
      char* end = nullptr;
      errno = 0;
      const unsigned long long v = std::strtoull(digits.c_str(), &end, radix);
      if (digits.empty() || *end || errno == ERANGE || v > 0x7fffffffffffffffULL)
        throw TranslateError(line, "the number 0" + std::string(1, base) + digits + " is not an integer aster-lite reads");
      pos_ = p;
      pushNumber(std::to_string(v), false, line);
      return;
    }
    auto run = [&] {
      while (p < s_.size() && (std::isdigit(static_cast<unsigned char>(s_[p])) || s_[p] == '_')) {
        if (s_[p] != '_') digits += s_[p];
        ++p;
      }
    };
    run();
    if (digits.empty()) digits = "0";
    if (p < s_.size() && s_[p] == '.') {
      isFloat = true;
      digits += '.';
      ++p;
      const std::size_t before = digits.size();
      run();
      if (digits.size() == before) digits += '0';
    }
    if (p < s_.size() && std::strchr("eEdD", s_[p])) {
      std::size_t q = p + 1;
      if (q < s_.size() && (s_[q] == '+' || s_[q] == '-')) ++q;
      if (q < s_.size() && std::isdigit(static_cast<unsigned char>(s_[q]))) {
        isFloat = true;
        digits += 'e';
        digits.append(s_, p + 1, q - p - 1);
        p = q;
        run();
      }
    }
    if (p < s_.size() && (s_[p] == 'j' || s_[p] == 'J'))
      throw TranslateError(line, "complex numbers are not supported");
    if (p < s_.size() && isNameChar(s_[p]))
      throw TranslateError(line, "a number runs into the name after it ('" + s_.substr(pos_, p - pos_ + 1) + "')");
    if (!isFloat) {
      while (digits.size() > 1 && digits[0] == '0') digits.erase(0, 1);
      if (digits.size() > 19 || (digits.size() == 19 && digits > "9223372036854775807")) {
        digits += ".0";  // Python's integers are unbounded; beyond 64 bits a float is the nearest
        isFloat = true;
      }
    }
    pos_ = p;
    pushNumber(digits, isFloat, line);
  }

  void pushNumber(std::string text, bool isFloat, int line) {
    Token t;
    t.kind = Token::Kind::Number;
    t.text = std::move(text);
    t.isFloat = isFloat;
    t.line = line;
    out_.tokens.push_back(std::move(t));
  }

  void string(const std::string& prefix, int line) {
    if (prefix.find('f') != std::string::npos) throw TranslateError(line, "f-strings are not supported");
    const bool raw = prefix.find('r') != std::string::npos;
    const char q = s_[pos_];
    const bool triple = pos_ + 2 < s_.size() && s_[pos_ + 1] == q && s_[pos_ + 2] == q;
    pos_ += triple ? 3 : 1;
    std::vector<StringPiece> pieces{{"", line_}};
    std::string whole;
    auto add = [&](const std::string& t) {
      pieces.back().text += t;
      whole += t;
    };
    for (;;) {
      if (pos_ >= s_.size()) throw TranslateError(line, "a string literal is never closed");
      const char c = s_[pos_];
      if (c == q && (!triple || (pos_ + 2 < s_.size() && s_[pos_ + 1] == q && s_[pos_ + 2] == q))) {
        pos_ += triple ? 3 : 1;
        break;
      }
      if (c == '\n') {
        if (!triple) throw TranslateError(line, "a string literal is never closed on its line");
        add("\n");
        ++pos_;
        ++line_;
        pieces.push_back({"", line_});
        continue;
      }
      if (c == '\r' && pos_ + 1 < s_.size() && s_[pos_ + 1] == '\n') {
        ++pos_;  // CRLF files: the line break is the \n
        continue;
      }
      if (c != '\\') {
        add(std::string(1, c));
        ++pos_;
        continue;
      }
      if (pos_ + 1 >= s_.size()) throw TranslateError(line, "a string literal is never closed");
      const char e = s_[pos_ + 1];
      if (e == '\n' || (e == '\r' && pos_ + 2 < s_.size() && s_[pos_ + 2] == '\n')) {
        pos_ += e == '\n' ? 2 : 3;
        if (raw) add("\\\n");
        ++line_;
        pieces.push_back({"", line_});
        continue;
      }
      if (raw) {
        add(std::string{'\\', e});
        pos_ += 2;
        continue;
      }
      pos_ += 2;
      switch (e) {
        case 'n': add("\n"); break;
        case 't': add("\t"); break;
        case 'r': add("\r"); break;
        case '0': case '1': case '2': case '3': case '4': case '5': case '6': case '7': {
          int v = e - '0';
          for (int k = 0; k < 2 && pos_ < s_.size() && s_[pos_] >= '0' && s_[pos_] <= '7'; ++k) v = v * 8 + (s_[pos_++] - '0');
          add(std::string(1, static_cast<char>(v & 0xFF)));
          break;
        }
        case 'a': add("\a"); break;
        case 'b': add("\b"); break;
        case 'f': add("\f"); break;
        case 'v': add("\v"); break;
        case '\\': add("\\"); break;
        case '\'': add("'"); break;
        case '"': add("\""); break;
        case 'x': case 'u': case 'U': {
          const int n = e == 'x' ? 2 : e == 'u' ? 4 : 8;
          std::uint32_t cp = 0;
          for (int k = 0; k < n; ++k) {
            if (pos_ >= s_.size() || !std::isxdigit(static_cast<unsigned char>(s_[pos_])))
              throw TranslateError(line, std::string("a \\") + e + " escape needs " + std::to_string(n) + " hex digits");
            const char h = s_[pos_++];
            cp = cp * 16 + static_cast<std::uint32_t>(std::isdigit(static_cast<unsigned char>(h)) ? h - '0' : (std::tolower(h) - 'a' + 10));
          }
          if (cp > 0x10FFFF) throw TranslateError(line, "a \\U escape beyond Unicode");
          std::string t;
          if (e == 'x' && prefix.find('b') != std::string::npos) t = std::string(1, static_cast<char>(cp));
          else appendUtf8(t, cp);
          add(t);
          break;
        }
        case 'N': throw TranslateError(line, "\\N{...} escapes are not supported");
        default: add(std::string{'\\', e}); break;
      }
    }
    // Adjacent literals are one string ('a' 'b' is 'ab').
    if (!out_.tokens.empty() && out_.tokens.back().kind == Token::Kind::String) {
      Token& prev = out_.tokens.back();
      prev.text += whole;
      for (auto& piece : pieces) {
        if (piece.line == prev.pieces.back().line) prev.pieces.back().text += piece.text;
        else prev.pieces.push_back(std::move(piece));
      }
      return;
    }
    Token t;
    t.kind = Token::Kind::String;
    t.text = std::move(whole);
    t.line = line;
    t.pieces = std::move(pieces);
    out_.tokens.push_back(std::move(t));
  }

  void op() {
    for (const char* o : kOperators) {
      const std::size_t n = std::strlen(o);
      if (s_.compare(pos_, n, o) == 0) {
        const std::string text(o);
        if (text == "(" || text == "[" || text == "{") {
          if (depth_ == 0) openLine_ = line_;
          ++depth_;
        } else if (text == ")" || text == "]" || text == "}") {
          if (depth_ == 0) throw TranslateError(line_, "'" + text + "' closes no bracket");
          --depth_;
        }
        pos_ += n;
        push(Token::Kind::Op, text);
        return;
      }
    }
    throw TranslateError(line_, std::string("unexpected character '") + s_[pos_] + "'");
  }

  const std::string& s_;
  std::size_t pos_ = 0;
  int line_ = 1;
  int depth_ = 0;
  int openLine_ = 1;
  bool atLineStart_ = true;
  std::vector<int> indents_;
  LexedFile out_;
};

}  // namespace

LexedFile lex(const std::string& text) { return Lexer(text).run(); }

}  // namespace aster::comm
