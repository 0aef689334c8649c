// maillage_sdaster: a mesh. Shared so that MODI_MAILLAGE and DEFI_GROUP with
// reuse= change it where every command that holds it sees the change.
#pragma once
#include <memory>

#include "core/concept.hpp"
#include "mesh/mesh.hpp"

namespace aster::lang {

class MeshConcept : public Concept {
 public:
  explicit MeshConcept(std::shared_ptr<mesh::Mesh> m) : mesh(std::move(m)) {}
  std::string typeName() const override { return "maillage_sdaster"; }
  std::shared_ptr<mesh::Mesh> mesh;
};

inline mesh::Mesh& meshOf(const ConceptPtr& c) { return *static_cast<MeshConcept&>(*c).mesh; }

}  // namespace aster::lang
