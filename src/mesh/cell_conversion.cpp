#include "mesh/cell_conversion.hpp"

#include <map>
#include <utility>

#include "core/error.hpp"

namespace aster::mesh {

namespace {

// A new mesh with the nodes of `in` (same indices and names).
Mesh withNodesOf(const Mesh& in) {
  Mesh out;
  out.title = in.title;
  out.setSpaceDimension(in.spaceDimension());
  out.reserve(in.nodeCount(), in.cellCount(), 0);
  for (int i = 0; i < in.nodeCount(); ++i) out.addNode(in.node(i), in.nodeName(i));
  return out;
}

void copyCellGroups(const Mesh& in, Mesh& out) {
  for (const auto& g : in.cellGroupNames()) out.addCellGroup(g, in.cellGroup(g));
}

void copyNodeGroups(const Mesh& in, Mesh& out) {
  for (const auto& g : in.nodeGroupNames()) out.addNodeGroup(g, in.nodeGroup(g));
}

std::vector<char> flags(const Mesh& mesh, const std::vector<int>& cells) {
  std::vector<char> chosen(mesh.cellCount(), 0);
  for (int c : cells) {
    if (c < 0 || c >= mesh.cellCount()) throw Error("cell index out of range");
    chosen[c] = 1;
  }
  return chosen;
}

// The next name <prefix><number> (number advanced), refusing one a node has.
std::string newNodeName(const Mesh& out, const std::string& prefix, int& number) {
  const std::string name = prefix + std::to_string(number++);
  if (out.findNode(name) >= 0)
    throw Error("the new node name " + name + " is already a node's: choose another PREF_NOEUD or PREF_NUME");
  return name;
}

}  // namespace

Mesh lineToQuadratic(const Mesh& in, const std::vector<int>& cells, const std::string& prefix, int firstNumber) {
  const std::vector<char> chosen = flags(in, cells);
  Mesh out = withNodesOf(in);
  std::map<std::pair<int, int>, int> middle;  // sorted edge -> its middle node
  int number = firstNumber;
  auto middleOf = [&](int a, int b) {
    const auto key = a < b ? std::make_pair(a, b) : std::make_pair(b, a);
    auto it = middle.find(key);
    if (it != middle.end()) return it->second;
    const int n = out.addNode(0.5 * (in.node(a) + in.node(b)), newNodeName(out, prefix, number));
    middle.emplace(key, n);
    return n;
  };
  for (int c = 0; c < in.cellCount(); ++c) {
    const CellType t = in.cellType(c);
    const auto nodes = in.cellNodes(c);
    std::vector<int> v(nodes.begin(), nodes.end());
    CellType to = t;
    if (chosen[c]) {
      if (t == CellType::SEG2) to = CellType::SEG3;
      if (t == CellType::TRIA3) to = CellType::TRIA6;
      if (t == CellType::QUAD4) to = CellType::QUAD8;
    }
    if (to != t) {
      const int corners = static_cast<int>(v.size());
      const int edges = corners == 2 ? 1 : corners;  // a segment has one edge, a polygon as many as corners
      for (int e = 0; e < edges; ++e) v.push_back(middleOf(v[e], v[(e + 1) % corners]));
    }
    out.addCell(to, v, in.cellName(c));
  }
  copyCellGroups(in, out);
  copyNodeGroups(in, out);
  return out;
}

Mesh quadraticToLinear(const Mesh& in, const std::vector<int>& cells) {
  const std::vector<char> chosen = flags(in, cells);
  auto linearOf = [](CellType t) {
    switch (t) {
      case CellType::SEG3: return CellType::SEG2;
      case CellType::TRIA6:
      case CellType::TRIA7: return CellType::TRIA3;
      case CellType::QUAD8:
      case CellType::QUAD9: return CellType::QUAD4;
      default: return t;
    }
  };
  // The cells' new connectivity (old node indices), then the nodes still used.
  std::vector<std::pair<CellType, std::vector<int>>> newCells;
  std::vector<char> used(in.nodeCount(), 0), dropped(in.nodeCount(), 0);
  for (int c = 0; c < in.cellCount(); ++c) {
    const CellType t = in.cellType(c);
    const auto nodes = in.cellNodes(c);
    const CellType to = chosen[c] ? linearOf(t) : t;
    const int kept = to == t ? nodes.size() : vertexCount(t);
    for (int i = kept; i < nodes.size(); ++i) dropped[nodes[i]] = 1;
    newCells.emplace_back(to, std::vector<int>(nodes.begin(), nodes.begin() + kept));
    for (int n : newCells.back().second) used[n] = 1;
  }
  std::vector<int> newIndex(in.nodeCount(), -1);
  Mesh out;
  out.title = in.title;
  out.setSpaceDimension(in.spaceDimension());
  for (int i = 0; i < in.nodeCount(); ++i)
    if (used[i] || !dropped[i]) newIndex[i] = out.addNode(in.node(i), in.nodeName(i));
  for (int c = 0; c < in.cellCount(); ++c) {
    std::vector<int> v = newCells[c].second;
    for (int& n : v) n = newIndex[n];
    out.addCell(newCells[c].first, v, in.cellName(c));
  }
  copyCellGroups(in, out);
  for (const auto& g : in.nodeGroupNames()) {
    std::vector<int> members;
    for (int n : in.nodeGroup(g))
      if (newIndex[n] >= 0) members.push_back(newIndex[n]);
    out.addNodeGroup(g, std::move(members));
  }
  return out;
}

Mesh addCentreNodes(const Mesh& in, const std::vector<int>& cells, const std::string& option,
                    const std::string& prefix, int firstNumber) {
  CellType from, to;
  double vertexWeight, middleWeight;  // shape functions at the reference centre
  if (option == "QUAD8_9") {
    from = CellType::QUAD8, to = CellType::QUAD9;
    vertexWeight = -0.25, middleWeight = 0.5;  // N at (0,0) of QUAD8
  } else if (option == "TRIA6_7") {
    from = CellType::TRIA6, to = CellType::TRIA7;
    vertexWeight = -1.0 / 9.0, middleWeight = 4.0 / 9.0;  // N at (1/3,1/3) of TRIA6
  } else {
    throw Error("MODI_MAILLE OPTION='" + option + "' is not available in aster-lite (QUAD8_9 and TRIA6_7 are)");
  }
  const std::vector<char> chosen = flags(in, cells);
  Mesh out = withNodesOf(in);
  int number = firstNumber;
  for (int c = 0; c < in.cellCount(); ++c) {
    const CellType t = in.cellType(c);
    const auto nodes = in.cellNodes(c);
    std::vector<int> v(nodes.begin(), nodes.end());
    if (chosen[c] && t == from) {
      const int corners = vertexCount(t);
      Eigen::Vector3d x = Eigen::Vector3d::Zero();
      for (int i = 0; i < nodes.size(); ++i) x += (i < corners ? vertexWeight : middleWeight) * in.node(nodes[i]);
      v.push_back(out.addNode(x, newNodeName(out, prefix, number)));
      out.addCell(to, v, in.cellName(c));
    } else {
      out.addCell(t, v, in.cellName(c));
    }
  }
  copyCellGroups(in, out);
  copyNodeGroups(in, out);
  return out;
}

}  // namespace aster::mesh
