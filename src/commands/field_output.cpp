#include "commands/field_output.hpp"

#include "core/error.hpp"
#include "fem/mesh_cell_type.hpp"
#include "fem/quadrature.hpp"
#include "fem/shape_functions.hpp"

namespace aster::lang {
namespace {

template <class Rule>
void addPoints(const Rule& rule, mesh::GaussLocalization& l) {
  for (int q = 0; q < rule.size(); ++q) {
    for (int d = 0; d < rule.points[q].size(); ++d) l.points.push_back(rule.points[q](d));
    l.weights.push_back(rule.weights[q]);
  }
}

// `points`: the field's number of points on a cell of this type, which tells the
// rule of an AXIS model from a plane one's (they differ on TRIA6 only).
mesh::GaussLocalization localizationOf(mesh::CellType type, int points) {
  const fem::CellType t = fem::referenceCell(type, "fields at Gauss points");
  mesh::GaussLocalization l;
  l.type = type;
  l.dimension = fem::cellDimension(t);
  auto nodes = [&](auto tag) {
    const auto ref = fem::Cell<decltype(tag)::value>::referenceNodes();
    for (int a = 0; a < ref.rows(); ++a)
      for (int d = 0; d < ref.cols(); ++d) l.nodes.push_back(ref(a, d));
  };
  if (l.dimension == 2) {
    fem::dispatchSurface(t, nodes);
    const auto& plane = fem::fullSurfaceRule(t, false);
    addPoints(points == plane.size() ? plane : fem::fullSurfaceRule(t, true), l);
  } else {
    fem::dispatchEdge(t, nodes);
    addPoints(fem::fullEdgeRule(t), l);
  }
  return l;
}

}  // namespace

mesh::CellValues cellValuesOf(const mesh::Mesh& mesh, const CellField& f) {
  mesh::CellValues v;
  v.name = f.name;
  v.components = f.components;
  v.cells = f.cells;
  v.offsets = f.offsets;
  v.values = f.values;
  v.atNodes = f.location == CellLocation::Nodes;
  if (!v.atNodes)
    for (std::size_t k = 0; k < f.cells.size(); ++k) {
      const mesh::CellType type = mesh.cellType(f.cells[k]);
      const mesh::GaussLocalization* l = nullptr;
      for (const auto& x : v.localizations)
        if (x.type == type) l = &x;
      if (!l) {
        v.localizations.push_back(localizationOf(type, pointsOf(f, k)));
        l = &v.localizations.back();
      }
      if (static_cast<std::size_t>(pointsOf(f, k)) != l->weights.size())
        throw Error("the field " + f.name + " has " + std::to_string(pointsOf(f, k)) + " points on cell " +
                    mesh.cellName(f.cells[k]) + ", the model's rule on a " + mesh::cellTypeName(type) + " has " +
                    std::to_string(l->weights.size()));
    }
  return v;
}

mesh::FieldInstant fieldInstantOf(const mesh::Mesh& mesh, const ResultInstant& instant) {
  mesh::FieldInstant fi;
  fi.index = instant.index;
  fi.time = instant.time;
  fi.fields = instant.nodal;
  for (const auto& c : instant.cells) fi.cellFields.push_back(cellValuesOf(mesh, c));
  return fi;
}

void nameInternalVariables(const std::string& field, std::vector<std::string>& components,
                           const std::vector<std::string>& names) {
  if (names.empty() || field.rfind("VARI_", 0) != 0) return;
  for (auto& c : components) {
    if (c.size() < 2 || c[0] != 'V' || c.find_first_not_of("0123456789", 1) != std::string::npos) continue;
    const std::size_t k = std::stoul(c.substr(1));
    if (k >= 1 && k <= names.size()) c = names[k - 1];
  }
}

}  // namespace aster::lang
