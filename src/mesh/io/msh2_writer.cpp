#include "mesh/io/msh2_writer.hpp"

#include <algorithm>
#include <map>
#include <tuple>

#include "core/atomic_write.hpp"
#include "core/error.hpp"
#include "mesh/io/gmsh_format.hpp"
#include "mesh/group_ops.hpp"
#include "mesh/io/msh_check.hpp"
#include "mesh/node_ordering.hpp"

namespace aster::mesh {
namespace {

// One $NodeData view: a name, its width (1, 3 or 9) and a value per (node, component).
struct View {
  std::string name;
  int width;
  const NodalField* field;
  int component;  // the one component of a split field, -1 when the view holds the field
  double value(int node, int k) const {
    const std::size_t nc = field->components.size();
    if (component >= 0) return field->values[node * nc + component];
    return k < static_cast<int>(nc) ? field->values[node * nc + k] : 0.0;
  }
};

std::vector<View> viewsOf(const NodalField& f) {
  const int nc = static_cast<int>(f.components.size());
  if (nc == 1 || nc == 3 || nc == 9) return {{f.name, nc, &f, -1}};
  if (nc == 2) return {{f.name, 3, &f, -1}};
  std::vector<View> views;
  for (int c = 0; c < nc; ++c) views.push_back({f.name + "_" + f.components[c], 1, &f, c});
  return views;
}

// One $ElementData (Gauss point field: the mean per cell) or $ElementNodeData
// (field at cell nodes) view: widths as nodal views.
struct CellView {
  std::string name;
  int width;
  const CellValues* field;
  int component;  // as View::component
  double value(std::size_t k, int point, int c) const {
    const std::size_t nc = field->components.size();
    const std::size_t at = static_cast<std::size_t>(field->offsets[k]) + static_cast<std::size_t>(point) * nc;
    if (component >= 0) return field->values[at + component];
    return c < static_cast<int>(nc) ? field->values[at + c] : 0.0;
  }
  double mean(std::size_t k, int c) const {
    if (component >= 0) return pointMean(*field, k, component);
    return c < static_cast<int>(field->components.size()) ? pointMean(*field, k, c) : 0.0;
  }
};

std::vector<CellView> viewsOf(const CellValues& f) {
  const std::string name = f.atNodes ? f.name : f.name + "_MEAN";
  const int nc = static_cast<int>(f.components.size());
  if (nc == 1 || nc == 3 || nc == 9) return {{name, nc, &f, -1}};
  if (nc == 2) return {{name, 3, &f, -1}};
  std::vector<CellView> views;
  for (int c = 0; c < nc; ++c) views.push_back({name + "_" + f.components[c], 1, &f, c});
  return views;
}

}  // namespace

void writeMsh2(const Mesh& mesh, const std::string& path, const std::vector<FieldInstant>& instants) {
  OutputFile out(path);

  // Entities: one per (dimension, groups of the cell), in the order of the cells.
  const auto groupNames = mesh.cellGroupNames();
  const std::vector<std::vector<int>> groupsOfCell = groupsOfEachCell(mesh);
  std::map<std::pair<int, std::vector<int>>, int> entityOf;
  std::vector<int> entityOfCell(mesh.cellCount());
  for (int c = 0; c < mesh.cellCount(); ++c) {
    const int dim = topologicalDimension(mesh.cellType(c));
    const int next = static_cast<int>(entityOf.size()) + 1;
    entityOfCell[c] = entityOf.emplace(std::make_pair(dim, groupsOfCell[c]), next).first->second;
  }
  // Physical groups: per group and dimension, then the reserved one per dimension.
  std::map<std::pair<int, int>, int> physicalOf;  // (dimension, group or -1) -> tag
  std::vector<std::tuple<int, int, std::string>> names;
  auto addPhysical = [&](int dim, int group, const std::string& name) {
    if (physicalOf.count({dim, group})) return;
    const int tag = static_cast<int>(names.size()) + 1;
    physicalOf[{dim, group}] = tag;
    names.emplace_back(dim, tag, name);
  };
  for (std::size_t g = 0; g < groupNames.size(); ++g)
    for (int dim = 0; dim <= 3; ++dim)
      for (int c : mesh.cellGroup(groupNames[g]))
        if (topologicalDimension(mesh.cellType(c)) == dim) {
          addPhysical(dim, static_cast<int>(g), groupNames[g]);
          break;
        }
  for (int c = 0; c < mesh.cellCount(); ++c)
    if (groupsOfCell[c].empty()) addPhysical(topologicalDimension(mesh.cellType(c)), -1, kGmshUngroupedName);

  out.printf("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$PhysicalNames\n%zu\n", names.size());
  for (const auto& [dim, tag, name] : names) out.printf("%d %d \"%s\"\n", dim, tag, name.c_str());
  out.printf("$EndPhysicalNames\n$Nodes\n%d\n", mesh.nodeCount());
  for (int i = 0; i < mesh.nodeCount(); ++i) {
    const auto x = mesh.node(i);
    out.printf("%d %.17g %.17g %.17g\n", i + 1, x[0], x[1], x[2]);
  }
  std::size_t lines = 0;
  for (const auto& groups : groupsOfCell) lines += std::max<std::size_t>(groups.size(), 1);
  out.printf("$EndNodes\n$Elements\n%zu\n", lines);
  auto writeElement = [&](int tag, int c, int physical) {
    const CellType t = mesh.cellType(c);
    out.printf("%d %d 2 %d %d", tag, gmshElementType(t), physical, entityOfCell[c]);
    const auto n = mesh.cellNodes(c);
    for (int k : fromAsterOrder(NodeConvention::Gmsh, t, std::vector<int>(n.begin(), n.end())))
      out.printf(" %d", k + 1);
    out.put('\n');
  };
  for (int c = 0; c < mesh.cellCount(); ++c) {
    const int dim = topologicalDimension(mesh.cellType(c));
    const int group = groupsOfCell[c].empty() ? -1 : groupsOfCell[c].front();
    writeElement(c + 1, c, physicalOf.at({dim, group}));
  }
  int copy = mesh.cellCount();
  for (int c = 0; c < mesh.cellCount(); ++c) {
    const int dim = topologicalDimension(mesh.cellType(c));
    for (std::size_t k = 1; k < groupsOfCell[c].size(); ++k)
      writeElement(++copy, c, physicalOf.at({dim, groupsOfCell[c][k]}));
  }
  out.printf("$EndElements\n");

  // Views by name (gmsh's order), each with one block per instant.
  std::map<std::string, std::vector<std::pair<int, View>>> steps;
  for (std::size_t s = 0; s < instants.size(); ++s)
    for (const auto& f : instants[s].fields)
      for (const View& v : viewsOf(f)) steps[v.name].emplace_back(static_cast<int>(s), v);
  for (const auto& [name, blocks] : steps)
    for (const auto& [step, view] : blocks) {
      out.printf("$NodeData\n1\n\"%s\"\n1\n%.17g\n3\n%d\n%d\n%d\n", name.c_str(), instants[step].time, step,
                   view.width, mesh.nodeCount());
      for (int i = 0; i < mesh.nodeCount(); ++i) {
        out.printf("%d", i + 1);
        for (int k = 0; k < view.width; ++k) out.printf(" %.17g", view.value(i, k));
        out.put('\n');
      }
      out.printf("$EndNodeData\n");
    }

  // Cell fields: at Gauss points the mean per cell ($ElementData), at cell nodes
  // the values at each node in gmsh's node order ($ElementNodeData). A cell is
  // element c + 1, its first copy.
  std::map<std::string, std::vector<std::pair<int, CellView>>> cellSteps;
  for (std::size_t s = 0; s < instants.size(); ++s)
    for (const auto& f : instants[s].cellFields)
      for (const CellView& v : viewsOf(f)) cellSteps[v.name].emplace_back(static_cast<int>(s), v);
  for (const auto& [name, blocks] : cellSteps)
    for (const auto& [step, view] : blocks) {
      const CellValues& f = *view.field;
      const char* section = f.atNodes ? "ElementNodeData" : "ElementData";
      out.printf("$%s\n1\n\"%s\"\n1\n%.17g\n3\n%d\n%d\n%zu\n", section, name.c_str(), instants[step].time, step,
                 view.width, f.cells.size());
      for (std::size_t k = 0; k < f.cells.size(); ++k) {
        const int c = f.cells[k];
        out.printf("%d", c + 1);
        if (f.atNodes) {
          const CellType t = mesh.cellType(c);
          std::vector<int> order(nodeCount(t));
          for (std::size_t j = 0; j < order.size(); ++j) order[j] = static_cast<int>(j);
          order = fromAsterOrder(NodeConvention::Gmsh, t, order);
          out.printf(" %zu", order.size());
          for (int p : order)
            for (int i = 0; i < view.width; ++i) out.printf(" %.17g", view.value(k, p, i));
        } else {
          for (int i = 0; i < view.width; ++i) out.printf(" %.17g", view.mean(k, i));
        }
        out.put('\n');
      }
      out.printf("$End%s\n", section);
    }
  out.close();
}

}  // namespace aster::mesh
