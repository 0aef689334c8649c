#include "mesh/orient.hpp"

#include <algorithm>
#include <map>

#include "core/error.hpp"

namespace aster::mesh {

namespace {

bool isSegment(CellType t) { return t == CellType::SEG2 || t == CellType::SEG3 || t == CellType::SEG4; }

// Twice the signed area of the cell's vertex polygon in the XY plane.
double signedArea(const Mesh& mesh, int c) {
  const int nv = vertexCount(mesh.cellType(c));
  const auto n = mesh.cellNodes(c);
  double a = 0;
  for (int i = 0; i < nv; ++i) {
    const auto p = mesh.node(n[i]), q = mesh.node(n[(i + 1) % nv]);
    a += p[0] * q[1] - q[0] * p[1];
  }
  return a;
}

// Directed vertex edges of every 2D cell: {a, b} (sorted) -> the cells having it.
std::map<std::pair<int, int>, std::vector<int>> cellsOnEdges(const Mesh& mesh) {
  std::map<std::pair<int, int>, std::vector<int>> cellsOnEdge;
  for (int c = 0; c < mesh.cellCount(); ++c) {
    if (topologicalDimension(mesh.cellType(c)) != 2) continue;
    const int nv = vertexCount(mesh.cellType(c));
    const auto n = mesh.cellNodes(c);
    for (int i = 0; i < nv; ++i) cellsOnEdge[std::minmax(n[i], n[(i + 1) % nv])].push_back(c);
  }
  return cellsOnEdge;
}

// Whether the segment a -> b, an edge of the 2D cell c, has its normal (dy, -dx) out of c.
bool pointsOutOf(const Mesh& mesh, int c, int a, int b) {
  const int nv = vertexCount(mesh.cellType(c));
  const auto n = mesh.cellNodes(c);
  bool sameWay = false;  // the cell's vertex cycle goes a -> b
  for (int i = 0; i < nv; ++i)
    if (n[i] == a && n[(i + 1) % nv] == b) sameWay = true;
  // Walking a counterclockwise cell's cycle keeps the outside on the right: normal (dy, -dx).
  return sameWay == (signedArea(mesh, c) > 0);
}

}  // namespace

std::vector<InwardSegment> inwardSegments(const Mesh& mesh, const std::vector<int>& cells) {
  const auto cellsOnEdge = cellsOnEdges(mesh);
  std::vector<InwardSegment> out;
  for (int s : cells) {
    if (s < 0 || s >= mesh.cellCount() || !isSegment(mesh.cellType(s))) continue;
    const int a = mesh.cellNodes(s)[0], b = mesh.cellNodes(s)[1];
    const auto it = cellsOnEdge.find(std::minmax(a, b));
    if (it == cellsOnEdge.end() || it->second.size() != 1) continue;
    if (!pointsOutOf(mesh, it->second[0], a, b)) out.push_back({s, it->second[0]});
  }
  return out;
}

void reverseSegment(Mesh& mesh, int cell) {
  const auto n = mesh.cellNodes(cell);
  switch (mesh.cellType(cell)) {
    case CellType::SEG2: mesh.setCellNodes(cell, {n[1], n[0]}); break;
    case CellType::SEG3: mesh.setCellNodes(cell, {n[1], n[0], n[2]}); break;
    case CellType::SEG4: mesh.setCellNodes(cell, {n[1], n[0], n[3], n[2]}); break;
    default: throw Error("cell '" + mesh.cellName(cell) + "' is a " + cellTypeName(mesh.cellType(cell)) + ", not a segment");
  }
}

int orientBoundarySegments(Mesh& mesh, const std::vector<int>& cells) {
  const auto cellsOnEdge = cellsOnEdges(mesh);
  int reversed = 0;
  std::vector<int> free;
  for (int s : cells) {
    if (s < 0 || s >= mesh.cellCount()) throw Error("ORIE_PEAU: cell index out of range");
    if (!isSegment(mesh.cellType(s)))
      throw Error("ORIE_PEAU: cell '" + mesh.cellName(s) + "' is a " + cellTypeName(mesh.cellType(s)) +
                  "; only segments (SEG2, SEG3, SEG4) can be oriented in 2D");
    const int a = mesh.cellNodes(s)[0], b = mesh.cellNodes(s)[1];
    const auto it = cellsOnEdge.find(std::minmax(a, b));
    if (it == cellsOnEdge.end()) {
      free.push_back(s);
      continue;
    }
    if (it->second.size() > 1)
      throw Error("ORIE_PEAU: segment '" + mesh.cellName(s) + "' lies between the 2D cells '" +
                  mesh.cellName(it->second[0]) + "' and '" + mesh.cellName(it->second[1]) +
                  "': it is not on the boundary, its outward side is undefined");
    if (!pointsOutOf(mesh, it->second[0], a, b)) {
      reverseSegment(mesh, s);
      ++reversed;
    }
  }
  // Free segments: follow each chain from its first segment.
  std::vector<char> done(mesh.cellCount(), 0);
  for (int first : free) {
    if (done[first]) continue;
    done[first] = 1;
    std::vector<int> stack{first};
    while (!stack.empty()) {
      const int s = stack.back();
      stack.pop_back();
      const int a = mesh.cellNodes(s)[0], b = mesh.cellNodes(s)[1];
      for (int t : free) {
        if (done[t]) continue;
        const int ta = mesh.cellNodes(t)[0], tb = mesh.cellNodes(t)[1];
        // Consistent when t continues s (starts at b) or precedes it (ends at a).
        if (ta == b || tb == a) {
        } else if (tb == b || ta == a) {
          reverseSegment(mesh, t);
          ++reversed;
        } else {
          continue;
        }
        done[t] = 1;
        stack.push_back(t);
      }
    }
  }
  return reversed;
}

}  // namespace aster::mesh
