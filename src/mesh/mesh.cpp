#include "mesh/mesh.hpp"

#include <algorithm>
#include <map>
#include <sstream>

#include "core/error.hpp"
#include "core/suggest.hpp"

namespace aster::mesh {

void Mesh::setSpaceDimension(int dim) {
  if (dim < 1 || dim > 3) throw Error("space dimension must be 1, 2 or 3, got " + std::to_string(dim));
  spaceDim_ = dim;
}

void Mesh::reserve(int nodes, int cells, int cellNodes) {
  const auto n = static_cast<std::size_t>(std::max(nodes, 0));
  const auto c = static_cast<std::size_t>(std::max(cells, 0));
  xyz_.reserve(3 * n);
  nodeNames_.reserve(n);
  nodeByName_.reserve(n);
  types_.reserve(c);
  offsets_.reserve(c + 1);
  conn_.reserve(static_cast<std::size_t>(std::max(cellNodes, 0)));
  cellNames_.reserve(c);
  cellByName_.reserve(c);
}

std::string Mesh::freshNodeName(const std::string& prefix) {
  std::string name;
  do name = prefix + std::to_string(nextNodeNumber_++);
  while (nodeByName_.count(name));
  return name;
}

std::string Mesh::freshCellName(const std::string& prefix) {
  std::string name;
  do name = prefix + std::to_string(nextCellNumber_++);
  while (cellByName_.count(name));
  return name;
}

int Mesh::addNode(const Eigen::Vector3d& x, const std::string& name) {
  const std::string n = name.empty() ? freshNodeName() : name;
  const int index = nodeCount();
  if (!nodeByName_.emplace(n, index).second) throw Error("duplicate node name '" + n + "'");
  nodeNames_.push_back(n);
  xyz_.insert(xyz_.end(), {x[0], x[1], x[2]});
  return index;
}

void Mesh::setNode(int i, const Eigen::Vector3d& x) {
  if (i < 0 || i >= nodeCount()) throw Error("node index " + std::to_string(i) + " out of range");
  for (int k = 0; k < 3; ++k) xyz_[3 * i + k] = x[k];
}

int Mesh::findNode(const std::string& name) const {
  const auto it = nodeByName_.find(name);
  return it == nodeByName_.end() ? -1 : it->second;
}

int Mesh::nodeIndex(const std::string& name) const {
  const int i = findNode(name);
  if (i < 0) throw Error("node '" + name + "' not found in the mesh");
  return i;
}

int Mesh::addCell(CellType type, const std::vector<int>& nodes, const std::string& name) {
  return addCell(type, nodes.data(), static_cast<int>(nodes.size()), name);
}

int Mesh::addCell(CellType type, const int* nodes, int count, const std::string& name) {
  if (count != mesh::nodeCount(type))
    throw Error("a " + cellTypeName(type) + " cell needs " + std::to_string(mesh::nodeCount(type)) +
                " nodes, got " + std::to_string(count) + (name.empty() ? "" : " (cell '" + name + "')"));
  for (int k = 0; k < count; ++k)
    if (nodes[k] < 0 || nodes[k] >= nodeCount())
      throw Error("cell " + name + " refers to node index " + std::to_string(nodes[k]) +
                  " out of range (the mesh has " + std::to_string(nodeCount()) + " nodes)");
  const std::string n = name.empty() ? freshCellName() : name;
  const int index = cellCount();
  if (!cellByName_.emplace(n, index).second) throw Error("duplicate cell name '" + n + "'");
  cellNames_.push_back(n);
  types_.push_back(type);
  conn_.insert(conn_.end(), nodes, nodes + count);
  offsets_.push_back(static_cast<int>(conn_.size()));
  return index;
}

void Mesh::setCellNodes(int c, const std::vector<int>& nodes) {
  if (static_cast<int>(nodes.size()) != offsets_[c + 1] - offsets_[c])
    throw Error("setCellNodes: cell '" + cellNames_[c] + "' has " +
                std::to_string(offsets_[c + 1] - offsets_[c]) + " nodes, got " +
                std::to_string(nodes.size()));
  std::copy(nodes.begin(), nodes.end(), conn_.begin() + offsets_[c]);
}

int Mesh::findCell(const std::string& name) const {
  const auto it = cellByName_.find(name);
  return it == cellByName_.end() ? -1 : it->second;
}

int Mesh::cellIndex(const std::string& name) const {
  const int i = findCell(name);
  if (i < 0) throw Error("cell '" + name + "' not found in the mesh");
  return i;
}

int Mesh::meshDimension() const {
  int d = -1;
  for (auto t : types_) d = std::max(d, topologicalDimension(t));
  return d;
}

int Mesh::countCells(CellType t) const {
  return static_cast<int>(std::count(types_.begin(), types_.end(), t));
}

const std::vector<int>& Mesh::findGroup(const Groups& groups, const std::string& kind,
                                        const std::string& name) {
  for (const auto& g : groups)
    if (g.first == name) return g.second;
  std::vector<std::string> names;
  for (const auto& g : groups) names.push_back(g.first);
  std::string hint;
  const auto close = closestNames(name, names, 3);
  for (std::size_t i = 0; i < close.size(); ++i)
    hint += (i == 0 ? "; did you mean '" : (i + 1 == close.size() ? " or '" : ", '")) + close[i] + "'";
  if (!hint.empty()) hint += "?";
  throw Error(kind + " '" + name + "' not found in the mesh" + hint +
              " (groups: " + (names.empty() ? std::string("none") : joinNames(names)) + ")");
}

void Mesh::checkCells(const std::vector<int>& cells, const std::string& group) const {
  for (int c : cells)
    if (c < 0 || c >= cellCount())
      throw Error("group '" + group + "': cell index " + std::to_string(c) + " out of range");
}

void Mesh::checkNodes(const std::vector<int>& nodes, const std::string& group) const {
  for (int n : nodes)
    if (n < 0 || n >= nodeCount())
      throw Error("group '" + group + "': node index " + std::to_string(n) + " out of range");
}

void Mesh::addCellGroup(const std::string& name, std::vector<int> cells) {
  if (hasCellGroup(name)) throw Error("group of cells '" + name + "' already exists in the mesh");
  setCellGroup(name, std::move(cells));
}

void Mesh::setCellGroup(const std::string& name, std::vector<int> cells) {
  if (name.empty()) throw Error("a group of cells needs a name");
  checkCells(cells, name);
  for (auto& g : cellGroups_)
    if (g.first == name) {
      g.second = std::move(cells);
      return;
    }
  cellGroups_.emplace_back(name, std::move(cells));
}

bool Mesh::hasCellGroup(const std::string& name) const {
  for (const auto& g : cellGroups_)
    if (g.first == name) return true;
  return false;
}

const std::vector<int>& Mesh::cellGroup(const std::string& name) const {
  return findGroup(cellGroups_, "group", name);
}

std::vector<std::string> Mesh::cellGroupNames() const {
  std::vector<std::string> names;
  for (const auto& g : cellGroups_) names.push_back(g.first);
  return names;
}

void Mesh::removeCellGroup(const std::string& name) {
  cellGroup(name);  // throws when absent
  cellGroups_.erase(std::remove_if(cellGroups_.begin(), cellGroups_.end(),
                                   [&](const auto& g) { return g.first == name; }),
                    cellGroups_.end());
}

void Mesh::addNodeGroup(const std::string& name, std::vector<int> nodes) {
  if (hasNodeGroup(name)) throw Error("group of nodes '" + name + "' already exists in the mesh");
  setNodeGroup(name, std::move(nodes));
}

void Mesh::setNodeGroup(const std::string& name, std::vector<int> nodes) {
  if (name.empty()) throw Error("a group of nodes needs a name");
  checkNodes(nodes, name);
  for (auto& g : nodeGroups_)
    if (g.first == name) {
      g.second = std::move(nodes);
      return;
    }
  nodeGroups_.emplace_back(name, std::move(nodes));
}

bool Mesh::hasNodeGroup(const std::string& name) const {
  for (const auto& g : nodeGroups_)
    if (g.first == name) return true;
  return false;
}

const std::vector<int>& Mesh::nodeGroup(const std::string& name) const {
  return findGroup(nodeGroups_, "group", name);
}

std::vector<std::string> Mesh::nodeGroupNames() const {
  std::vector<std::string> names;
  for (const auto& g : nodeGroups_) names.push_back(g.first);
  return names;
}

void Mesh::removeNodeGroup(const std::string& name) {
  nodeGroup(name);
  nodeGroups_.erase(std::remove_if(nodeGroups_.begin(), nodeGroups_.end(),
                                   [&](const auto& g) { return g.first == name; }),
                    nodeGroups_.end());
}

std::vector<int> Mesh::nodesOfCells(const std::vector<int>& cells) const {
  std::vector<char> seen(nodeCount(), 0);
  std::vector<int> out;
  for (int c : cells) {
    if (c < 0 || c >= cellCount()) throw Error("cell index " + std::to_string(c) + " out of range");
    for (int n : cellNodes(c))
      if (!seen[n]) {
        seen[n] = 1;
        out.push_back(n);
      }
  }
  return out;
}

std::vector<int> Mesh::orphanNodes() const {
  std::vector<char> used(nodeCount(), 0);
  for (int n : conn_) used[n] = 1;
  std::vector<int> out;
  for (int i = 0; i < nodeCount(); ++i)
    if (!used[i]) out.push_back(i);
  return out;
}

std::string Mesh::summary() const {
  std::ostringstream s;
  s << "------------ MESH " << (title.empty() ? "" : "'" + title + "' ") << "------------\n";
  s << "space dimension: " << spaceDim_ << "\n";
  s << "  number of nodes:  " << nodeCount() << "\n";
  s << "  number of cells:  " << cellCount() << "\n";
  for (int t = 0; t < kCellTypeCount; ++t) {
    const int n = countCells(static_cast<CellType>(t));
    if (n) s << "    " << cellTypeName(static_cast<CellType>(t)) << ": " << n << "\n";
  }
  s << "  number of groups of cells: " << cellGroups_.size() << "\n";
  for (const auto& g : cellGroups_) s << "    " << g.first << ": " << g.second.size() << "\n";
  s << "  number of groups of nodes: " << nodeGroups_.size() << "\n";
  for (const auto& g : nodeGroups_) s << "    " << g.first << ": " << g.second.size() << "\n";
  return s.str();
}

}  // namespace aster::mesh
