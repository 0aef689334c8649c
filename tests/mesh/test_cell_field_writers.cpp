// Cell fields in the MED, gmsh (MSH 2.2) and VTK writers, read back: MED with
// the MED library's own dump tool (mdump), gmsh and VTK from the text.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>

#include "mesh/io/gmsh_format.hpp"
#include "mesh/io/med_format.hpp"
#include "mesh/io/vtk_format.hpp"
#include "mesh/mesh.hpp"

using namespace aster::mesh;

namespace {
const std::string kOut = std::string(ASTER_BINARY_DIR) + "/";

// Two QUAD4 (M1, M2), a TRIA3 (M3) and an edge SEG2 (M4).
Mesh smallMesh() {
  Mesh m;
  m.setSpaceDimension(2);
  const double xy[7][2] = {{0, 0}, {1, 0}, {2, 0}, {0, 1}, {1, 1}, {2, 1}, {3, 0.5}};
  for (int i = 0; i < 7; ++i) m.addNode({xy[i][0], xy[i][1], 0}, "N" + std::to_string(i + 1));
  m.addCell(CellType::QUAD4, {0, 1, 4, 3}, "M1");
  m.addCell(CellType::QUAD4, {1, 2, 5, 4}, "M2");
  m.addCell(CellType::TRIA3, {2, 6, 5}, "M3");
  m.addCell(CellType::SEG2, {3, 4}, "M4");
  return m;
}

// Values chosen exact in mdump's 6 decimals: 10 * (cell + 1) + point + component / 4.
double value(int cell, int point, int component) { return 10.0 * (cell + 1) + point + 0.25 * component; }

CellValues field(const std::string& name, const std::vector<std::string>& cmps, const std::vector<int>& cells,
                 const std::vector<int>& points, bool atNodes) {
  CellValues f;
  f.name = name;
  f.components = cmps;
  f.cells = cells;
  f.atNodes = atNodes;
  f.offsets.push_back(0);
  for (std::size_t k = 0; k < cells.size(); ++k) {
    for (int p = 0; p < points[k]; ++p)
      for (std::size_t c = 0; c < cmps.size(); ++c) f.values.push_back(value(cells[k], p, static_cast<int>(c)));
    f.offsets.push_back(static_cast<int>(f.values.size()));
  }
  return f;
}

// SIEF_ELGA on M2 (2x2 points) and M3 (1 point): a profile for the QUAD4 (M1 is
// not in it); SIGM_ELNO on the three surface cells; DEPL at the nodes.
FieldInstant instant() {
  const double a = 1 / std::sqrt(3.0);
  CellValues elga = field("SIEF_ELGA", {"SIXX", "SIYY", "SIZZ", "SIXY"}, {1, 2}, {4, 1}, false);
  elga.localizations.push_back({CellType::QUAD4, 2, {-1, -1, 1, -1, 1, 1, -1, 1},
                                {-a, -a, a, -a, -a, a, a, a}, {1, 1, 1, 1}});
  elga.localizations.push_back({CellType::TRIA3, 2, {0, 0, 1, 0, 0, 1}, {1 / 3.0, 1 / 3.0}, {0.5}});
  CellValues elno = field("SIGM_ELNO", {"SIXX"}, {0, 1, 2}, {4, 4, 3}, true);
  NodalField depl{"DEPL", {"DX", "DY"}, {}};
  for (int i = 0; i < 7; ++i) {
    depl.values.push_back(0.5 * i);
    depl.values.push_back(-0.25 * i);
  }
  FieldInstant fi;
  fi.index = 1;
  fi.time = 2.0;
  fi.fields = {depl};
  fi.cellFields = {elga, elno};
  return fi;
}

double mean(int cell, int points, int component) {
  double s = 0;
  for (int p = 0; p < points; ++p) s += value(cell, p, component);
  return s / points;
}

std::string readAll(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string run(const std::string& command) {
  std::string out;
  FILE* p = popen(command.c_str(), "r");
  if (!p) return out;
  char buffer[4096];
  for (std::size_t n; (n = fread(buffer, 1, sizeof buffer, p)) > 0;) out.append(buffer, n);
  pclose(p);
  return out;
}

// mdump's numbers between '|' on the line after "- Valeurs :".
std::vector<double> numbersOf(const std::string& line) {
  std::vector<double> v;
  std::string cleaned = line;
  for (char& c : cleaned)
    if (c == '|') c = ' ';
  std::istringstream in(cleaned);
  for (double x; in >> x;) v.push_back(x);
  return v;
}

// What mdump prints of one field: per (entity, geometric type) line, the profile and values.
struct DumpedPart {
  std::string entity, profile;
  std::vector<double> values;
};
std::vector<DumpedPart> dumpedField(const std::string& dump, const std::string& name) {
  std::vector<DumpedPart> parts;
  // mdump prints the field's header again before each geometric type.
  for (std::size_t at = dump.find("CHAMP |" + name + "|"); at != std::string::npos;
       at = dump.find("CHAMP |" + name + "|", at + 1)) {
    const std::size_t end = dump.find("(* CHAMP |", at + 1);
    std::istringstream in(dump.substr(at, end == std::string::npos ? std::string::npos : end - at));
    std::string line;
    while (std::getline(in, line)) {
      const auto entity = line.find("Chaque entite ");
      if (entity != std::string::npos) {
        DumpedPart p;
        p.entity = line.substr(entity + 14, line.find(" associes") - entity - 14);
        const auto pfl = line.find("au profil |");
        p.profile = line.substr(pfl + 11, line.find('|', pfl + 11) - pfl - 11);
        parts.push_back(p);
      }
      if (line.find("- Valeurs :") != std::string::npos && std::getline(in, line) && !parts.empty())
        parts.back().values = numbersOf(line);
    }
  }
  return parts;
}
}  // namespace

TEST(CellFieldWriters, MedHoldsGaussAndNodeFieldsAsCodeAster) {
  if (run("command -v mdump").empty()) GTEST_SKIP() << "mdump (libmed-tools) is not installed";
  const Mesh m = smallMesh();
  const std::string path = kOut + "cell_fields.med";
  writeMedResults(m, path, {instant()}, "MAIL");
  const std::string dump = run("printf '1\\n1\\n1\\n' | mdump " + path + " 2>&1");
  // Localizations named <elrefe>_____RIGI, with the rule's points.
  EXPECT_NE(dump.find("|QU4_____RIGI| de dimension 2 avec 4 pts de GAUSS"), std::string::npos) << dump;
  EXPECT_NE(dump.find("|TR3_____RIGI| de dimension 2 avec 1 pts de GAUSS"), std::string::npos) << dump;
  EXPECT_NE(dump.find("-0.577350  -0.577350"), std::string::npos);

  const auto elga = dumpedField(dump, "SIEF_ELGA");
  ASSERT_EQ(elga.size(), 2u) << dump;
  EXPECT_EQ(elga[0].entity, "MED_MAILLE de type geometrique MED_TRIA3");
  EXPECT_EQ(elga[0].profile, "");
  std::vector<double> expected;
  for (int c = 0; c < 4; ++c) expected.push_back(value(2, 0, c));
  EXPECT_EQ(elga[0].values, expected);
  // M2 alone of the QUAD4: a profile.
  EXPECT_EQ(elga[1].entity, "MED_MAILLE de type geometrique MED_QUAD4");
  EXPECT_EQ(elga[1].profile, "SIEF_ELGA_QUAD4");
  expected.clear();
  for (int p = 0; p < 4; ++p)
    for (int c = 0; c < 4; ++c) expected.push_back(value(1, p, c));
  EXPECT_EQ(elga[1].values, expected);
  EXPECT_NE(dump.find("Nom des composantes : |SIXX            SIYY            SIZZ            SIXY"),
            std::string::npos);

  const auto elno = dumpedField(dump, "SIGM_ELNO");
  ASSERT_EQ(elno.size(), 2u) << dump;
  EXPECT_EQ(elno[0].entity, "MED_NOEUD_MAILLE de type geometrique MED_TRIA3");
  EXPECT_EQ(elno[0].values, (std::vector<double>{value(2, 0, 0), value(2, 1, 0), value(2, 2, 0)}));
  EXPECT_EQ(elno[1].entity, "MED_NOEUD_MAILLE de type geometrique MED_QUAD4");
  EXPECT_EQ(elno[1].profile, "");
  expected.clear();
  for (int cell = 0; cell < 2; ++cell)
    for (int p = 0; p < 4; ++p) expected.push_back(value(cell, p, 0));
  EXPECT_EQ(elno[1].values, expected);
  // The nodal field as before.
  EXPECT_EQ(readMedNodalField(path, "DEPL", 1).values, instant().fields[0].values);
}

TEST(CellFieldWriters, GmshWritesElementDataAndElementNodeData) {
  const Mesh m = smallMesh();
  const std::string path = kOut + "cell_fields.msh";
  GmshWriteOptions options;
  options.version = 2.2;
  writeGmshResults(m, path, {instant()}, options);
  const std::string text = readAll(path);
  // Per view name: element tag -> numbers after it.
  std::map<std::string, std::map<int, std::vector<double>>> views;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    if (line != "$ElementData" && line != "$ElementNodeData") continue;
    const bool nodeData = line == "$ElementNodeData";
    std::string name;
    int ns, nr, ni, step, width, count;
    double time;
    in >> ns >> std::ws;
    std::getline(in, name);
    in >> nr >> time >> ni >> step >> width >> count;
    EXPECT_DOUBLE_EQ(time, 2.0);
    for (int e = 0; e < count; ++e) {
      int tag, nodes = 1;
      in >> tag;
      if (nodeData) in >> nodes;
      std::vector<double> v(static_cast<std::size_t>(nodes) * width);
      for (double& x : v) in >> x;
      views[(nodeData ? "N:" : "E:") + name][tag] = v;
    }
  }
  // SIEF_ELGA: 4 components, one scalar view each, the mean over the Gauss points.
  for (int c = 0; c < 4; ++c) {
    const std::string view = std::string("E:\"SIEF_ELGA_MEAN_") + (c == 0 ? "SIXX" : c == 1 ? "SIYY" : c == 2 ? "SIZZ" : "SIXY") + "\"";
    ASSERT_EQ(views[view].size(), 2u) << view << "\n" << text;
    EXPECT_DOUBLE_EQ(views[view][2].at(0), mean(1, 4, c));
    EXPECT_DOUBLE_EQ(views[view][3].at(0), value(2, 0, c));
  }
  const auto& elno = views["N:\"SIGM_ELNO\""];
  ASSERT_EQ(elno.size(), 3u) << text;
  EXPECT_EQ(elno.at(1), (std::vector<double>{value(0, 0, 0), value(0, 1, 0), value(0, 2, 0), value(0, 3, 0)}));
  EXPECT_EQ(elno.at(3), (std::vector<double>{value(2, 0, 0), value(2, 1, 0), value(2, 2, 0)}));
  EXPECT_NE(text.find("$NodeData\n1\n\"DEPL\""), std::string::npos);
}

