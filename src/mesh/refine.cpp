#include "mesh/refine.hpp"

#include <algorithm>
#include <array>
#include <map>

#include "core/error.hpp"
#include "mesh/cell_children.hpp"
#include "mesh/group_ops.hpp"

namespace aster::mesh {

namespace {

using Ref = Eigen::Vector2d;

// Reference coordinates of the nodes of the splittable cells (code_aster order).
std::vector<Ref> referenceNodes(CellType t) {
  switch (t) {
    case CellType::TRIA3: return {{0, 0}, {1, 0}, {0, 1}};
    case CellType::TRIA6: return {{0, 0}, {1, 0}, {0, 1}, {0.5, 0}, {0.5, 0.5}, {0, 0.5}};
    case CellType::QUAD4: return {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    case CellType::QUAD8:
      return {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}, {0, -1}, {1, 0}, {0, 1}, {-1, 0}};
    case CellType::QUAD9:
      return {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}, {0, -1}, {1, 0}, {0, 1}, {-1, 0}, {0, 0}};
    default: throw Error("uniform refinement of " + cellTypeName(t) + " cells is not implemented");
  }
}

// Shape functions of the parent at a reference point (the isoparametric map).
std::vector<double> shape(CellType t, const Ref& p) {
  const double x = p[0], y = p[1];
  switch (t) {
    case CellType::TRIA3: return {1 - x - y, x, y};
    case CellType::TRIA6: {
      const double l0 = 1 - x - y, l1 = x, l2 = y;
      return {l0 * (2 * l0 - 1), l1 * (2 * l1 - 1), l2 * (2 * l2 - 1), 4 * l0 * l1, 4 * l1 * l2, 4 * l2 * l0};
    }
    case CellType::QUAD4:
      return {0.25 * (1 - x) * (1 - y), 0.25 * (1 + x) * (1 - y), 0.25 * (1 + x) * (1 + y),
              0.25 * (1 - x) * (1 + y)};
    case CellType::QUAD8: {
      std::vector<double> n(8);
      const auto ref = referenceNodes(t);
      for (int i = 0; i < 4; ++i) {
        const double xi = ref[i][0], yi = ref[i][1];
        n[i] = 0.25 * (1 + x * xi) * (1 + y * yi) * (x * xi + y * yi - 1);
      }
      for (int i = 4; i < 8; ++i) {
        const double xi = ref[i][0], yi = ref[i][1];
        n[i] = xi == 0 ? 0.5 * (1 - x * x) * (1 + y * yi) : 0.5 * (1 + x * xi) * (1 - y * y);
      }
      return n;
    }
    case CellType::QUAD9: {
      auto l = [](double s, double si) { return si < 0 ? 0.5 * s * (s - 1) : si > 0 ? 0.5 * s * (s + 1) : 1 - s * s; };
      std::vector<double> n(9);
      const auto ref = referenceNodes(t);
      for (int i = 0; i < 9; ++i) n[i] = l(x, ref[i][0]) * l(y, ref[i][1]);
      return n;
    }
    default: throw Error("uniform refinement of " + cellTypeName(t) + " cells is not implemented");
  }
}

// Corners (reference points) of the 4 children, counterclockwise like the parent.
std::vector<std::array<Ref, 4>> childCorners(CellType t) {
  if (vertexCount(t) == 3) {
    const Ref v0{0, 0}, v1{1, 0}, v2{0, 1}, e0{0.5, 0}, e1{0.5, 0.5}, e2{0, 0.5};
    return {{v0, e0, e2, v0}, {e0, v1, e1, v0}, {e2, e1, v2, v0}, {e0, e1, e2, v0}};  // 4th unused
  }
  const Ref v[4] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
  const Ref e[4] = {{0, -1}, {1, 0}, {0, 1}, {-1, 0}};
  const Ref c{0, 0};
  std::vector<std::array<Ref, 4>> out;
  for (int k = 0; k < 4; ++k) out.push_back({v[k], e[k], c, e[(k + 3) % 4]});
  return out;
}

CellType linearOf(CellType t) { return vertexCount(t) == 3 ? CellType::TRIA3 : CellType::QUAD4; }

class Refiner {
 public:
  explicit Refiner(const Mesh& in) : in_(in) {
    out_.title = in.title;
    out_.setSpaceDimension(in.spaceDimension());
    for (int i = 0; i < in.nodeCount(); ++i) out_.addNode(in.node(i), in.nodeName(i));
  }

