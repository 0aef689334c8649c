// A concept is what a command returns and later commands take: a mesh, a model,
// a load, a result... (code_aster's "sd"). Operators wrap kernel objects in a
// Concept subclass; the language layer holds them as typed Lua userdata.
#pragma once
#include <memory>
#include <string>

namespace aster {

class Concept {
 public:
  virtual ~Concept() = default;
  // code_aster's type name, e.g. "maillage_sdaster"; the catalogue checks it.
  virtual std::string typeName() const = 0;
  std::string name;  // the study's variable name, when known
  // The variable the creating line assigned it to ("local RESU = ..." too): its
  // name in messages when no global variable holds it.
  std::string assignedAs;
  // Where DETRUIRE destroyed it ("study.lua:12"); empty while it is usable. A
  // destroyed concept may live on inside others (a model keeps its mesh), but
  // the study can no longer use it.
  std::string destroyedAt;
};

using ConceptPtr = std::shared_ptr<Concept>;

}  // namespace aster
