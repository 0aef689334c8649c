// Concepts of the model family: modele_sdaster, mater_sdaster, cham_mater,
// char_meca / char_cine_meca (loads).
#pragma once
#include <memory>

#include "core/concept.hpp"
#include "model/loads.hpp"
#include "model/material.hpp"
#include "model/model.hpp"

namespace aster::lang {

class ModelConcept : public Concept {
 public:
  explicit ModelConcept(std::shared_ptr<model::Model> m) : model(std::move(m)) {}
  std::string typeName() const override { return "modele_sdaster"; }
  std::shared_ptr<model::Model> model;
};

class MaterialConcept : public Concept {
 public:
  explicit MaterialConcept(model::MaterialPtr m) : material(std::move(m)) {}
  std::string typeName() const override { return "mater_sdaster"; }
  model::MaterialPtr material;
};

class MaterialFieldConcept : public Concept {
 public:
  MaterialFieldConcept(std::shared_ptr<mesh::Mesh> mesh, std::shared_ptr<model::MaterialField> f)
      : mesh(std::move(mesh)), field(std::move(f)) {}
  std::string typeName() const override { return "cham_mater"; }
  std::shared_ptr<mesh::Mesh> mesh;
  std::shared_ptr<model::MaterialField> field;
};

class LoadConcept : public Concept {
 public:
  LoadConcept(std::shared_ptr<model::Model> m, model::MechanicalLoad l)
      : model(std::move(m)), load(std::move(l)) {}
  std::string typeName() const override { return load.kinematic ? "char_cine_meca" : "char_meca"; }
  std::shared_ptr<model::Model> model;
  model::MechanicalLoad load;
};

inline model::Model& modelOf(const ConceptPtr& c) { return *static_cast<ModelConcept&>(*c).model; }

}  // namespace aster::lang
