// Fields at cell nodes (ELNO) in POST_RELEVE_T and RECU_FONCTION, built in C++
// (CALC_CHAMP makes them in studies) and handed to the operators directly.
// The rectangle_4x1 mesh: M1 = N1 N2 N7 N6, M2 = N2 N3 N8 N7 (QUAD4). The field
// SIGM_ELNO on M1 and M2: SIXX = 100 (k + 1) + a at the cell's a-th node (k = 0 for
// M1), discontinuous between cells; SIYY = the node's X, continuous.
#include <gtest/gtest.h>

#include <cmath>

#include "commands/function_concepts.hpp"
#include "commands/result_concepts.hpp"
#include "commands/table_concept.hpp"
#include "core/error.hpp"
#include "expr/function.hpp"
#include "lang/operators.hpp"
#include "lang/session.hpp"
#include "mesh/io/aster_format.hpp"

using namespace aster;
using namespace aster::lang;

namespace {

std::shared_ptr<mesh::Mesh> rectangle() {
  return std::make_shared<mesh::Mesh>(
      mesh::readAsterMesh(std::string(ASTER_SOURCE_DIR) + "/tests/program/rectangle_4x1.mail"));
}

CellField elno(const mesh::Mesh& m, double scale) {
  CellField f;
  f.name = "SIGM_ELNO";
  f.components = {"SIXX", "SIYY"};
  f.location = CellLocation::Nodes;
  f.offsets.push_back(0);
  for (int k = 0; k < 2; ++k) {
    const int c = m.cellIndex(k == 0 ? "M1" : "M2");
    f.cells.push_back(c);
    const auto nodes = m.cellNodes(c);
    for (int a = 0; a < 4; ++a) {
      f.values.push_back(scale * (100.0 * (k + 1) + a));
      f.values.push_back(scale * m.node(nodes[a])(0));
    }
    f.offsets.push_back(static_cast<int>(f.values.size()));
  }
  return f;
}

Value text(const std::string& s) { return Value::ofText(s); }

post::Table releve(const Keywords& action) {
  Keywords k;
  k.setFactor("ACTION", {action});
  k.setSimple("INFO", {Value::ofInteger(1)});
  Session session;
  auto t = (*Operators::instance().find("POST_RELEVE_T"))(k, session, nullptr);
  return std::static_pointer_cast<TableConcept>(t)->table;
}

Keywords action(ConceptPtr field, const std::string& nodes, const std::string& moyeNoeud) {
  Keywords a;
  a.setSimple("OPERATION", {text("EXTRACTION")});
  a.setSimple("INTITULE", {text("ELNO")});
  a.setSimple("CHAM_GD", {Value::ofConcept(std::move(field))});
  a.setSimple("NOEUD", {text(nodes)});
  a.setSimple("TOUT_CMP", {text("OUI")});
  a.setSimple("MOYE_NOEUD", {text(moyeNoeud)});
  return a;
}

}  // namespace

TEST(ElnoPost, ExtractionAveragesAtTheNodeByDefault) {
  const auto m = rectangle();
  const auto field = std::make_shared<CellFieldConcept>(m, elno(*m, 1.0));
  const post::Table t = releve(action(field, "N2", "OUI"));
  ASSERT_EQ(t.rowCount(), 1);
  // N2 is node 2 of M1 (101) and node 1 of M2 (200).
  EXPECT_DOUBLE_EQ(t.at("SIXX", 0).number(), (101.0 + 200.0) / 2);
  EXPECT_DOUBLE_EQ(t.at("SIYY", 0).number(), 1.0);
  EXPECT_EQ(t.at("NOEUD", 0).text, "N2");
  EXPECT_FALSE(t.hasColumn("MAILLE"));
}

TEST(ElnoPost, MoyeNoeudNonGivesOneRowPerCell) {
  const auto m = rectangle();
  const auto field = std::make_shared<CellFieldConcept>(m, elno(*m, 1.0));
  const post::Table t = releve(action(field, "N2", "NON"));
  ASSERT_EQ(t.rowCount(), 2);
  EXPECT_EQ(t.at("MAILLE", 0).text, "M1");
  EXPECT_DOUBLE_EQ(t.at("SIXX", 0).number(), 101.0);
  EXPECT_EQ(t.at("MAILLE", 1).text, "M2");
  EXPECT_DOUBLE_EQ(t.at("SIXX", 1).number(), 200.0);
  EXPECT_EQ(t.at("NOEUD", 1).text, "N2");
}

TEST(ElnoPost, GroupMaKeepsTheValuesOfItsCells) {
  const auto m = rectangle();
  m->addCellGroup("DEUX", {m->cellIndex("M2")});
  const auto field = std::make_shared<CellFieldConcept>(m, elno(*m, 1.0));
  Keywords a = action(field, "N2", "OUI");
  a.setSimple("GROUP_MA", {text("DEUX")});
  const post::Table t = releve(a);
  ASSERT_EQ(t.rowCount(), 1);
  EXPECT_DOUBLE_EQ(t.at("SIXX", 0).number(), 200.0);
  // N1 is on M1 only.
  Keywords b = action(field, "N1", "OUI");
  b.setSimple("GROUP_MA", {text("DEUX")});
  EXPECT_THROW(releve(b), Error);
}

TEST(ElnoPost, NodeOutsideTheFieldIsAnError) {
  const auto m = rectangle();
  const auto field = std::make_shared<CellFieldConcept>(m, elno(*m, 1.0));
  try {
    releve(action(field, "N4", "OUI"));
    FAIL() << "N4 is on no cell of the field";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("no value at node N4"), std::string::npos) << e.what();
  }
}

TEST(ElnoPost, RecuFonctionReadsTheValueOfTheNodeOfTheCell) {
  const auto m = rectangle();
  auto result = std::make_shared<ResultConcept>(std::make_shared<model::Model>(m), "evol_elas");
  for (int i = 1; i <= 3; ++i) {
    ResultInstant inst;
    inst.index = i;
    inst.time = 0.5 * i;
    inst.cells.push_back(elno(*m, inst.time));
    result->instants.push_back(inst);
  }
  Keywords k;
  k.setSimple("RESULTAT", {Value::ofConcept(result)});
  k.setSimple("NOM_CHAM", {text("SIGM_ELNO")});
  k.setSimple("NOM_CMP", {text("SIXX")});
  k.setSimple("MAILLE", {text("M2")});
  k.setSimple("NOEUD", {text("N2")});
  k.setSimple("INTERPOL", {text("LIN")});
  k.setSimple("PROL_GAUCHE", {text("EXCLU")});
  k.setSimple("PROL_DROITE", {text("EXCLU")});
  k.setSimple("INFO", {Value::ofInteger(1)});
  Session session;
  auto f = std::static_pointer_cast<FunctionConcept>((*Operators::instance().find("RECU_FONCTION"))(k, session, nullptr));
  // M2's first node is N2: 200 t.
  for (double t : {0.5, 0.75, 1.5}) EXPECT_NEAR(f->function->evaluate(&t), 200.0 * t, 1e-12) << t;
  EXPECT_EQ(f->function->parameters(), std::vector<std::string>{"INST"});
  // Without the node, or with a node of another cell: errors.
  k.erase("NOEUD");
  EXPECT_THROW((*Operators::instance().find("RECU_FONCTION"))(k, session, nullptr), Error);
  k.setSimple("NOEUD", {text("N1")});
  EXPECT_THROW((*Operators::instance().find("RECU_FONCTION"))(k, session, nullptr), Error);
}
