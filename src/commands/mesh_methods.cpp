// What a study may ask a mesh, with code_aster's own method names.
#include "commands/mesh_concept.hpp"
#include "core/error.hpp"
#include "lang/operators.hpp"

namespace aster::lang {
namespace {

const std::string& textArgument(const std::vector<Value>& args, const char* method) {
  if (args.size() != 1 || args[0].kind != Value::Kind::Text)
    throw Error(std::string(method) + " takes one group name");
  return args[0].text;
}

Datum names(const std::vector<std::string>& v) {
  std::vector<Datum> out;
  for (const auto& s : v) out.push_back(Datum::ofText(s));
  return Datum::ofList(out);
}

Datum oneBased(const std::vector<int>& v) {
  std::vector<Datum> out;
  for (int i : v) out.push_back(Datum::ofInteger(i + 1));
  return Datum::ofList(out);
}

Datum nodeCount(Concept& c, const std::vector<Value>&, Session&) {
  return Datum::ofInteger(static_cast<MeshConcept&>(c).mesh->nodeCount());
}
Datum cellCount(Concept& c, const std::vector<Value>&, Session&) {
  return Datum::ofInteger(static_cast<MeshConcept&>(c).mesh->cellCount());
}
Datum cellGroups(Concept& c, const std::vector<Value>&, Session&) {
  return names(static_cast<MeshConcept&>(c).mesh->cellGroupNames());
}
Datum nodeGroups(Concept& c, const std::vector<Value>&, Session&) {
  return names(static_cast<MeshConcept&>(c).mesh->nodeGroupNames());
}
Datum cells(Concept& c, const std::vector<Value>& args, Session&) {
  const auto& m = *static_cast<MeshConcept&>(c).mesh;
  if (args.empty()) {
    std::vector<int> all(m.cellCount());
    for (int i = 0; i < m.cellCount(); ++i) all[i] = i;
    return oneBased(all);
  }
  return oneBased(m.cellGroup(textArgument(args, "getCells")));
}
Datum nodes(Concept& c, const std::vector<Value>& args, Session&) {
  const auto& m = *static_cast<MeshConcept&>(c).mesh;
  if (args.empty()) {
    std::vector<int> all(m.nodeCount());
    for (int i = 0; i < m.nodeCount(); ++i) all[i] = i;
    return oneBased(all);
  }
  const std::string& g = textArgument(args, "getNodes");
  // A GROUP_NO if there is one, else the nodes of the GROUP_MA of that name.
  if (m.hasNodeGroup(g)) return oneBased(m.nodeGroup(g));
  return oneBased(m.nodesOfCells(m.cellGroup(g)));
}
Datum coordinates(Concept& c, const std::vector<Value>&, Session&) {
  std::vector<Datum> out;
  for (double x : static_cast<MeshConcept&>(c).mesh->coordinates()) out.push_back(Datum::ofReal(x));
  return Datum::ofList(out);
}

RegisterMethod m1("maillage_sdaster", "getNumberOfNodes", nodeCount);
RegisterMethod m2("maillage_sdaster", "getNumberOfCells", cellCount);
RegisterMethod m3("maillage_sdaster", "getGroupsOfCells", cellGroups);
RegisterMethod m4("maillage_sdaster", "getGroupsOfNodes", nodeGroups);
RegisterMethod m5("maillage_sdaster", "getCells", cells);
RegisterMethod m6("maillage_sdaster", "getNodes", nodes);
RegisterMethod m7("maillage_sdaster", "getCoordinates", coordinates);

}  // namespace
}  // namespace aster::lang
