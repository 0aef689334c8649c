// The generic validator: every rejection names the keyword and the expectation;
// defaults are filled; numbers are typed as the catalogue says.
#include <gtest/gtest.h>

#include <cmath>

#include "lang/catalogue.hpp"
#include "lang/docgen.hpp"
#include "lang/validator.hpp"

using namespace aster;
using namespace aster::lang;

namespace {

struct FakeConcept : Concept {
  explicit FakeConcept(std::string t) : type(std::move(t)) {}
  std::string typeName() const override { return type; }
  std::string type;
};

const char* kEssai = R"(
return OPER{ nom = 'ESSAI', sd_prod = 'modele_sdaster',
  SIMP{ 'MAILLAGE', statut = 'o', typ = 'maillage_sdaster' },
  SIMP{ 'FORMAT', typ = 'TXM', defaut = 'ASTER', into = {'ASTER', 'MED', 'GMSH'} },
  SIMP{ 'COEF', typ = 'R', defaut = 1, val_min = 0 },
  SIMP{ 'NIVEAU', typ = 'I', defaut = 1, into = {1, 2} },
  SIMP{ 'VALE', typ = 'R', min = 2, max = '**' },
  FACT{ 'AFFE', statut = 'o', max = '**',
    regles = { UN_PARMI('TOUT', 'GROUP_MA') },
    SIMP{ 'TOUT', typ = 'TXM', into = {'OUI'} },
    SIMP{ 'GROUP_MA', typ = 'grma', max = '**' },
    SIMP{ 'MODELISATION', statut = 'o', typ = 'TXM', into = {'D_PLAN', 'C_PLAN'} },
  },
  FACT{ 'NEWTON', statut = 'd',
    SIMP{ 'REAC_ITER', typ = 'I', defaut = 1 },
  },
  SIMP{ 'FORMULATION', typ = 'TXM', defaut = 'DISCRETE', into = {'DISCRETE', 'CONTINUE'} },
  BLOC{ 'b_continue', condition = { FORMULATION = 'CONTINUE' },
    SIMP{ 'COEF_CONT', typ = 'R', defaut = 100 },
  },
  regles = { EXCLUS('VALE', 'COEF') },
}
)";

const CommandSpec& essai() {
  static const Catalogue cat = Catalogue::fromSources({{"ESSAI", kEssai}});
  return *cat.find("ESSAI");
}

Keywords affe(const std::string& key, Value v) {
  Keywords k;
  k.setSimple(key, {v});
  k.setSimple("MODELISATION", {Value::ofText("D_PLAN")});
  return k;
}

Keywords minimalCall() {
  Keywords call;
  call.setSimple("MAILLAGE", {Value::ofConcept(std::make_shared<FakeConcept>("maillage_sdaster"))});
  call.setFactor("AFFE", {affe("TOUT", Value::ofText("OUI"))});
  return call;
}

std::string rejection(const Keywords& call, std::string* keyword = nullptr) {
  try {
    validate(essai(), call);
  } catch (const ValidationError& e) {
    if (keyword) *keyword = e.keyword;
    return e.what();
  }
  return "(accepted)";
}

}  // namespace

TEST(Validator, FillsDefaultsAndTypesNumbers) {
  const Keywords k = validate(essai(), minimalCall());
  EXPECT_EQ(k.text("FORMAT"), "ASTER");
  EXPECT_EQ(k.value("COEF").kind, Value::Kind::Real);
  EXPECT_DOUBLE_EQ(k.real("COEF"), 1.0);
  EXPECT_EQ(k.value("NIVEAU").kind, Value::Kind::Integer);
  EXPECT_EQ(k.integer("NIVEAU"), 1);
  ASSERT_EQ(k.factor("NEWTON").size(), 1u);  // statut 'd': created with its defaults
  EXPECT_EQ(k.factor("NEWTON")[0].integer("REAC_ITER"), 1);
  EXPECT_FALSE(k.has("COEF_CONT"));  // its block is inactive
  EXPECT_FALSE(k.has("VALE"));
}

