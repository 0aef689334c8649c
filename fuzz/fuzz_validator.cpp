// libFuzzer target: the generic validator, fed keyword trees built from the fuzz
// bytes against the builtin catalogue: a command, then at each level keywords of
// its spec (blocks and factors included) or made-up names, with values of every
// kind (numbers including NaN and infinities, texts from `into` or random,
// concepts of any type, functions, CO names). validate() must return a tree or
// throw ValidationError (an aster::Error); a crash or another exception is a finding.
#include <fuzzer/FuzzedDataProvider.h>

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "lang/catalogue.hpp"
#include "lang/keywords.hpp"
#include "lang/validator.hpp"

namespace {

using namespace aster::lang;

class FakeConcept : public aster::Concept {
 public:
  explicit FakeConcept(std::string type) : type_(std::move(type)) {}
  std::string typeName() const override { return type_; }

 private:
  std::string type_;
};

class FakeCallable : public aster::ScalarCallable {
 public:
  double call(const double*, int) const override { return 0.0; }
};

const char* const kTypes[] = {"maillage_sdaster", "modele_sdaster", "cham_mater", "char_meca",
                              "fonction_sdaster", "formule", "listr8_sdaster", "evol_noli",
                              "table_sdaster", "mater_sdaster", "list_inst", "char_cine_meca"};

// Every keyword spec reachable at one level (blocks are transparent).
void flatten(const std::vector<KeywordSpec>& specs, std::vector<const KeywordSpec*>& out) {
  for (const auto& k : specs) {
    if (k.kind == KeywordSpec::Kind::Block)
      flatten(k.children, out);
    else
      out.push_back(&k);
  }
}

Value randomValue(FuzzedDataProvider& p, const KeywordSpec* spec) {
  switch (p.ConsumeIntegralInRange(0, 8)) {
    case 0: return Value::ofInteger(p.ConsumeIntegral<long long>());
    case 1: return Value::ofInteger(p.ConsumeIntegralInRange<long long>(-3, 5));
    case 2: return Value::ofReal(p.ConsumeFloatingPoint<double>());
    case 3:
      if (spec && !spec->into.empty()) return spec->into[p.ConsumeIntegralInRange<std::size_t>(0, spec->into.size() - 1)];
      return Value::ofText(p.ConsumeRandomLengthString(16));
    case 4: return Value::ofText(p.ConsumeRandomLengthString(16));
    case 5: {
      std::string type;
      if (spec && !spec->types.empty() && p.ConsumeBool())
        type = spec->types[p.ConsumeIntegralInRange<std::size_t>(0, spec->types.size() - 1)];
      else
        type = kTypes[p.ConsumeIntegralInRange<std::size_t>(0, std::size(kTypes) - 1)];
      return Value::ofConcept(std::make_shared<FakeConcept>(type));
    }
    case 6: return Value::ofFunction(std::make_shared<FakeCallable>());
    case 7: return Value::ofNewName(p.ConsumeRandomLengthString(8));
    default:
      if (spec && !spec->defaults.empty()) return spec->defaults.front();
      return Value::other("a table");
  }
}

// Deeper than any catalogue (3 levels) and than the interpreter lets a study give (20).
constexpr int kMaxDepth = 24;

Keywords randomLevel(FuzzedDataProvider& p, const std::vector<KeywordSpec>& specs, const std::string& path,
                     int depth) {
  Keywords level;
  level.path = path;
  std::vector<const KeywordSpec*> flat;
  flatten(specs, flat);
  const int count = p.ConsumeIntegralInRange(0, 8);
  for (int i = 0; i < count && p.remaining_bytes() > 0; ++i) {
    const KeywordSpec* spec = nullptr;
    std::string key;
    if (!flat.empty() && p.ConsumeIntegralInRange(0, 9) > 0) {
      spec = flat[p.ConsumeIntegralInRange<std::size_t>(0, flat.size() - 1)];
      key = spec->name;
    } else {
      key = p.ConsumeRandomLengthString(12);
    }
    const bool asFactor = spec ? (spec->kind == KeywordSpec::Kind::Factor) != (p.ConsumeIntegralInRange(0, 15) == 0)
                               : p.ConsumeBool();
    if (asFactor && depth < kMaxDepth) {
      std::vector<Keywords> occurrences;
      const int n = p.ConsumeIntegralInRange(0, 3);
      static const std::vector<KeywordSpec> none;
      for (int o = 0; o < n; ++o)
        occurrences.push_back(randomLevel(p, spec ? spec->children : none,
                                          key + "[" + std::to_string(o + 1) + "]", depth + 1));
      level.setFactor(key, std::move(occurrences));
    } else {
      std::vector<Value> values;
      const int n = p.ConsumeIntegralInRange(0, 4);
      for (int v = 0; v < n; ++v) values.push_back(randomValue(p, spec));
      level.setSimple(key, std::move(values));
    }
  }
  return level;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const Catalogue& catalogue = Catalogue::builtin();
  static const std::vector<std::string> names = catalogue.names();
  FuzzedDataProvider p(data, size);
  const CommandSpec* spec = catalogue.find(names[p.ConsumeIntegralInRange<std::size_t>(0, names.size() - 1)]);
  if (!spec) __builtin_trap();
  const Keywords call = randomLevel(p, spec->children, "", 0);
  try {
    const Keywords out = validate(*spec, call);
    (void)out.keys();
  } catch (const ValidationError&) {
  } catch (const aster::Error&) {
    __builtin_trap();  // rejections are ValidationError, with the keyword path
  }
  return 0;
}
