#include "mesh/lac_patches.hpp"

#include <map>
#include <utility>

#include "core/error.hpp"
#include "mesh/cell_children.hpp"

namespace aster::mesh {

namespace {

std::pair<int, int> edgeKey(int a, int b) { return a < b ? std::make_pair(a, b) : std::make_pair(b, a); }

// Bilinear map of the quadrangle p (nodes 0..3 counterclockwise from (-1,-1)).
Eigen::Vector3d bilinear(const Eigen::Vector3d p[4], double xi, double eta) {
  return 0.25 * ((1 - xi) * (1 - eta) * p[0] + (1 + xi) * (1 - eta) * p[1] + (1 + xi) * (1 + eta) * p[2] +
                 (1 - xi) * (1 + eta) * p[3]);
}

}  // namespace

LacPatches cutLacPatches(const Mesh& in, const std::vector<int>& slaveCells) {
  // The 2D cells on each vertex edge.
  std::map<std::pair<int, int>, std::vector<int>> cellsOnEdge;
  for (int c = 0; c < in.cellCount(); ++c) {
    if (topologicalDimension(in.cellType(c)) != 2) continue;
    const auto n = in.cellNodes(c);
    const int corners = vertexCount(in.cellType(c));
    for (int e = 0; e < corners; ++e) cellsOnEdge[edgeKey(n[e], n[(e + 1) % corners])].push_back(c);
  }

  Mesh out;
  out.title = in.title;
  out.setSpaceDimension(in.spaceDimension());
  for (int i = 0; i < in.nodeCount(); ++i) out.addNode(in.node(i), in.nodeName(i));
  auto newNode = [&](const Eigen::Vector3d& x, const char* prefix) {
    std::string name = prefix + std::to_string(out.nodeCount() + 1);
    if (out.findNode(name) >= 0) name = out.freshNodeName(prefix);
    return out.addNode(x, name);
  };

  std::vector<CellChildren> children(in.cellCount());
  std::vector<int> slaveOf(in.cellCount(), -1);  // the 2D cell -> the slave segment it bears
  for (int s : slaveCells) {
    const CellType st = in.cellType(s);
    const std::string where = "slave cell " + in.cellName(s) + " (" + cellTypeName(st) + ")";
    if (st != CellType::SEG2 && st != CellType::SEG3)
      throw Error(where + ": DECOUPE_LAC cuts patches under segments (SEG2, SEG3) in 2D");
    const auto sn = in.cellNodes(s);
    const int a = sn[0], b = sn[1];
    auto found = cellsOnEdge.find(edgeKey(a, b));
    if (found == cellsOnEdge.end())
      throw Error(where + " lies on the edge of no 2D cell: DECOUPE_LAC needs the cell under each slave segment");
    if (found->second.size() > 1)
      throw Error(where + " lies between two 2D cells: a slave segment must be on the boundary");
    const int c = found->second.front();
    const CellType ct = in.cellType(c);
    if (slaveOf[c] >= 0)
      throw Error(where + ": the 2D cell " + in.cellName(c) + " under it also bears the slave cell " +
                  in.cellName(slaveOf[c]) + "; DECOUPE_LAC in aster-lite cuts a cell under one slave segment only");
    slaveOf[c] = s;
    const bool linear = st == CellType::SEG2;
    if (linear != (ct == CellType::TRIA3 || ct == CellType::QUAD4) ||
        !(ct == CellType::TRIA3 || ct == CellType::QUAD4 || ct == CellType::TRIA6 || ct == CellType::QUAD8))
      throw Error(where + " lies on the " + cellTypeName(ct) + " cell " + in.cellName(c) +
                  ": DECOUPE_LAC takes SEG2 on TRIA3 or QUAD4, SEG3 on TRIA6 or QUAD8");
    if (!linear) continue;  // quadratic: the segment is its own patch

    // Local numbering of the 2D cell starting at the slave edge: p0 p1 is the edge.
    const auto cn = in.cellNodes(c);
    const int corners = vertexCount(ct);
    int first = 0;
    while (edgeKey(cn[first], cn[(first + 1) % corners]) != edgeKey(a, b)) ++first;
    std::vector<int> p(corners);
    for (int i = 0; i < corners; ++i) p[i] = cn[(first + i) % corners];
    const bool sameWay = p[0] == a;  // the segment runs from p0 to p1
    if (ct == CellType::TRIA3) {
      const int m = newNode(0.5 * (in.node(a) + in.node(b)), "C");
      children[s] = {{CellType::SEG2, {a, m}}, {CellType::SEG2, {m, b}}};
      children[c] = {{CellType::TRIA3, {p[0], m, p[2]}}, {CellType::TRIA3, {m, p[1], p[2]}}};
    } else {
      const Eigen::Vector3d x[4] = {in.node(p[0]), in.node(p[1]), in.node(p[2]), in.node(p[3])};
      const int s0 = newNode(bilinear(x, -1.0 / 3, -1), "C"), s1 = newNode(bilinear(x, 1.0 / 3, -1), "C");
      const int i0 = newNode(bilinear(x, -1.0 / 3, 0), "L"), i1 = newNode(bilinear(x, 1.0 / 3, 0), "L");
      if (sameWay)
        children[s] = {{CellType::SEG2, {a, s0}}, {CellType::SEG2, {s0, s1}}, {CellType::SEG2, {s1, b}}};
      else
        children[s] = {{CellType::SEG2, {a, s1}}, {CellType::SEG2, {s1, s0}}, {CellType::SEG2, {s0, b}}};
      children[c] = {{CellType::QUAD4, {p[0], s0, i0, p[3]}},
                     {CellType::QUAD4, {s0, s1, i1, i0}},
                     {CellType::QUAD4, {s1, p[1], p[2], i1}},
                     {CellType::QUAD4, {p[2], p[3], i0, i1}}};
    }
  }

  const std::vector<std::vector<int>> newCells = addCellsAndChildren(in, children, out);
  for (const auto& g : in.nodeGroupNames()) out.addNodeGroup(g, in.nodeGroup(g));

  LacPatches result{std::move(out), {}};
  for (int s : slaveCells) result.patches.push_back(newCells[s]);
  return result;
}

}  // namespace aster::mesh