TEST(Validator, BlockKeywordsApplyWhenTheConditionHolds) {
  Keywords call = minimalCall();
  call.setSimple("FORMULATION", {Value::ofText("CONTINUE")});
  const Keywords k = validate(essai(), call);
  EXPECT_DOUBLE_EQ(k.real("COEF_CONT"), 100.0);
}

TEST(Validator, KeywordOfAnInactiveBlockSaysWhenItApplies) {
  Keywords call = minimalCall();
  call.setSimple("COEF_CONT", {Value::ofReal(10)});
  EXPECT_EQ(rejection(call), "keyword COEF_CONT is only allowed when FORMULATION = 'CONTINUE'");
}

TEST(Validator, UnknownKeywordSuggestsTheClosest) {
  Keywords call = minimalCall();
  call.setSimple("FORMT", {Value::ofText("MED")});
  std::string key;
  const std::string msg = rejection(call, &key);
  EXPECT_EQ(key, "FORMT");
  EXPECT_NE(msg.find("keyword FORMT is not a keyword of ESSAI; did you mean FORMAT?"), std::string::npos) << msg;
}

TEST(Validator, MissingMandatoryNamesTheExpectedType) {
  Keywords call = minimalCall();
  call.erase("MAILLAGE");
  EXPECT_EQ(rejection(call), "keyword MAILLAGE is mandatory and missing (expected a maillage_sdaster)");
}

TEST(Validator, WrongConceptType) {
  Keywords call = minimalCall();
  call.setSimple("MAILLAGE", {Value::ofConcept(std::make_shared<FakeConcept>("modele_sdaster"))});
  EXPECT_EQ(rejection(call), "keyword MAILLAGE expects a maillage_sdaster, got a modele_sdaster");
}

TEST(Validator, WrongScalarTypes) {
  Keywords call = minimalCall();
  call.setSimple("COEF", {Value::ofText("un")});
  EXPECT_EQ(rejection(call), "keyword COEF expects a real, got 'un'");
  call = minimalCall();
  call.setSimple("NIVEAU", {Value::ofReal(1.5)});
  EXPECT_EQ(rejection(call), "keyword NIVEAU expects an integer, got 1.5");
}

TEST(Validator, ValueNotAllowedListsTheAllowedOnes) {
  Keywords call = minimalCall();
  call.setSimple("FORMAT", {Value::ofText("MEDD")});
  EXPECT_EQ(rejection(call),
            "keyword FORMAT = 'MEDD' is not allowed; allowed values: 'ASTER', 'MED', 'GMSH'; did you mean 'MED'?");
}

TEST(Validator, BoundsOnNumbers) {
  Keywords call = minimalCall();
  call.setSimple("COEF", {Value::ofReal(-2)});
  EXPECT_EQ(rejection(call), "keyword COEF = -2 is below its minimum 0");
}

// Integers are read by operators as C++ ints: a larger one would be truncated
// (4294967298 would be 2), so it is refused by keyword name.
TEST(Validator, IntegersOutsideTheRangeOfIntAreRefused) {
  Keywords call = minimalCall();
  Keywords newton;
  newton.setSimple("REAC_ITER", {Value::ofInteger(4294967298LL)});
  call.setFactor("NEWTON", {newton});
  std::string keyword;
  EXPECT_EQ(rejection(call, &keyword),
            "NEWTON: keyword REAC_ITER = 4294967298 is out of the range of integers (-2147483648 to 2147483647)");
  EXPECT_EQ(keyword, "NEWTON/REAC_ITER");
  newton.setSimple("REAC_ITER", {Value::ofReal(-4294967296.0)});  // a real with an integer value
  call.setFactor("NEWTON", {newton});
  EXPECT_EQ(rejection(call),
            "NEWTON: keyword REAC_ITER = -4294967296 is out of the range of integers (-2147483648 to 2147483647)");
  newton.setSimple("REAC_ITER", {Value::ofInteger(2147483647)});
  call.setFactor("NEWTON", {newton});
  EXPECT_EQ(validate(essai(), call).factor("NEWTON")[0].integer("REAC_ITER"), 2147483647);
  newton.setSimple("REAC_ITER", {Value::ofInteger(-2147483648LL)});
  call.setFactor("NEWTON", {newton});
  EXPECT_EQ(validate(essai(), call).factor("NEWTON")[0].integer("REAC_ITER"), -2147483648LL);
}

