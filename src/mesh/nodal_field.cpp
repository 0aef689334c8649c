#include "mesh/nodal_field.hpp"

#include "core/error.hpp"
#include "mesh/mesh.hpp"

namespace aster::mesh {

void checkCellValues(const Mesh& mesh, const CellValues& f, const std::string& writer) {
  const std::size_t nc = f.components.size();
  const auto bad = [&](const std::string& what) { return Error(writer + ": cell field '" + f.name + "' " + what); };
  if (nc == 0) throw bad("has no component");
  if (f.offsets.size() != f.cells.size() + 1 || f.offsets.front() != 0 ||
      static_cast<std::size_t>(f.offsets.back()) != f.values.size())
    throw bad("has offsets that do not match its " + std::to_string(f.values.size()) + " values");
  for (std::size_t k = 0; k < f.cells.size(); ++k) {
    const int c = f.cells[k];
    if (c < 0 || c >= mesh.cellCount()) throw bad("names cell " + std::to_string(c) + ", not in the mesh");
    const int count = f.offsets[k + 1] - f.offsets[k];
    if (count < 0 || count % static_cast<int>(nc) != 0) throw bad("has a partial point on cell " + mesh.cellName(c));
    const int points = count / static_cast<int>(nc);
    if (f.atNodes && points != nodeCount(mesh.cellType(c)))
      throw bad("has " + std::to_string(points) + " points on cell " + mesh.cellName(c) + ", expected its " +
                std::to_string(nodeCount(mesh.cellType(c))) + " nodes");
    if (!f.atNodes) {
      const GaussLocalization* l = nullptr;
      for (const auto& x : f.localizations)
        if (x.type == mesh.cellType(c)) l = &x;
      if (!l) throw bad("has no Gauss point localization for the " + cellTypeName(mesh.cellType(c)) + " cells");
      if (static_cast<std::size_t>(points) != l->weights.size())
        throw bad("has " + std::to_string(points) + " points on cell " + mesh.cellName(c) + ", its localization " +
                  std::to_string(l->weights.size()));
    }
  }
}

}  // namespace aster::mesh
