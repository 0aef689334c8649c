#include "lang/docgen.hpp"

#include <sstream>

namespace aster::lang {
namespace {

std::string values(const std::vector<Value>& vals) {
  std::string s;
  for (std::size_t i = 0; i < vals.size(); ++i) s += (i ? ", " : "") + vals[i].describe();
  return s;
}

std::string countText(int min, int max) {
  if (min == 1 && max == 1) return "";
  return " (" + std::to_string(min) + ".." + (max < 0 ? std::string("n") : std::to_string(max)) + " values)";
}

void rulesText(std::ostringstream& out, const std::vector<Rule>& rules, const std::string& indent) {
  for (const auto& r : rules) out << indent << "- rule `" << r.describe() << "`\n";
}

void keywordsText(std::ostringstream& out, const std::vector<KeywordSpec>& specs, const std::string& indent) {
  for (const auto& k : specs) {
    const char* statut = k.statut == 'o' ? "mandatory" : "optional";
    switch (k.kind) {
      case KeywordSpec::Kind::Simple:
        out << indent << "- `" << k.name << "` — " << statut << ", " << describeTypes(k.types)
            << countText(k.min, k.max);
        if (!k.defaults.empty()) out << "; default " << values(k.defaults);
        if (!k.into.empty()) out << "; one of " << values(k.into);
        if (k.hasValMin) out << "; >= " << k.valMin;
        if (k.hasValMax) out << "; <= " << k.valMax;
        if (!k.doc.empty()) out << ". " << k.doc;
        if (!k.ignored.empty()) out << (k.doc.empty() ? ". " : " ") << "Accepted and ignored: " << k.ignored;
        out << "\n";
        break;
      case KeywordSpec::Kind::Factor:
        out << indent << "- `" << k.name << "` — factor keyword, "
            << (k.statut == 'd' ? "optional (created with its defaults when absent)" : statut) << ", "
            << k.minOcc << ".." << (k.maxOcc < 0 ? std::string("n") : std::to_string(k.maxOcc)) << " occurrences";
        if (!k.doc.empty()) out << ". " << k.doc;
        if (!k.ignored.empty()) out << (k.doc.empty() ? ". " : " ") << "Accepted and ignored: " << k.ignored;
        out << "\n";
        rulesText(out, k.rules, indent + "  ");
        keywordsText(out, k.children, indent + "  ");
        break;
      case KeywordSpec::Kind::Block:
        out << indent << "- when " << k.describeCondition() << ":\n";
        rulesText(out, k.rules, indent + "  ");
        keywordsText(out, k.children, indent + "  ");
        break;
    }
  }
}

}  // namespace

std::string commandReference(const Catalogue& catalogue) {
  std::ostringstream out;
  out << "# Command reference\n\n"
      << "Generated from the catalogue (`commands/*.lua`) by `aster-lite --doc docs/commands.md`; do not edit.\n"
      << "A test fails when this file is out of date.\n\n";
  for (const auto& [name, spec] : catalogue.commands()) out << "- [" << name << "](#" << name << ")\n";
  for (const auto& [name, spec] : catalogue.commands()) {
    out << "\n## " << name << "\n\n";
    if (!spec.doc.empty()) out << spec.doc << "\n\n";
    if (spec.results.empty())
      out << "Returns nothing.";
    else
      out << "Returns " << describeTypes(spec.results) << ".";
    if (spec.reentrant == 'o') out << " Modifies the concept given with `reuse=` (required).";
    if (spec.reentrant == 'f') out << " May modify the concept given with `reuse=`.";
    out << "\n\n";
    rulesText(out, spec.rules, "");
    keywordsText(out, spec.children, "");
    if (spec.others)
      out << "- any other keyword, `NAME = value` — optional, " << describeTypes(spec.others->types)
          << (spec.others->doc.empty() ? "" : ". " + spec.others->doc) << "\n";
  }
  return out.str();
}

}  // namespace aster::lang
