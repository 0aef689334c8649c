// LIRE_MAILLAGE's checks: coordinates that are not finite numbers, and
// VERI_MAIL's orphan nodes, cells with the same nodes, flattened cells and
// cells with a repeated node, each named in the message.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "core/error.hpp"
#include "mesh/mesh_check.hpp"

using namespace aster::mesh;

namespace {

// Two unit QUAD4 side by side (N1..N6), the right one in group RIGHT.
Mesh twoSquares() {
  Mesh m;
  for (auto p : {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(2, 0, 0),
                 Eigen::Vector3d(0, 1, 0), Eigen::Vector3d(1, 1, 0), Eigen::Vector3d(2, 1, 0)})
    m.addNode(p);
  m.addCell(CellType::QUAD4, {0, 1, 4, 3}, "LEFT_CELL");
  m.addCell(CellType::QUAD4, {1, 2, 5, 4}, "RIGHT_CELL");
  m.addCellGroup("RIGHT", {1});
  return m;
}

}  // namespace

TEST(MeshCheck, NonFiniteCoordinatesNameTheNode) {
  Mesh m = twoSquares();
  EXPECT_NO_THROW(checkFiniteCoordinates(m));
  m.setNode(4, Eigen::Vector3d(1, std::numeric_limits<double>::quiet_NaN(), 0));
  try {
    checkFiniteCoordinates(m);
    FAIL() << "a NaN coordinate was accepted";
  } catch (const aster::Error& e) {
    EXPECT_STREQ(e.what(), "node 'N5' has a coordinate that is not a finite number: (1, nan, 0)");
  }
  m.setNode(4, Eigen::Vector3d(1, 1, 0));
  m.setNode(2, Eigen::Vector3d(-INFINITY, 0, 0));
  EXPECT_THROW(checkFiniteCoordinates(m), aster::Error);
}

TEST(MeshCheck, ASoundMeshHasNoDefect) {
  const MeshDefects d = findDefects(twoSquares(), 1e-3);
  EXPECT_TRUE(d.alarms.empty());
  EXPECT_TRUE(d.fatal.empty());
}

TEST(MeshCheck, EveryDefectIsNamed) {
  Mesh m = twoSquares();
  m.addNode(Eigen::Vector3d(5, 5, 0), "LOST");
  m.addCell(CellType::QUAD4, {3, 0, 1, 4}, "COPY");  // LEFT_CELL's nodes, another order
  m.setNode(5, Eigen::Vector3d(2, 1e-4, 0));         // RIGHT_CELL: N3-N6 = 1e-4, N3-N5 = sqrt 2
  m.addCell(CellType::TRIA3, {0, 1, 1}, "TWICE");
  const MeshDefects d = findDefects(m, 1e-3);
  ASSERT_EQ(d.alarms.size(), 3u);
  EXPECT_EQ(d.alarms[0], "1 node belongs to no cell (orphan): LOST");
  EXPECT_EQ(d.alarms[1],
            "1 cell has the same nodes as another (elements on both would count that part twice): "
            "LEFT_CELL (QUAD4) and COPY (QUAD4)");
  EXPECT_EQ(d.alarms[2].rfind("1 cell is flattened or degenerate (smallest over largest distance between two of its "
                              "nodes below APLAT = 0.001): RIGHT_CELL (QUAD4 of RIGHT): ratio 7.07e-05",
                              0),
            0u)
      << d.alarms[2];
  EXPECT_EQ(d.fatal,
            "1 cell has a node repeated in its connectivity (topologically degenerate, no element can be built on "
            "it): TWICE (TRIA3): node N2 twice");
  // APLAT = 0: no cell is flattened unless all its nodes coincide.
  EXPECT_EQ(findDefects(m, 0.0).alarms.size(), 2u);
}
