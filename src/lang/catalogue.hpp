// The command catalogue: each command's syntax as data, read from the
// declarative files commands/<COMMAND>.lua (see docs/catalogue.md).
#pragma once
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "lang/catalogue_sources.hpp"
#include "lang/value.hpp"

namespace aster::lang {

// code_aster's "regles": constraints among the keywords of one level.
struct Rule {
  enum class Kind { UnParmi, Exclus, AuMoinsUn, AuPlusUn, PresentPresent, PresentAbsent, Ensemble };
  Kind kind;
  std::vector<std::string> keys;
  std::string describe() const;  // e.g. "UN_PARMI('TOUT', 'GROUP_MA')"
};

struct KeywordSpec {
  enum class Kind { Simple, Factor, Block };
  Kind kind = Kind::Simple;
  std::string name;
  std::string doc;
  // statut: 'o' mandatory, 'f' optional, 'd' (factor only) optional but one
  // occurrence with its defaults is created when absent.
  char statut = 'f';
  // Accepted and ignored (simple and factor keywords): the reason it changes no
  // result. The validator checks the value as declared, then drops the keyword,
  // so no operator ever reads it. Empty: a keyword like any other.
  std::string ignored;

  // Simple keywords.
  std::vector<std::string> types;  // 'R', 'I', 'TXM', 'grma', 'grno', 'CO', 'lua_function', concept type names
  std::vector<Value> defaults;
  std::vector<Value> into;
  int min = 1, max = 1;  // number of values; max -1: unlimited ('**')
  bool hasValMin = false, hasValMax = false;
  double valMin = 0, valMax = 0;

  // Factor keywords: occurrences. Factor keywords and blocks: content.
  int minOcc = 0, maxOcc = 1;
  std::vector<Rule> rules;
  std::vector<KeywordSpec> children;

  // Blocks: active when every condition holds. A condition on KEY with values
  // holds when KEY's value is one of them; with no values, when KEY is present.
  std::vector<std::pair<std::string, std::vector<Value>>> condition;
  std::vector<std::string> absent;  // and when these keys are absent
  std::string describeCondition() const;

  bool mandatory() const { return statut == 'o'; }
};

struct CommandSpec {
  enum class Kind { Oper, Proc, Macro };
  Kind kind = Kind::Proc;
  std::string name;
  std::string doc;
  std::vector<std::string> results;  // concept types it may return (empty for a PROC)
  char reentrant = 'n';              // 'n' no reuse, 'o' reuse required, 'f' reuse allowed
  std::vector<Rule> rules;
  std::vector<KeywordSpec> children;
  // autres_mots_cles: the keywords not declared above, when the command takes them
  // (FORMULE's names passed to the expression). Each must be named like an
  // identifier and hold one value of others->types; the validator gathers them in
  // one occurrence of a factor keyword named others->name.
  std::optional<KeywordSpec> others;
};

class Catalogue {
 public:
  // The catalogue compiled into the program (loaded once).
  static const Catalogue& builtin();
  // Reads catalogue files, each after the common groups (commands/commons/);
  // throws aster::Error naming the file on a bad entry.
  static Catalogue fromSources(const std::vector<CatalogueSource>& sources,
                               const std::vector<CatalogueSource>& commons = {});

  const CommandSpec* find(const std::string& name) const;
  const std::map<std::string, CommandSpec>& commands() const { return commands_; }
  std::vector<std::string> names() const;

 private:
  std::map<std::string, CommandSpec> commands_;
};

// Human wording of a keyword type for messages and docs: "a real", "a maillage_sdaster".
std::string describeType(const std::string& type);
std::string describeTypes(const std::vector<std::string>& types);

}  // namespace aster::lang
