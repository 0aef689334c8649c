#include "mesh/io/med_format.hpp"

#include <med.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <map>
#include <set>

#include "core/error.hpp"
#include "mesh/io/med_library.hpp"
#include "mesh/node_ordering.hpp"

namespace aster::mesh {

namespace {

med_geometry_type medType(CellType t) {
  switch (t) {
    case CellType::POI1: return MED_POINT1;
    case CellType::SEG2: return MED_SEG2;
    case CellType::SEG3: return MED_SEG3;
    case CellType::SEG4: return MED_SEG4;
    case CellType::TRIA3: return MED_TRIA3;
    case CellType::TRIA6: return MED_TRIA6;
    case CellType::TRIA7: return MED_TRIA7;
    case CellType::QUAD4: return MED_QUAD4;
    case CellType::QUAD8: return MED_QUAD8;
    case CellType::QUAD9: return MED_QUAD9;
    case CellType::TETRA4: return MED_TETRA4;
    case CellType::TETRA10: return MED_TETRA10;
    case CellType::PENTA6: return MED_PENTA6;
    case CellType::PENTA15: return MED_PENTA15;
    case CellType::PENTA18: return MED_PENTA18;
    case CellType::PYRAM5: return MED_PYRA5;
    case CellType::PYRAM13: return MED_PYRA13;
    case CellType::HEXA8: return MED_HEXA8;
    case CellType::HEXA20: return MED_HEXA20;
    case CellType::HEXA27: return MED_HEXA27;
  }
  return MED_NONE;
}

const char* const kMedExpected = "expected a MED file written by Salome, code_aster or aster-lite";

// A MED file is an HDF5 file, whose 8-byte signature MED files have at offset 0.
// Checked before the MED library sees the file (it says only that it cannot open it).
void checkHdf5Signature(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error("cannot open the MED file '" + path + "'");
  static const char kSignature[8] = {'\x89', 'H', 'D', 'F', '\r', '\n', '\x1a', '\n'};
  char head[8] = {};
  in.read(head, sizeof head);
  if (in.gcount() != sizeof head || std::memcmp(head, kSignature, sizeof head) != 0)
    throw Error(path + ": not a MED file (no HDF5 signature): " + kMedExpected);
}

// RAII on a MED file handle.
class MedFile {
 public:
  MedFile(const std::string& path, med_access_mode mode) : path_(path) {
    if (mode == MED_ACC_RDONLY) checkHdf5Signature(path);
    fid_ = medLibrary().fileOpen(path.c_str(), mode);
    if (fid_ < 0 && mode == MED_ACC_RDONLY)
      throw Error(path + ": an HDF5 file that the MED library cannot open (not a MED file, or a MED version newer "
                  "than 4.1): " + kMedExpected);
    if (fid_ < 0) throw Error("cannot open the MED file '" + path + "'");
  }
  ~MedFile() {
    if (fid_ >= 0) medLibrary().fileClose(fid_);
  }
  MedFile(const MedFile&) = delete;
  MedFile& operator=(const MedFile&) = delete;
  med_idt id() const { return fid_; }
  void check(med_err status, const std::string& what) const {
    if (status < 0) throw Error(path_ + ": MED error while " + what);
  }
  // Closes now, checked: the MED library (HDF5) writes much of a file when it closes it.
  void close() {
    const med_err status = medLibrary().fileClose(fid_);
    fid_ = -1;
    check(status, "closing the file");
  }