// NaN and infinities (0/0, 1/0, math.huge in a study) in any real keyword.
TEST(Validator, NonFiniteRealsAreRefused) {
  Keywords call = minimalCall();
  call.erase("COEF");
  call.setSimple("VALE", {Value::ofReal(1.0), Value::ofReal(std::nan("")), Value::ofReal(2.0)});
  EXPECT_EQ(rejection(call), "keyword VALE (value 2) = nan is not a finite number (0/0, 1/0 or math.huge in the study?)");
  call.setSimple("VALE", {Value::ofReal(1.0), Value::ofReal(-HUGE_VAL)});
  EXPECT_EQ(rejection(call), "keyword VALE (value 2) = -inf is not a finite number (0/0, 1/0 or math.huge in the study?)");
  call = minimalCall();
  call.setSimple("COEF", {Value::ofReal(HUGE_VAL)});
  EXPECT_EQ(rejection(call), "keyword COEF = inf is not a finite number (0/0, 1/0 or math.huge in the study?)");
}

// C strings end at a NUL byte: a text holding one would be cut short silently.
TEST(Validator, TextsWithANulByteAreRefused) {
  Keywords call = minimalCall();
  call.setFactor("AFFE", {affe("GROUP_MA", Value::ofText(std::string("HAUT\0BAS", 8)))});
  EXPECT_EQ(rejection(call), "AFFE[1]: keyword GROUP_MA = 'HAUT\\0BAS' contains a NUL byte ('\\0')");
}

TEST(Validator, NumberOfValues) {
  Keywords call = minimalCall();
  call.setSimple("VALE", {Value::ofReal(1)});
  EXPECT_EQ(rejection(call), "keyword VALE needs at least 2 values, got 1");
  call = minimalCall();
  call.setSimple("FORMAT", {Value::ofText("MED"), Value::ofText("ASTER")});
  EXPECT_EQ(rejection(call), "keyword FORMAT takes at most 1 value, got 2");
}

TEST(Validator, FactorOccurrences) {
  Keywords call = minimalCall();
  call.erase("AFFE");
  EXPECT_EQ(rejection(call), "factor keyword AFFE is mandatory and missing");
  call = minimalCall();
  call.setFactor("NEWTON", {Keywords(), Keywords()});
  EXPECT_EQ(rejection(call), "factor keyword NEWTON is given 2 times; expected at most 1");
}

TEST(Validator, ErrorsInsideAFactorNameTheOccurrence) {
  Keywords call = minimalCall();
  Keywords bad = affe("TOUT", Value::ofText("OUI"));
  bad.setSimple("MODELISATION", {Value::ofText("3D")});
  call.setFactor("AFFE", {affe("TOUT", Value::ofText("OUI")), bad});
  std::string key;
  EXPECT_EQ(rejection(call, &key),
            "AFFE[2]: keyword MODELISATION = '3D' is not allowed; allowed values: 'D_PLAN', 'C_PLAN'");
  EXPECT_EQ(key, "AFFE[2]/MODELISATION");
}

TEST(Validator, MutuallyExclusiveKeywords) {
  Keywords call = minimalCall();
  Keywords both = affe("TOUT", Value::ofText("OUI"));
  both.setSimple("GROUP_MA", {Value::ofText("HAUT")});
  call.setFactor("AFFE", {both});
  EXPECT_EQ(rejection(call), "AFFE[1]: exactly one of TOUT, GROUP_MA is required, got TOUT, GROUP_MA "
                             "(rule UN_PARMI('TOUT', 'GROUP_MA'))");
  call = minimalCall();
  call.setSimple("VALE", {Value::ofReal(1), Value::ofReal(2)});
  call.setSimple("COEF", {Value::ofReal(2)});
  EXPECT_EQ(rejection(call), "keywords VALE, COEF are mutually exclusive (rule EXCLUS('VALE', 'COEF'))");
}

