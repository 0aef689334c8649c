// TEST_FONCTION: checks a function's value at given parameters (OK/NOOK).
#include "commands/check_keywords.hpp"
#include "commands/function_concepts.hpp"
#include "core/error.hpp"
#include "core/number_format.hpp"
#include "lang/operators.hpp"
#include "post/check.hpp"

namespace aster::lang {
namespace {

// Python's str of a float (TEST_FONCTION prints the parameter so): lower-case exponent.
std::string pythonStr(double v) {
  std::string s = post::pythonRepr(v);
  for (char& c : s)
    if (c == 'E') c = 'e';
  return s;
}

std::string padded(const std::string& s) { return s.size() >= 16 ? s : s + std::string(16 - s.size(), ' '); }

ConceptPtr testFonction(const Keywords& k, Session& session, ConceptPtr) {
  // code_aster's TEST_FONCTION opens with a blank line and a rule of 80 dashes.
  std::string prefix = "\n" + std::string(80, '-') + "\n";
  for (const auto& occ : k.factor("VALEUR")) {
    const ConceptPtr fc = occ.conceptPtr("FONCTION");
    const auto f = functionOf(fc);
    const auto x = occ.reals("VALE_PARA");
    if (x.size() != f->parameters().size())
      throw Error(occ.path + ": VALE_PARA has " + std::to_string(x.size()) + " value(s) but the function takes " +
                  std::to_string(f->parameters().size()) + " (" + expr::joinNames(f->parameters()) + ")");
    const post::CheckSpec spec = checkSpecOf(occ);
    const auto lines = post::checkFunctionValue(f->evaluate(x.data()), spec);
    bool ok = true;
    for (const auto& l : lines) ok = ok && l.ok();
    // The header names the last parameter (as NOM_PARA gives it; blank without NOM_PARA) and its value.
    const std::string nomPara = occ.has("NOM_PARA") ? occ.texts("NOM_PARA").back() : "";
    const std::string block = prefix + " ---- FONCTION         " + padded(nomPara) + "\n      " +
                              padded(session.nameOf(*fc)) + " " + padded(pythonStr(x.back())) + " \n" +
                              post::formatFunctionLines(lines, spec.legende) + " \n";
    std::vector<CheckRecord> records;
    for (const auto& l : lines)
      records.push_back({l.ok() ? "OK" : "NOOK", l.reference, post::pythonRepr(l.computed), post::pythonRepr(l.expected)});
    appendCheckRecords(session, records);
    session.recordCheck(block, ok);
    prefix.clear();
  }
  return nullptr;
}

RegisterOperator reg("TEST_FONCTION", testFonction);

}  // namespace
}  // namespace aster::lang
