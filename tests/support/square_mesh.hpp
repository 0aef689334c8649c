// A regular N x N mesh of the unit square for tests: cells of one type (QUAD4,
// QUAD8, QUAD9, or TRIA3/TRIA6 from splitting each square along a diagonal),
// boundary segments (SEG2 or SEG3) in groups BAS (y=0), HAUT (y=1), GAUCHE
// (x=0), DROITE (x=1), cells in SURFACE. Node (i, j) of the (2N+1)^2 grid of
// half steps sits at (i/(2N), j/(2N)); linear cells use the even ones.
#pragma once
#include <map>
#include <string>
#include <vector>

#include "mesh/mesh.hpp"

namespace aster::test_support {

inline mesh::Mesh squareMesh(int N, mesh::CellType type) {
  using mesh::CellType;
  const bool quadratic = type == CellType::QUAD8 || type == CellType::QUAD9 || type == CellType::TRIA6;
  const int M = 2 * N;
  mesh::Mesh m;
  m.setSpaceDimension(2);
  std::map<std::pair<int, int>, int> id;
  auto node = [&](int i, int j) {
    auto it = id.find({i, j});
    if (it != id.end()) return it->second;
    const int n = m.addNode(Eigen::Vector3d(double(i) / M, double(j) / M, 0.0));
    id[{i, j}] = n;
    return n;
  };
  std::vector<int> surface, bas, haut, gauche, droite;
  for (int b = 0; b < N; ++b)
    for (int a = 0; a < N; ++a) {
      const int i = 2 * a, j = 2 * b;
      const int c1 = node(i, j), c2 = node(i + 2, j), c3 = node(i + 2, j + 2), c4 = node(i, j + 2);
      switch (type) {
        case CellType::QUAD4: surface.push_back(m.addCell(type, {c1, c2, c3, c4})); break;
        case CellType::QUAD8:
          surface.push_back(m.addCell(type, {c1, c2, c3, c4, node(i + 1, j), node(i + 2, j + 1), node(i + 1, j + 2),
                                             node(i, j + 1)}));
          break;
        case CellType::QUAD9:
          surface.push_back(m.addCell(type, {c1, c2, c3, c4, node(i + 1, j), node(i + 2, j + 1), node(i + 1, j + 2),
                                             node(i, j + 1), node(i + 1, j + 1)}));
          break;
        case CellType::TRIA3:
          surface.push_back(m.addCell(type, {c1, c2, c3}));
          surface.push_back(m.addCell(type, {c1, c3, c4}));
          break;
        case CellType::TRIA6:
          surface.push_back(m.addCell(type, {c1, c2, c3, node(i + 1, j), node(i + 2, j + 1), node(i + 1, j + 1)}));
          surface.push_back(m.addCell(type, {c1, c3, c4, node(i + 1, j + 1), node(i + 1, j + 2), node(i, j + 1)}));
          break;
        default: break;
      }
    }
  const CellType seg = quadratic ? CellType::SEG3 : CellType::SEG2;
  auto edge = [&](int i0, int j0, int i1, int j1) {
    std::vector<int> n = {node(i0, j0), node(i1, j1)};
    if (quadratic) n.push_back(node((i0 + i1) / 2, (j0 + j1) / 2));
    return m.addCell(seg, n);
  };
  // Counterclockwise around the square: outward normals.
  for (int a = 0; a < N; ++a) {
    bas.push_back(edge(2 * a, 0, 2 * a + 2, 0));
    droite.push_back(edge(M, 2 * a, M, 2 * a + 2));
    haut.push_back(edge(M - 2 * a, M, M - 2 * a - 2, M));
    gauche.push_back(edge(0, M - 2 * a, 0, M - 2 * a - 2));
  }
  m.addCellGroup("SURFACE", surface);
  m.addCellGroup("BAS", bas);
  m.addCellGroup("HAUT", haut);
  m.addCellGroup("GAUCHE", gauche);
  m.addCellGroup("DROITE", droite);
  return m;
}

}  // namespace aster::test_support