namespace {
std::vector<double> decodeBase64Doubles(const std::string& text) {
  static const std::string digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string bytes;
  unsigned buffer = 0;
  int bits = 0;
  for (char ch : text) {
    const auto d = digits.find(ch);
    if (d == std::string::npos) continue;
    buffer = (buffer << 6) | static_cast<unsigned>(d);
    bits += 6;
    if (bits >= 8) {
      bits -= 8;
      bytes += static_cast<char>((buffer >> bits) & 0xff);
    }
  }
  std::uint32_t size = 0;
  std::memcpy(&size, bytes.data(), 4);
  std::vector<double> v(size / 8);
  std::memcpy(v.data(), bytes.data() + 4, size);
  return v;
}
}  // namespace

TEST(CellFieldWriters, VtkCellDataIsTheMeanPerCell) {
  const Mesh m = smallMesh();
  const std::string path = kOut + "cell_fields.vtu";
  const FieldInstant fi = instant();
  writeVtu(m, path, fi.fields, fi.cellFields);
  const std::string text = readAll(path);
  auto arrayOf = [&](const std::string& name, int components) {
    const std::string head = "<DataArray type=\"Float64\" Name=\"" + name + "\" NumberOfComponents=\"" +
                             std::to_string(components) + "\"";
    const auto at = text.find(head);
    EXPECT_NE(at, std::string::npos) << name << "\n" << text;
    const auto begin = text.find('>', at) + 1;
    return decodeBase64Doubles(text.substr(begin, text.find("</DataArray>", begin) - begin));
  };
  EXPECT_NE(text.find("Name=\"SIEF_ELGA_MEAN\" NumberOfComponents=\"4\" ComponentName0=\"SIXX\" ComponentName1=\"SIYY\" "
                      "ComponentName2=\"SIZZ\" ComponentName3=\"SIXY\" format=\"binary\""),
            std::string::npos);
  const auto elga = arrayOf("SIEF_ELGA_MEAN", 4);
  ASSERT_EQ(elga.size(), 16u);
  for (int c = 0; c < 4; ++c) {
    EXPECT_TRUE(std::isnan(elga[0 * 4 + c]));  // M1: not in the field
    EXPECT_DOUBLE_EQ(elga[1 * 4 + c], mean(1, 4, c));
    EXPECT_DOUBLE_EQ(elga[2 * 4 + c], value(2, 0, c));
    EXPECT_TRUE(std::isnan(elga[3 * 4 + c]));  // the edge cell
  }
  const auto elno = arrayOf("SIGM_ELNO_MEAN", 1);
  ASSERT_EQ(elno.size(), 4u);
  EXPECT_DOUBLE_EQ(elno[0], mean(0, 4, 0));
  EXPECT_DOUBLE_EQ(elno[2], mean(2, 3, 0));
  EXPECT_TRUE(std::isnan(elno[3]));
  // The cell data sits between the point data and the points.
  EXPECT_LT(text.find("</PointData>"), text.find("<CellData>"));
  EXPECT_LT(text.find("</CellData>"), text.find("<Points>"));
}
