// The mesh model: nodes (3 coordinates each), cells of code_aster types with
// code_aster node ordering, names, and named groups of cells (GROUP_MA) and of
// nodes (GROUP_NO) kept in definition order. Indices are 0-based; the
// connectivity is compact (CSR-like: offsets + one node array).
#pragma once
#include <Eigen/Core>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "mesh/cell_type.hpp"

namespace aster::mesh {

// A read-only view on the nodes of one cell.
struct CellNodes {
  const int* first = nullptr;
  int count = 0;
  const int* begin() const { return first; }
  const int* end() const { return first + count; }
  int size() const { return count; }
  int operator[](int i) const { return first[i]; }
};

class Mesh {
 public:
  // Space dimension as read (2 for COOR_2D, 3 for COOR_3D...); coordinates are always 3.
  int spaceDimension() const { return spaceDim_; }
  void setSpaceDimension(int dim);
  std::string title;
  // Room for that many nodes and cells in all (cellNodes: their nodes in all),
  // so that a reader does not grow the tables by steps.
  void reserve(int nodes, int cells, int cellNodes);

  // --- nodes
  // An empty name gets an automatic unique one ("N<number>"); a duplicate name throws.
  int addNode(const Eigen::Vector3d& x, const std::string& name = "");
  int nodeCount() const { return static_cast<int>(nodeNames_.size()); }
  Eigen::Vector3d node(int i) const { return {xyz_[3 * i], xyz_[3 * i + 1], xyz_[3 * i + 2]}; }
  void setNode(int i, const Eigen::Vector3d& x);
  const std::vector<double>& coordinates() const { return xyz_; }  // x0 y0 z0 x1 ...
  const std::string& nodeName(int i) const { return nodeNames_[i]; }
  int findNode(const std::string& name) const;  // -1 when absent
  int nodeIndex(const std::string& name) const;  // throws when absent

  // --- cells
  int addCell(CellType type, const std::vector<int>& nodes, const std::string& name = "");
  int addCell(CellType type, const int* nodes, int count, const std::string& name = "");
  int cellCount() const { return static_cast<int>(types_.size()); }
  CellType cellType(int c) const { return types_[c]; }
  CellNodes cellNodes(int c) const {
    return {conn_.data() + offsets_[c], offsets_[c + 1] - offsets_[c]};
  }
  // Replaces the nodes of a cell by as many others (used to reorient cells).
  void setCellNodes(int c, const std::vector<int>& nodes);
  const std::string& cellName(int c) const { return cellNames_[c]; }
  int findCell(const std::string& name) const;  // -1 when absent
  int cellIndex(const std::string& name) const;  // throws when absent
  // Highest topological dimension among the cells (-1 for no cell).
  int meshDimension() const;
  int countCells(CellType t) const;

  // --- groups (definition order kept)
  // Adding a group that exists already throws; replace it with setCellGroup.
  void addCellGroup(const std::string& name, std::vector<int> cells);
  void setCellGroup(const std::string& name, std::vector<int> cells);
  bool hasCellGroup(const std::string& name) const;
  const std::vector<int>& cellGroup(const std::string& name) const;  // throws with suggestions
  std::vector<std::string> cellGroupNames() const;
  void removeCellGroup(const std::string& name);

  void addNodeGroup(const std::string& name, std::vector<int> nodes);
  void setNodeGroup(const std::string& name, std::vector<int> nodes);
  bool hasNodeGroup(const std::string& name) const;
  const std::vector<int>& nodeGroup(const std::string& name) const;
  std::vector<std::string> nodeGroupNames() const;
  void removeNodeGroup(const std::string& name);

  // Nodes of the given cells, each once, in order of first appearance.
  std::vector<int> nodesOfCells(const std::vector<int>& cells) const;
  // Nodes used by no cell.
  std::vector<int> orphanNodes() const;

  // code_aster-like description: counts per cell type, groups with their sizes.
  std::string summary() const;

  // A fresh name "<prefix><k>" not used yet by a node (resp. cell).
  std::string freshNodeName(const std::string& prefix = "N");
  std::string freshCellName(const std::string& prefix = "M");

 private:
  using Groups = std::vector<std::pair<std::string, std::vector<int>>>;
  static const std::vector<int>& findGroup(const Groups& groups, const std::string& kind,
                                           const std::string& name);
  void checkCells(const std::vector<int>& cells, const std::string& group) const;
  void checkNodes(const std::vector<int>& nodes, const std::string& group) const;

  int spaceDim_ = 3;
  std::vector<double> xyz_;
  std::vector<std::string> nodeNames_;
  std::unordered_map<std::string, int> nodeByName_;
  std::vector<CellType> types_;
  std::vector<int> offsets_{0};
  std::vector<int> conn_;
  std::vector<std::string> cellNames_;
  std::unordered_map<std::string, int> cellByName_;
  Groups cellGroups_;
  Groups nodeGroups_;
  int nextNodeNumber_ = 1;
  int nextCellNumber_ = 1;
};

}  // namespace aster::mesh