  Mesh run(const std::vector<int>& selection) {
    std::vector<char> split(in_.cellCount(), 0);
    if (selection.empty()) {
      for (int c = 0; c < in_.cellCount(); ++c)
        if (topologicalDimension(in_.cellType(c)) == 2) split[c] = 1;
    } else {
      for (int c : selection) {
        if (c < 0 || c >= in_.cellCount()) throw Error("refinement: cell index out of range");
        if (topologicalDimension(in_.cellType(c)) == 2) split[c] = 1;
      }
    }
    // Children of every split 2D cell (their nodes created on the way).
    std::vector<CellChildren> children(in_.cellCount());
    for (int c = 0; c < in_.cellCount(); ++c)
      if (split[c]) children[c] = splitSurface(c);
    // Then the segments lying on split edges.
    for (int c = 0; c < in_.cellCount(); ++c)
      if (!split[c]) children[c] = splitSegment(c);

    addCellsAndChildren(in_, children, out_);
    refineNodeGroups();
    return std::move(out_);
  }

 private:
  static std::pair<int, int> key(int a, int b) { return a < b ? std::make_pair(a, b) : std::make_pair(b, a); }

  Eigen::Vector3d map(CellType t, const int* nodes, const Ref& p) const {
    const auto n = shape(t, p);
    Eigen::Vector3d x = Eigen::Vector3d::Zero();
    for (std::size_t i = 0; i < n.size(); ++i) x += n[i] * in_.node(nodes[i]);
    return x;
  }

  // The node in the middle of global nodes a and b (reference points pa, pb of this parent).
  int middle(int a, int b, CellType t, const int* nodes, const Ref& pa, const Ref& pb) {
    const auto k = key(a, b);
    const auto it = mid_.find(k);
    if (it != mid_.end()) return it->second;
    const int n = newNode(map(t, nodes, 0.5 * (pa + pb)), {a, b});
    mid_.emplace(k, n);
    return n;
  }

  CellChildren splitSurface(int c) {
    const CellType t = in_.cellType(c);
    const auto ref = referenceNodes(t);
    const auto cn = in_.cellNodes(c);
    const int* nodes = cn.first;
    const int nv = vertexCount(t);
    // Global node at a child corner: an existing parent node, a shared edge middle, or the centre.
    int centre = -1;
    auto cornerNode = [&](const Ref& p) -> int {
      for (std::size_t i = 0; i < ref.size(); ++i)
        if ((ref[i] - p).norm() < 1e-12) return nodes[i];
      for (int i = 0; i < nv; ++i) {
        const int j = (i + 1) % nv;
        if ((0.5 * (ref[i] + ref[j]) - p).norm() < 1e-12) return middle(nodes[i], nodes[j], t, nodes, ref[i], ref[j]);
      }
      if (centre < 0) centre = newNode(map(t, nodes, p), std::vector<int>(cn.begin(), cn.end()));
      return centre;
    };
    std::vector<std::pair<CellType, std::vector<int>>> out;
    const auto corners = childCorners(t);
    for (const auto& cc : corners) {
      std::vector<int> child;
      std::vector<Ref> pts(cc.begin(), cc.begin() + nv);
      for (const auto& p : pts) child.push_back(cornerNode(p));
      if (t != linearOf(t)) {
        for (int i = 0; i < nv; ++i) {
          const int j = (i + 1) % nv;
          child.push_back(middle(child[i], child[j], t, nodes, pts[i], pts[j]));
        }
        if (t == CellType::QUAD9) {
          Ref m = Ref::Zero();
          for (const auto& p : pts) m += 0.25 * p;
          child.push_back(newNode(map(t, nodes, m), child));
        }
      }
      out.emplace_back(t, std::move(child));
    }
    return out;
  }

  CellChildren splitSegment(int c) {
    const CellType t = in_.cellType(c);
    const auto n = in_.cellNodes(c);
    if (t == CellType::SEG2) {
      const auto it = mid_.find(key(n[0], n[1]));
      if (it == mid_.end()) return {};
      return {{t, {n[0], it->second}}, {t, {it->second, n[1]}}};
    }
    if (t == CellType::SEG3) {
      const auto a = mid_.find(key(n[0], n[2])), b = mid_.find(key(n[2], n[1]));
      if (a == mid_.end() || b == mid_.end()) return {};
      return {{t, {n[0], n[2], a->second}}, {t, {n[2], n[1], b->second}}};
    }
    return {};
  }

  // A node the refinement creates, with the nodes it lies between: the two
  // ends of the edge it halves, or every node of the cell whose centre it is.
  int newNode(const Eigen::Vector3d& x, std::vector<int> between) {
    between_.push_back(std::move(between));
    return out_.addNode(x);
  }

  static std::vector<int> sortedSet(std::vector<int> v) {
    std::sort(v.begin(), v.end());
    v.erase(std::unique(v.begin(), v.end()), v.end());
    return v;
  }

  // The nodes of the segments of cell group `group` of `mesh` in chain order
  // from `first` (as DEFI_GROUP's NOEUD_ORDO gives), or empty when they form
  // no open chain with `first` at an end.
  static std::vector<int> chainFrom(const Mesh& mesh, const std::string& group, int first) {
    try {
      return orderedChainNodes(mesh, mesh.cellGroup(group), first);
    } catch (const Error&) {
      return {};
    }
  }