 private:
  std::string path_;
  med_idt fid_ = -1;
};

std::string fixed(const char* s, std::size_t size) {
  std::string out(s, strnlen(s, size));
  while (!out.empty() && out.back() == ' ') out.pop_back();
  return out;
}

std::string padded(const std::vector<std::string>& names, std::size_t width) {
  std::string out;
  for (const auto& n : names) {
    std::string p = n.substr(0, width);
    p.resize(width, ' ');
    out += p;
  }
  return out;
}

// Families: one per distinct set of groups; positive numbers for nodes, negative for cells.
struct Families {
  std::vector<med_int> numberOf;                    // per entity
  std::vector<std::pair<med_int, std::vector<std::string>>> groupsOf;  // family -> groups
};

Families buildFamilies(int count, const std::vector<std::string>& names,
                       const std::vector<const std::vector<int>*>& members, int sign) {
  Families f;
  f.numberOf.assign(count, 0);
  std::vector<std::vector<int>> groupsOfEntity(count);
  for (std::size_t g = 0; g < names.size(); ++g)
    for (int e : *members[g]) {
      auto& l = groupsOfEntity[e];
      if (std::find(l.begin(), l.end(), static_cast<int>(g)) == l.end()) l.push_back(static_cast<int>(g));
    }
  std::map<std::vector<int>, med_int> family;
  for (int e = 0; e < count; ++e) {
    auto key = groupsOfEntity[e];
    if (key.empty()) continue;
    std::sort(key.begin(), key.end());
    auto it = family.find(key);
    if (it == family.end()) {
      const med_int number = sign * static_cast<med_int>(family.size() + 1);
      it = family.emplace(key, number).first;
      std::vector<std::string> groups;
      for (int g : key) groups.push_back(names[g]);
      f.groupsOf.emplace_back(number, groups);
    }
    f.numberOf[e] = it->second;
  }
  return f;
}

void writeMesh(const MedFile& file, const Mesh& mesh, const std::string& meshName) {
  const med_idt fid = file.id();
  const int sdim = mesh.spaceDimension();
  const int mdim = std::max(0, mesh.meshDimension());
  for (const auto& n : mesh.cellGroupNames())
    if (n.size() > MED_LNAME_SIZE) throw Error("MED writer: group name '" + n + "' is longer than 80 characters");
  std::string axisNames = padded({"X", "Y", "Z"}, MED_SNAME_SIZE).substr(0, sdim * MED_SNAME_SIZE);
  std::string axisUnits(sdim * MED_SNAME_SIZE, ' ');
  file.check(medLibrary().meshCr(fid, meshName.c_str(), sdim, mdim, MED_UNSTRUCTURED_MESH, mesh.title.substr(0, MED_COMMENT_SIZE).c_str(), "",
                       MED_SORT_DTIT, MED_CARTESIAN, axisNames.c_str(), axisUnits.c_str()),
             "creating mesh " + meshName);
  std::vector<med_float> xyz;
  for (int i = 0; i < mesh.nodeCount(); ++i)
    for (int d = 0; d < sdim; ++d) xyz.push_back(mesh.node(i)[d]);
  file.check(medLibrary().meshNodeCoordinateWr(fid, meshName.c_str(), MED_NO_DT, MED_NO_IT, 0.0, MED_FULL_INTERLACE,
                                     mesh.nodeCount(), xyz.data()),
             "writing coordinates");
  bool shortNames = true;
  for (int i = 0; i < mesh.nodeCount(); ++i) shortNames = shortNames && mesh.nodeName(i).size() <= MED_SNAME_SIZE;
  for (int c = 0; c < mesh.cellCount(); ++c) shortNames = shortNames && mesh.cellName(c).size() <= MED_SNAME_SIZE;
  if (shortNames && mesh.nodeCount() > 0) {
    std::vector<std::string> names;
    for (int i = 0; i < mesh.nodeCount(); ++i) names.push_back(mesh.nodeName(i));
    file.check(medLibrary().meshEntityNameWr(fid, meshName.c_str(), MED_NO_DT, MED_NO_IT, MED_NODE, MED_NONE, mesh.nodeCount(),
                                   padded(names, MED_SNAME_SIZE).c_str()),
               "writing node names");
  }
  // Families.
  std::vector<const std::vector<int>*> nodeMembers, cellMembers;
  const auto nodeGroups = mesh.nodeGroupNames(), cellGroups = mesh.cellGroupNames();
  for (const auto& g : nodeGroups) nodeMembers.push_back(&mesh.nodeGroup(g));
  for (const auto& g : cellGroups) cellMembers.push_back(&mesh.cellGroup(g));
  const Families nodeFam = buildFamilies(mesh.nodeCount(), nodeGroups, nodeMembers, +1);
  const Families cellFam = buildFamilies(mesh.cellCount(), cellGroups, cellMembers, -1);
  file.check(medLibrary().familyCr(fid, meshName.c_str(), "FAMILLE_ZERO", 0, 0, ""), "creating family 0");
  for (const auto* fam : {&nodeFam, &cellFam})
    for (const auto& [number, groups] : fam->groupsOf) {
      const std::string name = (number > 0 ? "FAM_N_" : "FAM_M_") + std::to_string(number > 0 ? number : -number);
      file.check(medLibrary().familyCr(fid, meshName.c_str(), name.c_str(), number, static_cast<med_int>(groups.size()),
                             padded(groups, MED_LNAME_SIZE).c_str()),
                 "creating family " + name);
    }
  if (mesh.nodeCount() > 0)
    file.check(medLibrary().meshEntityFamilyNumberWr(fid, meshName.c_str(), MED_NO_DT, MED_NO_IT, MED_NODE, MED_NONE,
                                           mesh.nodeCount(), nodeFam.numberOf.data()),
               "writing node families");
  // Cells, type by type.
  for (int t = 0; t < kCellTypeCount; ++t) {
    const auto type = static_cast<CellType>(t);
    std::vector<med_int> conn, fam;
    std::vector<std::string> names;
    for (int c = 0; c < mesh.cellCount(); ++c) {
      if (mesh.cellType(c) != type) continue;
      const auto n = mesh.cellNodes(c);
      for (int k : fromAsterOrder(NodeConvention::Med, type, std::vector<int>(n.begin(), n.end()))) conn.push_back(k + 1);
      fam.push_back(cellFam.numberOf[c]);
      names.push_back(mesh.cellName(c));
    }
    if (fam.empty()) continue;
    const med_int count = static_cast<med_int>(fam.size());
    const std::string what = " of the " + cellTypeName(type) + " cells";
    file.check(medLibrary().meshElementConnectivityWr(fid, meshName.c_str(), MED_NO_DT, MED_NO_IT, 0.0, MED_CELL, medType(type),
                                            MED_NODAL, MED_FULL_INTERLACE, count, conn.data()),
               "writing the connectivity" + what);
    file.check(medLibrary().meshEntityFamilyNumberWr(fid, meshName.c_str(), MED_NO_DT, MED_NO_IT, MED_CELL, medType(type), count,
                                           fam.data()),
               "writing the families" + what);
    if (shortNames)
      file.check(medLibrary().meshEntityNameWr(fid, meshName.c_str(), MED_NO_DT, MED_NO_IT, MED_CELL, medType(type), count,
                                     padded(names, MED_SNAME_SIZE).c_str()),
                 "writing the names" + what);
  }
}

void writeFields(const MedFile& file, const Mesh& mesh, const std::vector<FieldInstant>& instants,
                 const std::string& meshName) {
  std::set<std::string> created;
  for (const auto& inst : instants)
    for (const auto& f : inst.fields) {
      const med_int nc = static_cast<med_int>(f.components.size());
      if (nc == 0 || f.values.size() != static_cast<std::size_t>(nc) * mesh.nodeCount())
        throw Error("MED writer: field '" + f.name + "' has " + std::to_string(f.values.size()) + " values, expected " +
                    std::to_string(mesh.nodeCount()) + " nodes x " + std::to_string(nc) + " components");
      if (f.name.size() > MED_NAME_SIZE) throw Error("MED writer: field name '" + f.name + "' is too long");
      if (created.insert(f.name).second)
        file.check(medLibrary().fieldCr(file.id(), f.name.c_str(), MED_FLOAT64, nc, padded(f.components, MED_SNAME_SIZE).c_str(),
                              std::string(nc * MED_SNAME_SIZE, ' ').c_str(), "", meshName.c_str()),
                   "creating field " + f.name);
      file.check(medLibrary().fieldValueWr(file.id(), f.name.c_str(), inst.index, MED_NO_IT, inst.time, MED_NODE, MED_NONE,
                                 MED_FULL_INTERLACE, MED_ALL_CONSTITUENT, mesh.nodeCount(),
                                 reinterpret_cast<const unsigned char*>(f.values.data())),
                 "writing field " + f.name + " at step " + std::to_string(inst.index));
    }
}

}  // namespace

void writeMedMesh(const Mesh& mesh, const std::string& path, const std::string& meshName) {
  writeMedResults(mesh, path, {}, meshName);
}

namespace {

// Writes to a new file, or adds to a copy of one (MED_ACC_RDWR), and closes it: every call
// and the close are checked. HDF5 keeps errno from the failing write: a full disk
// or a file-size limit is named.
void writeMedFile(const Mesh& mesh, const std::string& path, const std::vector<FieldInstant>& instants,
                  const std::string& meshName, bool add, bool meshPresent) {
  errno = 0;
  try {
    if (!add) std::remove(path.c_str());
    MedFile file(path, add ? MED_ACC_RDWR : MED_ACC_CREAT);
    if (!meshPresent) writeMesh(file, mesh, meshName);
    writeFields(file, mesh, instants, meshName);
    file.close();
  } catch (const Error& e) {
    const int why = errno;
    if (why == ENOSPC || why == EFBIG || why == EDQUOT || why == EIO)
      throw Error(std::string(e.what()) + ": " + std::strerror(why));
    throw;
  }
}

}  // namespace

void writeMedResults(const Mesh& mesh, const std::string& path, const std::vector<FieldInstant>& instants,
                     const std::string& meshName) {
  writeMedFile(mesh, path, instants, meshName, false, false);
}

void addMedResults(const Mesh& mesh, const std::string& path, const std::vector<FieldInstant>& instants,
                   const std::string& meshName, bool meshPresent) {
  writeMedFile(mesh, path, instants, meshName, true, meshPresent);
}

Mesh readMedMesh(const std::string& path, const std::string& wanted) {
  MedFile file(path, MED_ACC_RDONLY);
  const med_idt fid = file.id();
  const med_int meshes = medLibrary().nMesh(fid);
  if (meshes < 0) file.check(-1, "counting the meshes");
  if (meshes == 0) throw Error(path + ": the MED file holds no mesh (expected at least one unstructured mesh)");
  char name[MED_NAME_SIZE + 1] = {}, desc[MED_COMMENT_SIZE + 1] = {}, dtunit[MED_SNAME_SIZE + 1] = {};
  med_int sdim = 0, mdim = 0, nstep = 0;
  med_mesh_type mtype;
  med_sorting_type sort;
  med_axis_type axis;
  std::string meshName, description;
  std::vector<std::string> available;
  for (med_int m = 1; m <= meshes; ++m) {
    sdim = medLibrary().meshnAxis(fid, m);
    if (sdim < 0) file.check(-1, "reading the mesh list");
    std::vector<char> axisName(sdim * MED_SNAME_SIZE + 1), axisUnit(sdim * MED_SNAME_SIZE + 1);
    file.check(medLibrary().meshInfo(fid, m, name, &sdim, &mdim, &mtype, desc, dtunit, &sort, &nstep, &axis, axisName.data(),
                           axisUnit.data()),
               "reading the mesh list");
    const std::string n = fixed(name, MED_NAME_SIZE);
    available.push_back(n);
    if (wanted.empty() || n == wanted) {
      meshName = n;
      description = fixed(desc, MED_COMMENT_SIZE);
      if (mtype != MED_UNSTRUCTURED_MESH) throw Error(path + ": mesh '" + n + "' is not an unstructured mesh");
      break;
    }
  }
  if (meshName.empty())
    throw Error(path + ": no mesh called '" + wanted + "' in the MED file (expected one of the meshes present: " +
                [&] {
                  std::string s;
                  for (const auto& a : available) s += (s.empty() ? "" : ", ") + a;
                  return s;
                }() +
                ")");
  const char* mn = meshName.c_str();
  const std::string of = " of mesh '" + meshName + "'";  // the MED object in messages
  med_bool changed, transformed;
  Mesh mesh;
  mesh.title = description;
  mesh.setSpaceDimension(static_cast<int>(sdim));
  const med_int nn = medLibrary().meshnEntity(fid, mn, MED_NO_DT, MED_NO_IT, MED_NODE, MED_NONE, MED_COORDINATE, MED_NO_CMODE,
                                    &changed, &transformed);
  if (nn < 0) file.check(-1, "counting the nodes" + of);
  std::vector<med_float> xyz(static_cast<std::size_t>(nn) * sdim);
  if (nn > 0)
    file.check(medLibrary().meshNodeCoordinateRd(fid, mn, MED_NO_DT, MED_NO_IT, MED_FULL_INTERLACE, xyz.data()),
               "reading the coordinates" + of);

  auto readNames = [&](med_entity_type et, med_geometry_type gt, med_int count) {
    std::vector<std::string> names;
    const med_int has = medLibrary().meshnEntity(fid, mn, MED_NO_DT, MED_NO_IT, et, gt, MED_NAME, MED_NO_CMODE, &changed, &transformed);
    if (has <= 0) return names;
    std::vector<char> buf(static_cast<std::size_t>(count) * MED_SNAME_SIZE + 1);
    file.check(medLibrary().meshEntityNameRd(fid, mn, MED_NO_DT, MED_NO_IT, et, gt, buf.data()), "reading the names" + of);
    for (med_int k = 0; k < count; ++k) names.push_back(fixed(buf.data() + k * MED_SNAME_SIZE, MED_SNAME_SIZE));
    return names;
  };
  auto readFamilies = [&](med_entity_type et, med_geometry_type gt, med_int count) {
    std::vector<med_int> fam(count, 0);
    const med_int has =
        medLibrary().meshnEntity(fid, mn, MED_NO_DT, MED_NO_IT, et, gt, MED_FAMILY_NUMBER, MED_NO_CMODE, &changed, &transformed);
    if (has > 0 && count > 0)
      file.check(medLibrary().meshEntityFamilyNumberRd(fid, mn, MED_NO_DT, MED_NO_IT, et, gt, fam.data()),
                 "reading the families" + of);
    return fam;
  };

  const auto nodeNames = readNames(MED_NODE, MED_NONE, nn);
  for (med_int i = 0; i < nn; ++i) {
    Eigen::Vector3d x = Eigen::Vector3d::Zero();
    for (int d = 0; d < sdim; ++d) x[d] = xyz[static_cast<std::size_t>(i) * sdim + d];
    mesh.addNode(x, nodeNames.empty() ? "N" + std::to_string(i + 1) : nodeNames[i]);
  }
  const auto nodeFamily = readFamilies(MED_NODE, MED_NONE, nn);

  // Cells in MED type order.
  std::vector<std::pair<int, CellType>> order;
  for (int t = 0; t < kCellTypeCount; ++t) order.emplace_back(medType(static_cast<CellType>(t)), static_cast<CellType>(t));
  std::sort(order.begin(), order.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<med_int> cellFamily;
  std::vector<int> nodes;
  for (const auto& [mt, type] : order) {
    const med_int count = medLibrary().meshnEntity(fid, mn, MED_NO_DT, MED_NO_IT, MED_CELL, mt, MED_CONNECTIVITY, MED_NODAL,
                                         &changed, &transformed);
    if (count <= 0) continue;
    const int nnc = nodeCount(type);
    std::vector<med_int> conn(static_cast<std::size_t>(count) * nnc);
    file.check(medLibrary().meshElementConnectivityRd(fid, mn, MED_NO_DT, MED_NO_IT, MED_CELL, mt, MED_NODAL, MED_FULL_INTERLACE,
                                            conn.data()),
               "reading the " + cellTypeName(type) + " cells" + of);
    const auto names = readNames(MED_CELL, mt, count);
    const auto fam = readFamilies(MED_CELL, mt, count);
    const auto& perm = asterFromForeign(NodeConvention::Med, type);
    for (med_int e = 0; e < count; ++e) {
      nodes.assign(nnc, 0);
      for (int j = 0; j < nnc; ++j) {
        const med_int k = conn[static_cast<std::size_t>(e) * nnc + perm[j]];
        if (k < 1 || k > nn)
          throw Error(path + ": " + cellTypeName(type) + " cell " + std::to_string(e + 1) + " refers to node " +
                      std::to_string(k) + ", the mesh has " + std::to_string(nn) + " nodes");
        nodes[j] = static_cast<int>(k - 1);
      }
      mesh.addCell(type, nodes, names.empty() ? "M" + std::to_string(mesh.cellCount() + 1) : names[e]);
      cellFamily.push_back(fam[e]);
    }
  }
  // Families -> groups, in order of family definition.
  const med_int nfam = medLibrary().nFamily(fid, mn);
  std::map<med_int, std::vector<std::string>> groupsOfFamily;
  std::vector<std::string> nodeGroupOrder, cellGroupOrder;
  for (med_int f = 1; f <= nfam; ++f) {
    const med_int ng = medLibrary().nFamilyGroup(fid, mn, f);
    if (ng < 0) file.check(-1, "reading the families" + of);
    char famName[MED_NAME_SIZE + 1] = {};
    med_int number = 0;
    std::vector<char> groups(static_cast<std::size_t>(ng) * MED_LNAME_SIZE + 1);
    file.check(medLibrary().familyInfo(fid, mn, f, famName, &number, groups.data()), "reading the families" + of);
    auto& order = number > 0 ? nodeGroupOrder : cellGroupOrder;
    for (med_int g = 0; g < ng; ++g) {
      const std::string gname = fixed(groups.data() + g * MED_LNAME_SIZE, MED_LNAME_SIZE);
      groupsOfFamily[number].push_back(gname);
      if (std::find(order.begin(), order.end(), gname) == order.end()) order.push_back(gname);
    }
  }
  std::map<std::string, std::vector<int>> nodeGroups, cellGroups;
  for (int i = 0; i < mesh.nodeCount(); ++i)
    if (nodeFamily[i] != 0)
      for (const auto& g : groupsOfFamily[nodeFamily[i]]) nodeGroups[g].push_back(i);
  for (int c = 0; c < mesh.cellCount(); ++c)
    if (cellFamily[c] != 0)
      for (const auto& g : groupsOfFamily[cellFamily[c]]) cellGroups[g].push_back(c);
  for (const auto& g : cellGroupOrder) mesh.addCellGroup(g, cellGroups[g]);
  for (const auto& g : nodeGroupOrder) mesh.addNodeGroup(g, nodeGroups[g]);
  return mesh;
}

NodalField readMedNodalField(const std::string& path, const std::string& fieldName, int numdt) {
  MedFile file(path, MED_ACC_RDONLY);
  const med_idt fid = file.id();
  const med_int nc = medLibrary().fieldnComponentByName(fid, fieldName.c_str());
  if (nc <= 0) throw Error(path + ": no field '" + fieldName + "' in the MED file");
  char meshName[MED_NAME_SIZE + 1] = {}, dtunit[MED_SNAME_SIZE + 1] = {};
  med_bool local;
  med_field_type type;
  med_int nsteps = 0;
  std::vector<char> comp(nc * MED_SNAME_SIZE + 1), unit(nc * MED_SNAME_SIZE + 1);
  file.check(medLibrary().fieldInfoByName(fid, fieldName.c_str(), meshName, &local, &type, comp.data(), unit.data(), dtunit, &nsteps),
             "reading field " + fieldName);
  NodalField f;
  f.name = fieldName;
  for (med_int k = 0; k < nc; ++k) f.components.push_back(fixed(comp.data() + k * MED_SNAME_SIZE, MED_SNAME_SIZE));
  const med_int count = medLibrary().fieldnValue(fid, fieldName.c_str(), numdt, MED_NO_IT, MED_NODE, MED_NONE);
  if (count <= 0) throw Error(path + ": field '" + fieldName + "' has no nodal values at step " + std::to_string(numdt));
  f.values.resize(static_cast<std::size_t>(count) * nc);
  file.check(medLibrary().fieldValueRd(fid, fieldName.c_str(), numdt, MED_NO_IT, MED_NODE, MED_NONE, MED_FULL_INTERLACE,
                             MED_ALL_CONSTITUENT, reinterpret_cast<unsigned char*>(f.values.data())),
             "reading field " + fieldName);
  return f;
}

}  // namespace aster::mesh
