// DOF numbering, sparsity pattern and position-based assembly against a dense
// assembly done by hand; colouring validity.
#include <gtest/gtest.h>

#include <random>
#include <set>

#include <Eigen/Dense>

#include "core/error.hpp"
#include "fem/assembly_pattern.hpp"

using namespace aster::fem;

TEST(DofMap, UniformAndExtraDofs) {
  DofMap m(4, 2);
  EXPECT_EQ(m.dofCount(), 8);
  EXPECT_EQ(m.dof(3, 1), 7);
  const DofMap c = m.withExtraDofs({1, 3}, 1);  // e.g. a contact pressure on nodes 1 and 3
  EXPECT_EQ(c.dofCount(), 10);
  EXPECT_EQ(c.first(2), 5);
  EXPECT_EQ(c.count(1), 3);
  EXPECT_EQ(c.at(1, 2), 4);
  EXPECT_EQ(c.at(3, 2), 9);
  EXPECT_THROW(c.at(0, 2), aster::Error);
  EXPECT_THROW(c.at(4, 0), aster::Error);
}

// A cell's DOF list, worked by hand: node 0 owns DOFs 0-1, node 1 none, node 2 DOFs 2-4.
TEST(DofMap, NodeDofsAreNodeMajorAndMinusOneWithoutDofs) {
  const DofMap map(std::vector<int>{2, 0, 3});
  const std::vector<int> nodes = {2, 0, 1};
  std::vector<int> dofs = {7};  // appended after what is there
  map.appendNodeDofs(nodes.data(), nodes.data() + nodes.size(), 2, dofs);
  EXPECT_EQ(dofs, (std::vector<int>{7, 2, 3, 0, 1, -1, -1}));
  ElementDofs elements;
  EXPECT_THROW(elements.addCells({{0, 1}}, map, 2), aster::Error);  // node 1 has no DX, DY
  elements.addCells({{2, 0}}, map, 2);
  EXPECT_EQ(std::vector<int>(elements.dofs(0), elements.dofs(0) + elements.size(0)), (std::vector<int>{2, 3, 0, 1}));
}

TEST(AssemblyPattern, MatchesDenseAssembly) {
  // A strip of 3 QUAD4 (nodes 0..7) plus a 2-node "contact" element with an
  // extra DOF on node 7, and an element with an eliminated DOF (-1).
  const std::vector<std::vector<int>> cells = {{0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}};
  const DofMap map = DofMap(8, 2).withExtraDofs({7}, 1);
  ElementDofs elements;
  elements.addCells(cells, map, 2);
  elements.add({map.dof(7, 2), map.dof(7, 1), map.dof(3, 1)});
  elements.add({map.dof(0, 0), -1, map.dof(4, 1)});
  const int n = map.dofCount();
  AssemblyPattern pattern(n, elements);

  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1, 1);
  Eigen::MatrixXd dense = Eigen::MatrixXd::Zero(n, n);
  Eigen::VectorXd denseF = Eigen::VectorXd::Zero(n);
  aster::linalg::SparseMatrix A = pattern.newMatrix();
  Eigen::VectorXd F = Eigen::VectorXd::Zero(n);
  for (int round = 0; round < 2; ++round) {  // re-assembly into the same values
    for (int e = 0; e < elements.elementCount(); ++e) {
      const int m = elements.size(e);
      Eigen::MatrixXd Ke(m, m);
      Eigen::VectorXd fe(m);
      for (int i = 0; i < m; ++i) {
        fe(i) = u(rng);
        for (int j = 0; j < m; ++j) Ke(i, j) = u(rng);
      }
      const int* d = elements.dofs(e);
      for (int i = 0; i < m; ++i) {
        if (d[i] < 0) continue;
        denseF(d[i]) += fe(i);
        for (int j = 0; j < m; ++j)
          if (d[j] >= 0) dense(d[i], d[j]) += Ke(i, j);
      }
      pattern.addMatrix(e, Ke, A);
      pattern.addVector(e, fe, F);
    }
  }
  EXPECT_NEAR((Eigen::MatrixXd(A) - dense).norm(), 0, 1e-13);
  EXPECT_NEAR((F - denseF).norm(), 0, 1e-13);
  // The pattern is exactly the coupled pairs: QUAD4 couplings + extra ones.
  std::set<std::pair<int, int>> pairs;
  for (int e = 0; e < elements.elementCount(); ++e)
    for (int i = 0; i < elements.size(e); ++i)
      for (int j = 0; j < elements.size(e); ++j)
        if (elements.dofs(e)[i] >= 0 && elements.dofs(e)[j] >= 0)
          pairs.insert({elements.dofs(e)[i], elements.dofs(e)[j]});
  EXPECT_EQ(pattern.nonZeros(), static_cast<long long>(pairs.size()));
  AssemblyPattern::clear(A);
  EXPECT_EQ(Eigen::MatrixXd(A).norm(), 0.0);
  // Wrong sizes are refused.
  EXPECT_THROW(pattern.addMatrix(0, Eigen::MatrixXd(3, 3), A), aster::Error);
  ElementDofs bad;
  bad.add({0, 99});
  EXPECT_THROW(AssemblyPattern(10, bad), aster::Error);

  // The pattern's own matrix, handed over: same pattern, zero values, and only once.
  aster::linalg::SparseMatrix taken;
  pattern.takeMatrix(taken);
  ASSERT_EQ(taken.nonZeros(), A.nonZeros());
  EXPECT_TRUE(std::equal(A.innerIndexPtr(), A.innerIndexPtr() + A.nonZeros(), taken.innerIndexPtr()));
  EXPECT_TRUE(std::equal(A.outerIndexPtr(), A.outerIndexPtr() + n + 1, taken.outerIndexPtr()));
  EXPECT_EQ(Eigen::MatrixXd(taken).norm(), 0.0);
  const Eigen::MatrixXd ones = Eigen::MatrixXd::Ones(8, 8);
  pattern.addMatrix(0, ones, taken);  // still assembles into it
  EXPECT_EQ(taken.coeff(map.dof(5, 1), map.dof(0, 0)), 1.0);
  EXPECT_THROW(pattern.takeMatrix(taken), aster::Error);
  EXPECT_THROW(pattern.newMatrix(), aster::Error);
}

TEST(AssemblyPattern, ColouringSeparatesNeighbours) {
  // A 6 x 5 grid of QUAD4.
  const int nx = 6, ny = 5;
  std::vector<std::vector<int>> cells;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const int a = j * (nx + 1) + i;
      cells.push_back({a, a + 1, a + nx + 2, a + nx + 1});
    }
  const DofMap map((nx + 1) * (ny + 1), 2);
  ElementDofs elements;
  elements.addCells(cells, map, 2);
  const auto colours = colourElements(elements, map.dofCount());
  EXPECT_EQ(colours.size(), 4u);  // the greedy colouring of a structured grid
  std::size_t total = 0;
  for (const auto& c : colours) {
    std::set<int> seen;
    for (int e : c)
      for (int i = 0; i < elements.size(e); ++i) EXPECT_TRUE(seen.insert(elements.dofs(e)[i]).second);
    total += c.size();
  }
  EXPECT_EQ(total, cells.size());
}
