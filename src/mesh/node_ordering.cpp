#include "mesh/node_ordering.hpp"

#include <algorithm>
#include <array>
#include <map>
#include <numeric>

#include "core/error.hpp"

namespace aster::mesh {

namespace {

using NodeSets = std::vector<std::vector<int>>;  // each node: the vertices it lies on/between

// Vertices 0..nv-1 followed by the given higher-order node definitions.
NodeSets withVertices(int nv, NodeSets higher) {
  NodeSets s;
  for (int v = 0; v < nv; ++v) s.push_back({v});
  s.insert(s.end(), higher.begin(), higher.end());
  return s;
}

NodeSets allVertices(int nv) {
  std::vector<int> all(nv);
  std::iota(all.begin(), all.end(), 0);
  return {all};
}

NodeSets concat(NodeSets a, const NodeSets& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

// code_aster's definitions (vertices numbered as in code_aster).
NodeSets asterSets(CellType t) {
  const NodeSets triEdges{{0, 1}, {1, 2}, {2, 0}};
  const NodeSets quadEdges{{0, 1}, {1, 2}, {2, 3}, {3, 0}};
  const NodeSets tetEdges{{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 3}, {2, 3}};
  const NodeSets pentaEdges{{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 4}, {2, 5}, {3, 4}, {4, 5}, {5, 3}};
  const NodeSets pyramEdges{{0, 1}, {1, 2}, {2, 3}, {3, 0}, {0, 4}, {1, 4}, {2, 4}, {3, 4}};
  const NodeSets hexaEdges{{0, 1}, {1, 2}, {2, 3}, {3, 0}, {0, 4}, {1, 5},
                           {2, 6}, {3, 7}, {4, 5}, {5, 6}, {6, 7}, {7, 4}};
  switch (t) {
    case CellType::SEG3: return withVertices(2, {{0, 1}});
    case CellType::TRIA6: return withVertices(3, triEdges);
    case CellType::TRIA7: return withVertices(3, concat(triEdges, allVertices(3)));
    case CellType::QUAD8: return withVertices(4, quadEdges);
    case CellType::QUAD9: return withVertices(4, concat(quadEdges, allVertices(4)));
    case CellType::TETRA10: return withVertices(4, tetEdges);
    case CellType::PENTA15: return withVertices(6, pentaEdges);
    case CellType::PENTA18:
      return withVertices(6, concat(pentaEdges, {{0, 1, 4, 3}, {1, 2, 5, 4}, {2, 0, 3, 5}}));
    case CellType::PYRAM13: return withVertices(5, pyramEdges);
    case CellType::HEXA20: return withVertices(8, hexaEdges);
    case CellType::HEXA27:
      return withVertices(8, concat(concat(hexaEdges, {{0, 1, 2, 3}, {0, 1, 5, 4}, {1, 2, 6, 5},
                                                        {2, 3, 7, 6}, {3, 0, 4, 7}, {4, 5, 6, 7}}),
                                    allVertices(8)));
    default: return withVertices(vertexCount(t), {});
  }
}

// gmsh's definitions (gmsh's documented node ordering; its vertices agree with code_aster's).
NodeSets gmshSets(CellType t) {
  const NodeSets hexaEdges{{0, 1}, {0, 3}, {0, 4}, {1, 2}, {1, 5}, {2, 3},
                           {2, 6}, {3, 7}, {4, 5}, {4, 7}, {5, 6}, {6, 7}};
  const NodeSets prismEdges{{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 4}, {2, 5}, {3, 4}, {3, 5}, {4, 5}};
  switch (t) {
    case CellType::TRIA7: throw Error("gmsh has no 7-node triangle (TRIA7)");
    case CellType::TETRA10:
      return withVertices(4, {{0, 1}, {1, 2}, {2, 0}, {3, 0}, {3, 2}, {3, 1}});
    case CellType::PENTA15: return withVertices(6, prismEdges);
    case CellType::PENTA18:
      return withVertices(6, concat(prismEdges, {{0, 1, 4, 3}, {0, 2, 5, 3}, {1, 2, 5, 4}}));
    case CellType::PYRAM13:
      return withVertices(5, {{0, 1}, {0, 3}, {0, 4}, {1, 2}, {1, 4}, {2, 3}, {2, 4}, {3, 4}});
    case CellType::HEXA20: return withVertices(8, hexaEdges);
    case CellType::HEXA27:
      return withVertices(8, concat(concat(hexaEdges, {{0, 3, 2, 1}, {0, 1, 5, 4}, {0, 4, 7, 3},
                                                        {1, 2, 6, 5}, {2, 3, 7, 6}, {4, 5, 6, 7}}),
                                    allVertices(8)));
    default: return asterSets(t);
  }
}

// VTK's definitions (VTK file format documentation, vtkCellType).
NodeSets vtkSets(CellType t) {
  const NodeSets hexaEdges{{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6},
                           {6, 7}, {7, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
  const NodeSets wedgeEdges{{0, 1}, {1, 2}, {2, 0}, {3, 4}, {4, 5}, {5, 3}, {0, 3}, {1, 4}, {2, 5}};
  switch (t) {
    case CellType::PENTA15: return withVertices(6, wedgeEdges);
    case CellType::PENTA18:
      return withVertices(6, concat(wedgeEdges, {{0, 1, 4, 3}, {1, 2, 5, 4}, {2, 0, 3, 5}}));
    case CellType::HEXA20: return withVertices(8, hexaEdges);
    case CellType::HEXA27:
      return withVertices(8, concat(concat(hexaEdges, {{0, 4, 7, 3}, {1, 2, 6, 5}, {0, 1, 5, 4},
                                                        {3, 2, 6, 7}, {0, 1, 2, 3}, {4, 5, 6, 7}}),
                                    allVertices(8)));
    default: return asterSets(t);
  }
}

std::vector<int> matchSets(CellType t, const NodeSets& foreign) {
  NodeSets aster = asterSets(t);
  NodeSets other = foreign;
  for (auto& s : aster) std::sort(s.begin(), s.end());
  for (auto& s : other) std::sort(s.begin(), s.end());
  std::vector<int> p(aster.size(), -1);
  for (std::size_t j = 0; j < aster.size(); ++j)
    for (std::size_t k = 0; k < other.size(); ++k)
      if (other[k] == aster[j]) p[j] = static_cast<int>(k);
  if (static_cast<int>(other.size()) != nodeCount(t) ||
      std::find(p.begin(), p.end(), -1) != p.end())
    throw Error("internal: inconsistent node ordering tables for " + cellTypeName(t));
  return p;
}

// code_aster's own table of MED to code_aster connectivity (node j of code_aster is
// node numnoa[j] of MED, 1-based); the types not listed agree.
std::vector<int> medPermutation(CellType t) {
  std::vector<int> numnoa;
  switch (t) {
    case CellType::TETRA4: numnoa = {1, 3, 2, 4}; break;
    case CellType::TETRA10: numnoa = {1, 3, 2, 4, 7, 6, 5, 8, 10, 9}; break;
    case CellType::PENTA6: numnoa = {1, 3, 2, 4, 6, 5}; break;
    case CellType::PENTA15: numnoa = {1, 3, 2, 4, 6, 5, 9, 8, 7, 13, 15, 14, 12, 11, 10}; break;
    case CellType::PENTA18:
      numnoa = {1, 3, 2, 4, 6, 5, 9, 8, 7, 13, 15, 14, 12, 11, 10, 18, 17, 16};
      break;
    case CellType::PYRAM5: numnoa = {1, 4, 3, 2, 5}; break;
    case CellType::PYRAM13: numnoa = {1, 4, 3, 2, 5, 9, 8, 7, 6, 10, 13, 12, 11}; break;
    case CellType::HEXA8: numnoa = {1, 4, 3, 2, 5, 8, 7, 6}; break;
    case CellType::HEXA20:
      numnoa = {1, 4, 3, 2, 5, 8, 7, 6, 12, 11, 10, 9, 17, 20, 19, 18, 16, 15, 14, 13};
      break;
    case CellType::HEXA27:
      numnoa = {1,  4,  3,  2,  5,  8,  7,  6,  12, 11, 10, 9,  17, 20,
                19, 18, 16, 15, 14, 13, 21, 25, 24, 23, 22, 26, 27};
      break;
    default: numnoa.resize(nodeCount(t)); std::iota(numnoa.begin(), numnoa.end(), 1);
  }
  for (int& k : numnoa) --k;
  return numnoa;
}

std::vector<int> identity(CellType t) {
  std::vector<int> p(nodeCount(t));
  std::iota(p.begin(), p.end(), 0);
  return p;
}

std::vector<int> build(NodeConvention c, CellType t) {
  if (c == NodeConvention::Med) return medPermutation(t);
  if (t == CellType::SEG4) return identity(t);  // ends, then the two inner nodes from the first end
  return matchSets(t, c == NodeConvention::Gmsh ? gmshSets(t) : vtkSets(t));
}

}  // namespace

const std::vector<int>& asterFromForeign(NodeConvention convention, CellType type) {
  static std::map<std::pair<int, int>, std::vector<int>> cache;
  static const bool filled = [] {
    for (int c = 0; c < 3; ++c)
      for (int t = 0; t < kCellTypeCount; ++t) {
        const auto conv = static_cast<NodeConvention>(c);
        const auto type = static_cast<CellType>(t);
        if (conv == NodeConvention::Gmsh && type == CellType::TRIA7) continue;
        cache[{c, t}] = build(conv, type);
      }
    return true;
  }();
  (void)filled;
  const auto it = cache.find({static_cast<int>(convention), static_cast<int>(type)});
  if (it == cache.end())
    throw Error("cell type " + cellTypeName(type) + " has no equivalent in the " +
                (convention == NodeConvention::Gmsh ? "gmsh" : convention == NodeConvention::Med ? "MED" : "VTK") +
                " format");
  return it->second;
}

std::vector<int> toAsterOrder(NodeConvention convention, CellType type, const std::vector<int>& foreign) {
  const auto& p = asterFromForeign(convention, type);
  std::vector<int> out(p.size());
  for (std::size_t j = 0; j < p.size(); ++j) out[j] = foreign[p[j]];
  return out;
}

std::vector<int> fromAsterOrder(NodeConvention convention, CellType type, const std::vector<int>& aster) {
  const auto& p = asterFromForeign(convention, type);
  std::vector<int> out(p.size());
  for (std::size_t j = 0; j < p.size(); ++j) out[p[j]] = aster[j];
  return out;
}

}  // namespace aster::mesh
