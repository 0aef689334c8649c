#include "mesh/refine.hpp"

#include <array>
#include <map>
#include <unordered_set>

#include "core/error.hpp"

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
    std::vector<std::vector<std::pair<CellType, std::vector<int>>>> children(in_.cellCount());
    for (int c = 0; c < in_.cellCount(); ++c)
      if (split[c]) children[c] = splitSurface(c);
    // Then the segments lying on split edges.
    for (int c = 0; c < in_.cellCount(); ++c)
      if (!split[c]) children[c] = splitSegment(c);

    // Names: untouched cells keep theirs, children get fresh ones.
    std::unordered_set<std::string> taken;
    for (int c = 0; c < in_.cellCount(); ++c)
      if (children[c].empty()) taken.insert(in_.cellName(c));
    int counter = 1;
    auto freshName = [&] {
      std::string name;
      do name = "M" + std::to_string(counter++);
      while (taken.count(name));
      taken.insert(name);
      return name;
    };
    std::vector<std::vector<int>> newCells(in_.cellCount());
    for (int c = 0; c < in_.cellCount(); ++c) {
      if (children[c].empty()) {
        const auto n = in_.cellNodes(c);
        newCells[c].push_back(out_.addCell(in_.cellType(c), n.first, n.count, in_.cellName(c)));
      } else {
        for (const auto& [type, nodes] : children[c]) newCells[c].push_back(out_.addCell(type, nodes, freshName()));
      }
    }
    for (const auto& g : in_.cellGroupNames()) {
      std::vector<int> members;
      for (int c : in_.cellGroup(g)) members.insert(members.end(), newCells[c].begin(), newCells[c].end());
      out_.addCellGroup(g, std::move(members));
    }
    for (const auto& g : in_.nodeGroupNames()) out_.addNodeGroup(g, in_.nodeGroup(g));
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
    const int n = out_.addNode(map(t, nodes, 0.5 * (pa + pb)));
    mid_.emplace(k, n);
    return n;
  }

  std::vector<std::pair<CellType, std::vector<int>>> splitSurface(int c) {
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
      if (centre < 0) centre = out_.addNode(map(t, nodes, p));
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
          child.push_back(out_.addNode(map(t, nodes, m)));
        }
      }
      out.emplace_back(t, std::move(child));
    }
    return out;
  }

  std::vector<std::pair<CellType, std::vector<int>>> splitSegment(int c) {
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

  const Mesh& in_;
  Mesh out_;
  std::map<std::pair<int, int>, int> mid_;
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