  // Node groups follow the cells they were made from. A group whose nodes are
  // exactly those of a group of cells becomes the nodes of that group's refined
  // cells (in chain order when it was the ordered chain of those segments,
  // else its old nodes in their order, then the new ones). A group no new node
  // lies between (points, scattered nodes) is kept as it is. Any other group is
  // ambiguous: which new nodes belong to it cannot be told from its nodes
  // (HOMARD, code_aster's refinement tool, keeps only their old nodes and asks
  // for boundary conditions on cells): the refinement stops naming it.
  void refineNodeGroups() {
    if (in_.nodeGroupNames().empty()) return;
    const auto cellGroups = in_.cellGroupNames();
    std::vector<std::vector<int>> nodesOfGroup(cellGroups.size());
    for (std::size_t k = 0; k < cellGroups.size(); ++k)
      nodesOfGroup[k] = sortedSet(in_.nodesOfCells(in_.cellGroup(cellGroups[k])));
    std::vector<std::string> ambiguous;
    for (const auto& g : in_.nodeGroupNames()) {
      const std::vector<int>& nodes = in_.nodeGroup(g);
      const std::vector<int> set = sortedSet(nodes);
      std::vector<std::size_t> sources;
      if (!set.empty())
        for (std::size_t k = 0; k < cellGroups.size(); ++k)
          if (nodesOfGroup[k] == set) sources.push_back(k);
      if (!sources.empty()) {
        const std::string& source = cellGroups[sources[0]];
        const std::vector<int> refined = sortedSet(out_.nodesOfCells(out_.cellGroup(source)));
        std::string disagreeing;
        for (std::size_t k = 1; k < sources.size() && disagreeing.empty(); ++k)
          if (sortedSet(out_.nodesOfCells(out_.cellGroup(cellGroups[sources[k]]))) != refined)
            disagreeing = cellGroups[sources[k]];
        if (!disagreeing.empty()) {
          ambiguous.push_back("'" + g + "' has exactly the nodes of the groups of cells '" + source + "' and '" +
                              disagreeing + "', whose refined cells have different nodes");
          continue;
        }
        std::vector<int> members;
        if (nodes.size() > 1 && chainFrom(in_, source, nodes[0]) == nodes) {
          members = chainFrom(out_, source, nodes[0]);
        } else {
          members = nodes;
          for (int n : refined)
            if (n >= in_.nodeCount()) members.push_back(n);
        }
        out_.addNodeGroup(g, std::move(members));
        continue;
      }
      // No group of cells to follow: is some new node between nodes of g?
      std::vector<char> in(out_.nodeCount(), 0);
      for (int n : nodes) in[n] = 1;
      int example = -1;
      for (int n = in_.nodeCount(); n < out_.nodeCount() && example < 0; ++n) {
        const auto& between = between_[n - in_.nodeCount()];
        in[n] = std::all_of(between.begin(), between.end(), [&](int b) { return in[b] != 0; });
        if (in[n]) example = n;
      }
      if (example < 0) {
        out_.addNodeGroup(g, nodes);
        continue;
      }
      std::string around;
      for (int b : between_[example - in_.nodeCount()]) around += (around.empty() ? "" : ", ") + out_.nodeName(b);
      ambiguous.push_back("'" + g + "': the new node " + out_.nodeName(example) + " lies between its nodes " + around +
                          " and no group of cells has exactly its nodes");
    }
    if (!ambiguous.empty()) {
      std::string list;
      for (const auto& a : ambiguous) list += (list.empty() ? "" : "; ") + a;
      throw Error("GROUP_NO " + list +
                  ". Which new nodes belong to such a group of nodes cannot be told: define it from cells (a "
                  "GROUP_MA with exactly its nodes, which it then follows; or, on the refined mesh, DEFI_GROUP "
                  "CREA_GROUP_NO from a GROUP_MA, or the GROUP_MA itself in the loads), or delete it before "
                  "refining (DEFI_GROUP DETR_GROUP_NO)");
    }
  }

  const Mesh& in_;
  Mesh out_;
  std::map<std::pair<int, int>, int> mid_;
  std::vector<std::vector<int>> between_;  // of each new node, by index - in_.nodeCount()
};

}  // namespace

Mesh refineUniformly(const Mesh& mesh, const std::vector<int>& cells) {
  for (int c : cells)
    if (c >= 0 && c < mesh.cellCount() && topologicalDimension(mesh.cellType(c)) == 2) referenceNodes(mesh.cellType(c));
  if (cells.empty())
    for (int c = 0; c < mesh.cellCount(); ++c)
      if (topologicalDimension(mesh.cellType(c)) == 2) referenceNodes(mesh.cellType(c));
  return Refiner(mesh).run(cells);
}

}  // namespace aster::mesh