TEST(Validator, OneOfIsRequired) {
  Keywords call = minimalCall();
  Keywords none;
  none.setSimple("MODELISATION", {Value::ofText("D_PLAN")});
  call.setFactor("AFFE", {none});
  EXPECT_EQ(rejection(call), "AFFE[1]: exactly one of TOUT, GROUP_MA is required, got none "
                             "(rule UN_PARMI('TOUT', 'GROUP_MA'))");
}

TEST(Validator, SimpleKeywordGivenATable) {
  Keywords call = minimalCall();
  call.setFactor("FORMAT", {Keywords()});
  EXPECT_EQ(rejection(call), "keyword FORMAT expects a text, got a table of keywords");
}

TEST(Catalogue, RejectsADefaultOutsideItsAllowedValues) {
  const char* bad = "return PROC{ nom = 'MAUVAIS', SIMP{ 'A', typ = 'TXM', defaut = 'X', into = {'Y'} } }";
  try {
    Catalogue::fromSources({{"MAUVAIS", bad}});
    FAIL() << "accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("commands/MAUVAIS.lua: MAUVAIS/A: default 'X' is not among the allowed "
                                         "values"),
              std::string::npos)
        << e.what();
  }
}

TEST(Catalogue, NameMustMatchTheFile) {
  EXPECT_THROW(Catalogue::fromSources({{"AUTRE", "return PROC{ nom = 'MAUVAIS' }"}}), Error);
}

// A common group (commands/commons/C_PAIRE.lua) used twice, with two value types.
const char* kPaire = R"(
function C_PAIRE(typ)
  return KEYWORDS{ SIMP{ 'A', typ = typ }, SIMP{ 'B', typ = typ, defaut = 2 } }
end
)";

TEST(Catalogue, CommonGroupIsSplicedWhereItIsPlaced) {
  const char* command = R"(
return PROC{ nom = 'ESSAI_COMMUN',
  SIMP{ 'DEBUT', typ = 'TXM' },
  C_PAIRE('R'),
  SIMP{ 'FIN', typ = 'TXM' },
  FACT{ 'F', C_PAIRE('I') },
}
)";
  const Catalogue cat = Catalogue::fromSources({{"ESSAI_COMMUN", command}}, {{"C_PAIRE", kPaire}});
  const CommandSpec& spec = *cat.find("ESSAI_COMMUN");
  std::vector<std::string> names;
  for (const auto& k : spec.children) names.push_back(k.name);
  EXPECT_EQ(names, (std::vector<std::string>{"DEBUT", "A", "B", "FIN", "F"}));
  EXPECT_EQ(spec.children[1].types, std::vector<std::string>{"R"});
  const auto& f = spec.children[4].children;
  ASSERT_EQ(f.size(), 2u);
  EXPECT_EQ(f[0].name, "A");
  EXPECT_EQ(f[0].types, std::vector<std::string>{"I"});
  ASSERT_EQ(f[1].defaults.size(), 1u);
  EXPECT_EQ(f[1].defaults[0].integer, 2);
}

TEST(Catalogue, CommonFileMustDefineItsName) {
  try {
    Catalogue::fromSources({{"DEBUT", "return PROC{ nom = 'DEBUT' }"}}, {{"C_AUTRE", kPaire}});
    FAIL() << "accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("commands/commons/C_AUTRE.lua: it must define C_AUTRE"), std::string::npos)
        << e.what();
  }
}

TEST(Catalogue, BuiltinLoads) {
  const Catalogue& cat = Catalogue::builtin();
  ASSERT_NE(cat.find("DEBUT"), nullptr);
  ASSERT_NE(cat.find("FIN"), nullptr);
}

// A factor keyword with min = 2 and an AU_MOINS_UN rule, beside ESSAI.
const char* kEssaiMinimum = R"(
return PROC{ nom = 'ESSAI_MIN',
  regles = { AU_MOINS_UN('TOUT', 'GROUP_MA') },
  SIMP{ 'TOUT', typ = 'TXM', into = {'OUI'} },
  SIMP{ 'GROUP_MA', typ = 'grma', max = '**' },
  FACT{ 'POINT', statut = 'o', min = 2, max = '**',
    SIMP{ 'X', statut = 'o', typ = 'R' },
  },
}
)";

