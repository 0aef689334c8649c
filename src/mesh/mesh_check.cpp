#include "mesh/mesh_check.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <cmath>
#include <cstdio>

#include "core/error.hpp"
#include "core/number_format.hpp"
#include "mesh/group_ops.hpp"

namespace aster::mesh {

namespace {

constexpr std::size_t kListed = 10;  // names listed in a message, then a count

std::string sci(double v) { return format::significant(v, 3); }

// "a, b, c" then "and 12 more".
std::string listed(const std::vector<std::string>& items) {
  std::string s;
  for (std::size_t k = 0; k < items.size() && k < kListed; ++k) s += (k ? ", " : "") + items[k];
  if (items.size() > kListed) s += " and " + std::to_string(items.size() - kListed) + " more";
  return s;
}

}  // namespace

void checkFiniteCoordinates(const Mesh& mesh) {
  const auto& xyz = mesh.coordinates();
  for (int i = 0; i < mesh.nodeCount(); ++i)
    if (!std::isfinite(xyz[3 * i]) || !std::isfinite(xyz[3 * i + 1]) || !std::isfinite(xyz[3 * i + 2]))
      throw Error("node '" + mesh.nodeName(i) + "' has a coordinate that is not a finite number: (" +
                  sci(xyz[3 * i]) + ", " + sci(xyz[3 * i + 1]) + ", " + sci(xyz[3 * i + 2]) + ")");
}

std::string describeCell(const Mesh& mesh, int cell, const std::vector<std::vector<int>>& groupsOfCells) {
  std::string s = mesh.cellName(cell) + " (" + cellTypeName(mesh.cellType(cell));
  const auto names = mesh.cellGroupNames();
  if (cell < static_cast<int>(groupsOfCells.size()) && !groupsOfCells[cell].empty()) {
    s += " of ";
    for (std::size_t k = 0; k < groupsOfCells[cell].size(); ++k) s += (k ? ", " : "") + names[groupsOfCells[cell][k]];
  }
  return s + ")";
}

MeshDefects findDefects(const Mesh& mesh, double flatness) {
  MeshDefects d;
  std::vector<std::vector<int>> groups;  // computed only when a cell is named
  auto name = [&](int c) {
    if (groups.empty()) groups = groupsOfEachCell(mesh);
    return describeCell(mesh, c, groups);
  };

  const auto orphans = mesh.orphanNodes();
  if (!orphans.empty()) {
    std::vector<std::string> names;
    for (int n : orphans) names.push_back(mesh.nodeName(n));
    d.alarms.push_back(std::to_string(orphans.size()) + " node" + (orphans.size() > 1 ? "s belong" : " belongs") +
                       " to no cell (orphan): " + listed(names));
  }

  std::vector<std::string> repeated, flat, doubles;
  // Cells with the same nodes: equal sorted connectivities, found by sorting
  // (hash, cell) pairs and comparing equal hashes exactly.
  std::vector<std::pair<std::uint64_t, int>> keys;
  keys.reserve(mesh.cellCount());
  std::array<int, kMaxCellNodes> sorted{};
  auto sortedNodes = [&](int c) {
    const auto n = mesh.cellNodes(c);
    std::copy(n.begin(), n.end(), sorted.begin());
    std::sort(sorted.begin(), sorted.begin() + n.size());
    return n.size();
  };
  for (int c = 0; c < mesh.cellCount(); ++c) {
    const auto n = mesh.cellNodes(c);
    const int count = sortedNodes(c);
    if (const auto twice = std::adjacent_find(sorted.begin(), sorted.begin() + count); twice != sorted.begin() + count) {
      repeated.push_back(name(c) + ": node " + mesh.nodeName(*twice) + " twice");
      continue;
    }
    if (count < 2) continue;
    std::uint64_t h = 1469598103934665603ull;  // FNV-1a over the sorted node indices
    for (int k = 0; k < count; ++k) h = (h ^ static_cast<std::uint64_t>(sorted[k])) * 1099511628211ull;
    keys.emplace_back(h, c);
    double shortest = INFINITY, longest = 0;
    for (int a = 0; a < count; ++a)
      for (int b = a + 1; b < count; ++b) {
        const double l = (mesh.node(n[a]) - mesh.node(n[b])).norm();
        shortest = std::min(shortest, l);
        longest = std::max(longest, l);
      }
    if (longest == 0 || !(shortest >= flatness * longest))
      flat.push_back(name(c) + ": " + (longest == 0 ? std::string("all its nodes coincide")
                                                    : "ratio " + sci(shortest / longest)));
  }
  std::sort(keys.begin(), keys.end());
  for (std::size_t i = 0; i < keys.size();) {
    std::size_t j = i + 1;
    while (j < keys.size() && keys[j].first == keys[i].first) ++j;
    for (std::size_t a = i; a < j; ++a) {  // a run of equal hashes: compare exactly
      const int ca = keys[a].second, na = sortedNodes(ca);
      const std::vector<int> first(sorted.begin(), sorted.begin() + na);
      for (std::size_t b = a + 1; b < j; ++b) {
        const int cb = keys[b].second, nb = sortedNodes(cb);
        if (nb == na && std::equal(first.begin(), first.end(), sorted.begin())) {
          doubles.push_back(name(ca) + " and " + name(cb));
          break;
        }
      }
    }
    i = j;
  }
  if (!doubles.empty())
    d.alarms.push_back(std::to_string(doubles.size()) + " cell" + (doubles.size() > 1 ? "s have" : " has") +
                       " the same nodes as another (elements on both would count that part twice): " + listed(doubles));
  if (!flat.empty())
    d.alarms.push_back(std::to_string(flat.size()) + " cell" + (flat.size() > 1 ? "s are" : " is") +
                       " flattened or degenerate (smallest over largest distance between two of its nodes below "
                       "APLAT = " + sci(flatness) + "): " + listed(flat));
  if (!repeated.empty())
    d.fatal = std::to_string(repeated.size()) + " cell" + (repeated.size() > 1 ? "s have" : " has") +
              " a node repeated in its connectivity (topologically degenerate, no element can be built on it): " +
              listed(repeated);
  return d;
}

}  // namespace aster::mesh