std::string minimumRejection(const Keywords& call, std::string* keyword) {
  static const Catalogue cat = Catalogue::fromSources({{"ESSAI_MIN", kEssaiMinimum}});
  try {
    validate(*cat.find("ESSAI_MIN"), call);
  } catch (const ValidationError& e) {
    *keyword = e.keyword;
    return e.what();
  }
  return "(accepted)";
}

Keywords points(int n) {
  std::vector<Keywords> occ(n);
  for (auto& o : occ) o.setSimple("X", {Value::ofReal(1.0)});
  Keywords call;
  call.setFactor("POINT", occ);
  return call;
}

TEST(Validator, RejectsTooFewOccurrencesOfAFactorKeyword) {
  Keywords call = points(1);
  call.setSimple("TOUT", {Value::ofText("OUI")});
  std::string keyword;
  EXPECT_EQ(minimumRejection(call, &keyword), "factor keyword POINT is given 1 time; expected at least 2");
  EXPECT_EQ(keyword, "POINT");
  call = points(2);
  call.setSimple("TOUT", {Value::ofText("OUI")});
  EXPECT_EQ(minimumRejection(call, &keyword), "(accepted)");
}

TEST(Validator, RejectsACallWithNoneOfAnAuMoinsUnRule) {
  std::string keyword;
  const std::string why = minimumRejection(points(2), &keyword);
  EXPECT_NE(why.find("at least one of TOUT, GROUP_MA is required"), std::string::npos) << why;
}

// autres_mots_cles: undeclared keywords as named values (FORMULE's context).
namespace {

const CommandSpec& avecAutres() {
  static const Catalogue cat = Catalogue::fromSources({{"AVEC_AUTRES", R"(
return OPER{ nom = 'AVEC_AUTRES', sd_prod = 'formule',
  SIMP{ 'NOM_PARA', statut = 'o', typ = 'TXM', max = '**' },
  autres_mots_cles = SIMP{ 'CONTEXTE', typ = {'R', 'formule'} },
}
)"}});
  return *cat.find("AVEC_AUTRES");
}

std::string validationError(const Keywords& call) {
  try {
    validate(avecAutres(), call);
  } catch (const Error& e) {
    return e.what();
  }
  return "no error";
}

}  // namespace

TEST(Validator, OtherKeywordsAreGatheredAsNamedValues) {
  Keywords call;
  call.setSimple("NOM_PARA", {Value::ofText("X")});
  call.setSimple("A", {Value::ofInteger(2)});
  const auto f = std::make_shared<FakeConcept>("formule");
  call.setSimple("G", {Value::ofConcept(f)});
  const Keywords out = validate(avecAutres(), call);
  EXPECT_FALSE(out.has("A"));
  ASSERT_EQ(out.factor("CONTEXTE").size(), 1u);
  const Keywords& ctx = out.factor("CONTEXTE").front();
  EXPECT_EQ(ctx.keys(), (std::vector<std::string>{"A", "G"}));
  EXPECT_EQ(ctx.value("A").kind, Value::Kind::Real);  // typed as 'R'
  EXPECT_EQ(ctx.real("A"), 2.0);
  EXPECT_EQ(ctx.conceptPtr("G"), f);
  // None given: no CONTEXTE at all.
  Keywords plain;
  plain.setSimple("NOM_PARA", {Value::ofText("X")});
  EXPECT_TRUE(validate(avecAutres(), plain).factor("CONTEXTE").empty());
}

TEST(Validator, OtherKeywordsAreCheckedAsDeclared) {
  Keywords call;
  call.setSimple("NOM_PARA", {Value::ofText("X")});
  Keywords badName = call;
  badName.setSimple("A B", {Value::ofReal(1.0)});
  EXPECT_EQ(validationError(badName), "keyword 'A B' is not a valid name: a value passed to the expression (CONTEXTE) "
                                      "is named by a letter or _ then letters, digits or _");
  Keywords text = call;
  text.setSimple("A", {Value::ofText("deux")});
  EXPECT_EQ(validationError(text), "keyword A is not one of AVEC_AUTRES's own keywords, so it is a value passed to the "
                                   "expression (CONTEXTE): it must be a real or a formule, got 'deux'");
  Keywords two = call;
  two.setSimple("A", {Value::ofReal(1.0), Value::ofReal(2.0)});
  EXPECT_NE(validationError(two).find("got 2 values"), std::string::npos);
  Keywords nan = call;
  nan.setSimple("A", {Value::ofReal(std::nan(""))});
  EXPECT_NE(validationError(nan).find("is not a finite number"), std::string::npos);
  Keywords wrongConcept = call;
  wrongConcept.setSimple("A", {Value::ofConcept(std::make_shared<FakeConcept>("maillage_sdaster"))});
  EXPECT_NE(validationError(wrongConcept).find("it must be a real or a formule, got"), std::string::npos);
}

TEST(Catalogue, OtherKeywordsAreOneOptionalValue) {
  EXPECT_THROW(Catalogue::fromSources({{"MAUVAIS", R"(
return OPER{ nom = 'MAUVAIS', sd_prod = 'formule', autres_mots_cles = SIMP{ 'C', typ = 'R', max = '**' } })"}}),
               Error);
  EXPECT_THROW(Catalogue::fromSources({{"MAUVAIS", R"(
return OPER{ nom = 'MAUVAIS', sd_prod = 'formule', SIMP{ 'C', typ = 'R' }, autres_mots_cles = SIMP{ 'C', typ = 'R' } })"}}),
               Error);
  EXPECT_THROW(Catalogue::fromSources({{"MAUVAIS", R"(
return OPER{ nom = 'MAUVAIS', sd_prod = 'formule', autres_mots_cles = { 'C' } })"}}), Error);
}

// An accepted-and-ignored keyword (ignored = "reason"): checked as declared,
// then absent from the tree the operator reads, defaults included.
const char* kIgnore = R"(
return PROC{ nom = 'IGNORE',
  SIMP{ 'PAR_LOT', typ = 'TXM', defaut = 'NON', into = {'OUI', 'NON'}, ignored = "runs command by command." },
  FACT{ 'DEBUG', ignored = "developers' checks of code_aster.",
    SIMP{ 'SDVERI', typ = 'TXM', into = {'OUI', 'NON'} },
  },
  SIMP{ 'GARDE', typ = 'I', defaut = 3 },
}
)";

TEST(Validator, IgnoredKeywordsAreCheckedThenDropped) {
  static const Catalogue cat = Catalogue::fromSources({{"IGNORE", kIgnore}});
  const CommandSpec& spec = *cat.find("IGNORE");
  Keywords call;
  call.setSimple("PAR_LOT", {Value::ofText("OUI")});
  Keywords debug;
  debug.setSimple("SDVERI", {Value::ofText("OUI")});
  call.setFactor("DEBUG", {debug});
  const Keywords out = validate(spec, call);
  EXPECT_FALSE(out.has("PAR_LOT"));
  EXPECT_FALSE(out.has("DEBUG"));
  EXPECT_EQ(out.integer("GARDE"), 3);
  EXPECT_FALSE(validate(spec, Keywords{}).has("PAR_LOT"));  // nor its default

  Keywords misspelt;
  misspelt.setSimple("PAR_LOT", {Value::ofText("OUII")});
  EXPECT_THROW(validate(spec, misspelt), ValidationError);
  Keywords inside;
  Keywords badDebug;
  badDebug.setSimple("SDVERI", {Value::ofText("PEUT-ETRE")});
  inside.setFactor("DEBUG", {badDebug});
  try {
    validate(spec, inside);
    FAIL() << "accepted";
  } catch (const ValidationError& e) {
    EXPECT_EQ(e.keyword, "DEBUG/SDVERI");
  }
}

TEST(Catalogue, IgnoredNeedsAReasonAndAnOptionalKeyword) {
  for (const char* bad : {"return PROC{ nom = 'MAUVAIS', SIMP{ 'A', typ = 'TXM', ignored = '' } }",
                          "return PROC{ nom = 'MAUVAIS', SIMP{ 'A', typ = 'TXM', ignored = true } }",
                          "return PROC{ nom = 'MAUVAIS', SIMP{ 'A', statut = 'o', typ = 'TXM', ignored = 'x' } }",
                          "return PROC{ nom = 'MAUVAIS', BLOC{ 'b', condition = { A = true }, ignored = 'x' } }"})
    EXPECT_THROW(Catalogue::fromSources({{"MAUVAIS", bad}}), Error) << bad;
}

TEST(Docgen, MarksIgnoredKeywordsWithTheirReason) {
  static const Catalogue cat = Catalogue::fromSources({{"IGNORE", kIgnore}});
  const std::string doc = commandReference(cat);
  EXPECT_NE(doc.find("- `PAR_LOT` — optional, a text; default 'NON'; one of 'OUI', 'NON'. Accepted and ignored: runs "
                     "command by command.\n"),
            std::string::npos)
      << doc;
  EXPECT_NE(doc.find("- `DEBUG` — factor keyword, optional, 0..1 occurrences. Accepted and ignored: developers' checks "
                     "of code_aster.\n"),
            std::string::npos)
      << doc;
  EXPECT_EQ(doc.find("`GARDE` — optional, an integer; default 3. Accepted"), std::string::npos);
}

// The built-in catalogue: code_aster's DEBUT options are accepted, ignored and say why.
TEST(Docgen, BuiltinReferenceMarksDebutOptionsIgnored) {
  const std::string doc = commandReference(Catalogue::builtin());
  const auto debut = doc.find("\n## DEBUT\n");
  ASSERT_NE(debut, std::string::npos);
  const std::string section = doc.substr(debut, doc.find("\n## ", debut + 1) - debut);
  for (const char* key : {"`PAR_LOT`", "`DEBUG`", "`IGNORE_ALARM`", "`ERREUR`", "`MESURE_TEMPS`", "`CODE`"}) {
    const auto at = section.find(key);
    ASSERT_NE(at, std::string::npos) << key;
    const std::string line = section.substr(at, section.find('\n', at) - at);
    EXPECT_NE(line.find("Accepted and ignored: "), std::string::npos) << line;
  }
  const CommandSpec& spec = *Catalogue::builtin().find("DEBUT");
  Keywords call, debug;
  debug.setSimple("SDVERI", {Value::ofText("OUI")});
  call.setFactor("DEBUG", {debug});
  call.setSimple("IGNORE_ALARM", {Value::ofText("MODELE1_63"), Value::ofText("SUPERVIS_1")});
  EXPECT_TRUE(validate(spec, call).keys().empty());  // nothing reaches the operator
}

// IMPR_RESU's TYPE_CHAM: only 'VECT_2D', what the GMSH writer does anyway with two
// components, is accepted (and dropped); 'SCALAIRE' would ask for another file.
TEST(Validator, ImprResuTypeChamOnlyTheWriterBehaviour) {
  const CommandSpec& spec = *Catalogue::builtin().find("IMPR_RESU");
  auto call = [](const char* typeCham) {
    Keywords resu;
    resu.setSimple("CHAM_GD", {Value::ofConcept(std::make_shared<FakeConcept>("cham_no_sdaster"))});
    resu.setSimple("NOM_CMP", {Value::ofText("DX"), Value::ofText("DY")});
    resu.setSimple("TYPE_CHAM", {Value::ofText(typeCham)});
    Keywords k;
    k.setSimple("FORMAT", {Value::ofText("GMSH")});
    k.setFactor("RESU", {resu});
    return k;
  };
  const Keywords out = validate(spec, call("VECT_2D"));
  EXPECT_FALSE(out.factor("RESU").front().has("TYPE_CHAM"));
  EXPECT_THROW(validate(spec, call("SCALAIRE")), ValidationError);
}
