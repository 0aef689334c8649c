#include "mesh/io/med_format.hpp"

#include <med.h>

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <map>
#include <set>
#include <type_traits>

#include "core/error.hpp"
#include "core/interrupt.hpp"
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
  if (in.gcount() != sizeof head || std::memcmp(head, kSignature, sizeof head) != 0) {
    // A repository cloned without Git LFS holds a small text pointer in the file's place.
    static const char kLfsPointer[] = "version https://git-lfs";
    std::string start(sizeof kLfsPointer - 1, '\0');
    in.clear();
    in.seekg(0);
    in.read(start.data(), static_cast<std::streamsize>(start.size()));
    if (start == kLfsPointer)
      throw Error(path + ": a Git LFS pointer, not the MED file itself (fetch the file with 'git lfs pull')");
    throw Error(path + ": not a MED file (no HDF5 signature): " + kMedExpected);
  }
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

// code_aster's name of the reference element (elrefe) of a cell type, which
// begins the name of its Gauss point localizations.
std::string elrefeName(CellType t) {
  switch (t) {
    case CellType::POI1: return "PO1";
    case CellType::SEG2: return "SE2";
    case CellType::SEG3: return "SE3";
    case CellType::SEG4: return "SE4";
    case CellType::TRIA3: return "TR3";
    case CellType::TRIA6: return "TR6";
    case CellType::TRIA7: return "TR7";
    case CellType::QUAD4: return "QU4";
    case CellType::QUAD8: return "QU8";
    case CellType::QUAD9: return "QU9";
    default: return cellTypeName(t);
  }
}

// A Gauss point localization of a file (one aster-lite wrote: a file it adds to).
struct LocalizationInFile {
  std::string name;
  med_geometry_type type;
  med_int dimension, points;
};

std::vector<LocalizationInFile> localizationsInFile(const MedFile& file) {
  std::vector<LocalizationInFile> out;
  const med_int n = medLibrary().nLocalization(file.id());
  for (med_int k = 1; k <= n; ++k) {
    char name[MED_NAME_SIZE + 1] = {}, interp[MED_NAME_SIZE + 1] = {}, section[MED_NAME_SIZE + 1] = {};
    med_geometry_type gt, sgt;
    med_int sdim, npt, nsec;
    file.check(medLibrary().localizationInfo(file.id(), static_cast<int>(k), name, &gt, &sdim, &npt, interp, section,
                                             &nsec, &sgt),
               "reading the localizations");
    out.push_back({fixed(name, MED_NAME_SIZE), gt, sdim, npt});
  }
  return out;
}

std::set<std::string> profileNamesInFile(const MedFile& file) {
  std::set<std::string> names;
  const med_int n = medLibrary().nProfile(file.id());
  for (med_int k = 1; k <= n; ++k) {
    char name[MED_NAME_SIZE + 1] = {};
    med_int size = 0;
    file.check(medLibrary().profileInfo(file.id(), static_cast<int>(k), name, &size), "reading the profiles");
    names.insert(fixed(name, MED_NAME_SIZE));
  }
  return names;
}

// `base`, else base_2, base_3...: the first not in `used`, which takes it.
std::string takeName(const std::string& base, std::set<std::string>& used) {
  std::string name = base;
  for (int n = 2; used.count(name); ++n) name = base + "_" + std::to_string(n);
  used.insert(name);
  return name;
}

// Cell fields as code_aster writes them: at Gauss points (ELGA) on MED_CELL
// with a localization per cell type named after code_aster's (<elrefe>_____RIGI,
// "QU4_____RIGI"), at cell nodes (ELNO) on MED_NODE_ELEMENT, values in MED's
// node order; a profile when the field lies on some of the cells of a type.
class CellFieldWriter {
 public:
  CellFieldWriter(const MedFile& file, const Mesh& mesh) : file_(file), mesh_(mesh) {
    inFile_ = localizationsInFile(file);
    for (const auto& l : inFile_) localizationNames_.insert(l.name);
    profileNames_ = profileNamesInFile(file);
    for (int c = 0; c < mesh.cellCount(); ++c) {
      positionInType_.push_back(typeCount_[mesh.cellType(c)]++);
    }
  }

  void write(const CellValues& f, const FieldInstant& inst) {
    checkCellValues(mesh_, f, "MED writer");
    const std::size_t nc = f.components.size();
    // Cells by type, in the order the mesh numbers them within the type.
    std::map<CellType, std::vector<std::size_t>> byType;
    for (std::size_t k = 0; k < f.cells.size(); ++k) byType[mesh_.cellType(f.cells[k])].push_back(k);
    for (auto& [type, ks] : byType) {
      std::sort(ks.begin(), ks.end(), [&](std::size_t a, std::size_t b) { return f.cells[a] < f.cells[b]; });
      std::string localization = MED_NO_LOCALIZATION;
      const int nodes = nodeCount(type);
      std::vector<int> order(nodes);  // MED position j holds the aster point order[j] (ELNO)
      for (int j = 0; j < nodes; ++j) order[j] = j;
      if (f.atNodes) {
        order = fromAsterOrder(NodeConvention::Med, type, order);
      } else {
        for (const auto& l : f.localizations)
          if (l.type == type) localization = localizationOf(l);
      }
      std::vector<double> values;
      std::vector<med_int> profile;
      for (std::size_t k : ks) {
        const int begin = f.offsets[k];
        const int points = (f.offsets[k + 1] - begin) / static_cast<int>(nc);
        for (int p = 0; p < points; ++p) {
          const int from = f.atNodes ? order[p] : p;
          for (std::size_t c = 0; c < nc; ++c) values.push_back(f.values[begin + from * nc + c]);
        }
        profile.push_back(positionInType_[f.cells[k]] + 1);
      }
      std::string profileName = MED_NO_PROFILE;
      if (static_cast<int>(ks.size()) != typeCount_[type]) profileName = profileOf(f.name, type, profile);
      file_.check(medLibrary().fieldValueWithProfileWr(
                      file_.id(), f.name.c_str(), inst.index, MED_NO_IT, inst.time,
                      f.atNodes ? MED_NODE_ELEMENT : MED_CELL, medType(type), MED_COMPACT_STMODE, profileName.c_str(),
                      localization.c_str(), MED_FULL_INTERLACE, MED_ALL_CONSTITUENT,
                      static_cast<med_int>(ks.size()), reinterpret_cast<const unsigned char*>(values.data())),
                  "writing field " + f.name + " on the " + cellTypeName(type) + " cells at step " +
                      std::to_string(inst.index));
    }
  }

 private:
  std::string localizationOf(const GaussLocalization& l) {
    for (const auto& [known, name] : localizations_)
      if (known->type == l.type && known->points == l.points && known->weights == l.weights) return name;
    // The reference nodes in MED's order.
    const int nodes = nodeCount(l.type);
    std::vector<int> order(nodes);
    for (int j = 0; j < nodes; ++j) order[j] = j;
    order = fromAsterOrder(NodeConvention::Med, l.type, order);
    std::vector<double> ref;
    for (int j = 0; j < nodes; ++j)
      for (int d = 0; d < l.dimension; ++d) ref.push_back(l.nodes[order[j] * l.dimension + d]);
    // One the file holds already (an earlier IMPR_RESU to it), the same to the bit: taken again, as code_aster does.
    const med_int count = static_cast<med_int>(l.weights.size());
    for (const auto& f : inFile_) {
      if (f.type != medType(l.type) || f.dimension != l.dimension || f.points != count) continue;
      std::vector<double> fileRef(ref.size()), filePoints(l.points.size()), fileWeights(l.weights.size());
      file_.check(medLibrary().localizationRd(file_.id(), f.name.c_str(), MED_FULL_INTERLACE, fileRef.data(),
                                              filePoints.data(), fileWeights.data()),
                  "reading the localization " + f.name);
      if (fileRef == ref && filePoints == l.points && fileWeights == l.weights) {
        localizations_.emplace_back(&l, f.name);
        return f.name;
      }
    }
    const std::string name = takeName(elrefeName(l.type) + "_____RIGI", localizationNames_);
    file_.check(medLibrary().localizationWr(file_.id(), name.c_str(), medType(l.type), l.dimension, ref.data(),
                                            MED_FULL_INTERLACE, static_cast<med_int>(l.weights.size()),
                                            l.points.data(), l.weights.data(), MED_NO_INTERPOLATION,
                                            MED_NO_MESH_SUPPORT),
                "writing the Gauss point localization " + name);
    localizations_.emplace_back(&l, name);
    return name;
  }

  std::string profileOf(const std::string& field, CellType type, const std::vector<med_int>& cells) {
    for (const auto& [known, name] : profiles_)
      if (known == cells) return name;
    const std::string name = takeName((field + "_" + cellTypeName(type)).substr(0, MED_NAME_SIZE - 4), profileNames_);
    file_.check(medLibrary().profileWr(file_.id(), name.c_str(), static_cast<med_int>(cells.size()), cells.data()),
                "writing the profile " + name);
    profiles_.emplace_back(cells, name);
    return name;
  }

  const MedFile& file_;
  const Mesh& mesh_;
  std::map<CellType, int> typeCount_;
  std::vector<int> positionInType_;
  std::vector<LocalizationInFile> inFile_;
  std::set<std::string> localizationNames_, profileNames_;
  std::vector<std::pair<const GaussLocalization*, std::string>> localizations_;
  std::vector<std::pair<std::vector<med_int>, std::string>> profiles_;
};

void writeCellFields(const MedFile& file, const Mesh& mesh, const std::vector<FieldInstant>& instants,
                     const std::string& meshName) {
  CellFieldWriter writer(file, mesh);
  std::set<std::string> created;
  for (const auto& inst : instants)
    for (const auto& f : inst.cellFields) {
      const med_int nc = static_cast<med_int>(f.components.size());
      if (f.name.size() > MED_NAME_SIZE) throw Error("MED writer: field name '" + f.name + "' is too long");
      if (created.insert(f.name).second)
        file.check(medLibrary().fieldCr(file.id(), f.name.c_str(), MED_FLOAT64, nc,
                                        padded(f.components, MED_SNAME_SIZE).c_str(),
                                        std::string(nc * MED_SNAME_SIZE, ' ').c_str(), "", meshName.c_str()),
                   "creating field " + f.name);
      writer.write(f, inst);
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
    writeCellFields(file, mesh, instants, meshName);
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

namespace {

// ---- Reading ----
//
// HDF5 and the MED library trust the metadata of the file they read: crashes of
// HDF5 1.10 on crafted object headers and B-trees are on record (CVEs), and both
// print their error stacks to stderr. A MED file is therefore
// read in a child process (fork) that sends what it read back through a pipe;
// the parent turns a child that dies into an error naming the file. The child
// only reads the file and leaves with _exit: no loop of the worker pool, no destructor of
// the parent's objects and no atexit handler runs in it. Its stdout goes to
// /dev/null, its stderr to a temporary file that is dropped, unless it holds a
// sanitizer report (sanitizer builds), which is passed on.
// The counts and indices the library returns are checked all the same before
// they size a buffer or index an array.

// A count of items of `bytesEach` bytes that the file must hold: MED writes its
// arrays uncompressed, so a count larger than the file is damaged metadata.
void checkCount(const std::string& path, std::uintmax_t fileSize, med_int n, std::uintmax_t bytesEach,
                const std::string& what) {
  if (n < 0 || static_cast<std::uintmax_t>(n) > fileSize / bytesEach ||
      static_cast<long long>(n) > std::numeric_limits<int>::max())
    throw Error(path + ": the MED file announces " + std::to_string(n) + " " + what + ", more than its " +
                std::to_string(fileSize) + " bytes can hold (a damaged file; " + kMedExpected + ")");
}

// What the child sends to the parent, written and read in the same order (host
// byte order: both ends are this program).
class Packer {
 public:
  template <class T>
  void put(const T& value) {
    static_assert(std::is_trivially_copyable_v<T>);
    data_.append(reinterpret_cast<const char*>(&value), sizeof value);
  }
  void put(const std::string& s) {
    put(static_cast<std::uint64_t>(s.size()));
    data_ += s;
  }
  template <class T>
  void put(const std::vector<T>& v) {
    put(static_cast<std::uint64_t>(v.size()));
    data_.append(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(T));
  }
  std::string take() { return std::move(data_); }

 private:
  std::string data_;
};

class Unpacker {
 public:
  explicit Unpacker(const std::string& data) : data_(data) {}
  template <class T>
  T get() {
    T value{};
    need(sizeof value);
    std::memcpy(&value, data_.data() + pos_, sizeof value);
    pos_ += sizeof value;
    return value;
  }
  std::string getString() {
    const std::size_t n = size(1);
    std::string s = data_.substr(pos_, n);
    pos_ += n;
    return s;
  }
  template <class T>
  std::vector<T> getVector() {
    const std::size_t n = size(sizeof(T));
    std::vector<T> v(n);
    if (n) std::memcpy(v.data(), data_.data() + pos_, n * sizeof(T));
    pos_ += n * sizeof(T);
    return v;
  }

 private:
  void need(std::size_t n) const {
    if (data_.size() - pos_ < n) throw Error("MED reader: the data sent by the reading process is incomplete");
  }
  std::size_t size(std::size_t bytesEach) {
    const auto n = get<std::uint64_t>();
    if (n > (data_.size() - pos_) / bytesEach)
      throw Error("MED reader: the data sent by the reading process is incomplete");
    return static_cast<std::size_t>(n);
  }
  const std::string& data_;
  std::size_t pos_ = 0;
};

std::string packMesh(const Mesh& mesh) {
  Packer p;
  p.put(mesh.title);
  p.put(static_cast<std::int32_t>(mesh.spaceDimension()));
  p.put(static_cast<std::uint64_t>(mesh.nodeCount()));
  for (int i = 0; i < mesh.nodeCount(); ++i) {
    const Eigen::Vector3d x = mesh.node(i);
    p.put(std::array<double, 3>{x[0], x[1], x[2]});
    p.put(mesh.nodeName(i));
  }
  p.put(static_cast<std::uint64_t>(mesh.cellCount()));
  for (int c = 0; c < mesh.cellCount(); ++c) {
    const auto n = mesh.cellNodes(c);
    p.put(static_cast<std::int32_t>(mesh.cellType(c)));
    p.put(std::vector<int>(n.begin(), n.end()));
    p.put(mesh.cellName(c));
  }
  const auto cellGroups = mesh.cellGroupNames(), nodeGroups = mesh.nodeGroupNames();
  p.put(static_cast<std::uint64_t>(cellGroups.size()));
  for (const auto& g : cellGroups) {
    p.put(g);
    p.put(mesh.cellGroup(g));
  }
  p.put(static_cast<std::uint64_t>(nodeGroups.size()));
  for (const auto& g : nodeGroups) {
    p.put(g);
    p.put(mesh.nodeGroup(g));
  }
  return p.take();
}

Mesh unpackMesh(const std::string& data) {
  Unpacker u(data);
  Mesh mesh;
  mesh.title = u.getString();
  mesh.setSpaceDimension(u.get<std::int32_t>());
  const auto nodes = u.get<std::uint64_t>();
  for (std::uint64_t i = 0; i < nodes; ++i) {
    const auto x = u.get<std::array<double, 3>>();
    mesh.addNode({x[0], x[1], x[2]}, u.getString());
  }
  const auto cells = u.get<std::uint64_t>();
  for (std::uint64_t c = 0; c < cells; ++c) {
    const auto t = u.get<std::int32_t>();
    if (t < 0 || t >= kCellTypeCount) throw Error("MED reader: the data sent by the reading process is damaged");
    const auto type = static_cast<CellType>(t);
    const auto n = u.getVector<int>();
    mesh.addCell(type, n, u.getString());
  }
  for (const bool cellGroups : {true, false}) {
    const auto groups = u.get<std::uint64_t>();
    for (std::uint64_t g = 0; g < groups; ++g) {
      const std::string name = u.getString();
      auto members = u.getVector<int>();
      cellGroups ? mesh.addCellGroup(name, std::move(members)) : mesh.addNodeGroup(name, std::move(members));
    }
  }
  return mesh;
}

void writeAll(int fd, const std::string& data) {
  std::size_t done = 0;
  while (done < data.size()) {
    const ssize_t n = ::write(fd, data.data() + done, data.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return;  // the parent is gone or failed: it reports the missing data
    done += static_cast<std::size_t>(n);
  }
}

// What the child printed to stderr, passed on when it is a sanitizer report.
void passOnSanitizerReport(std::FILE* log) {
  if (!log) return;
  std::string text;
  char buffer[4096];
  std::rewind(log);
  for (std::size_t n; (n = std::fread(buffer, 1, sizeof buffer, log)) > 0;) text.append(buffer, n);
  std::fclose(log);
  if (text.find("Sanitizer") != std::string::npos || text.find("runtime error:") != std::string::npos)
    std::fprintf(stderr, "%s", text.c_str());
}

}  // namespace

std::string detail::readInChild(const std::string& path, const std::function<std::string()>& read) {
  medLibrary();  // loaded once, in the parent: its errors are the parent's
  int fds[2];
  if (::pipe(fds) != 0)
    throw Error("cannot read the MED file '" + path + "': no pipe to a reading process (" + std::strerror(errno) + ")");
  std::FILE* log = std::tmpfile();
  std::fflush(nullptr);  // nothing buffered is written twice
  const pid_t pid = ::fork();
  if (pid < 0) {
    const int e = errno;
    ::close(fds[0]);
    ::close(fds[1]);
    if (log) std::fclose(log);
    throw Error("cannot read the MED file '" + path + "': no reading process (fork: " + std::strerror(e) + ")");
  }
  if (pid == 0) {
    ::close(fds[0]);
    const int null = ::open("/dev/null", O_WRONLY);
    if (null >= 0) ::dup2(null, STDOUT_FILENO);
    if (log)
      ::dup2(::fileno(log), STDERR_FILENO);
    else if (null >= 0)
      ::dup2(null, STDERR_FILENO);
    std::string out;
    try {
      out = "D" + read();
    } catch (const std::bad_alloc&) {
      out = "E" + path + ": the MED file announces more data than memory can hold (a damaged file; " + kMedExpected + ")";
    } catch (const std::exception& e) {
      out = std::string("E") + e.what();
    } catch (...) {
      out = "E" + path + ": unknown error while reading the MED file";
    }
    writeAll(fds[1], out);
    ::_exit(0);
  }
  ::close(fds[1]);
  std::string data;
  char buffer[65536];
  for (;;) {
    const ssize_t n = ::read(fds[0], buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    data.append(buffer, static_cast<std::size_t>(n));
  }
  ::close(fds[0]);
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  passOnSanitizerReport(log);
  if (WIFSIGNALED(status)) {
    const int sig = WTERMSIG(status);
    if (sig == SIGINT) throw Interrupted("interrupted (SIGINT) while reading the MED file " + path);
    const char* name = sigabbrev_np(sig);
    throw Error(path + ": the MED library (HDF5) crashed reading the file (signal " +
                (name ? "SIG" + std::string(name) : std::to_string(sig)) + "): a damaged MED file (" + kMedExpected +
                ")");
  }
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0 || data.empty())
    throw Error(path + ": the process reading the MED file ended without a result (exit status " +
                std::to_string(WIFEXITED(status) ? WEXITSTATUS(status) : -1) + "): a damaged MED file? (" +
                kMedExpected + ")");
  if (data[0] == 'E') throw Error(data.substr(1));
  return data.substr(1);
}

namespace {

// Reads the mesh (in the child): every count and index from the file checked.
Mesh readMesh(const std::string& path, const std::string& wanted, std::uintmax_t fileSize) {
  MedFile file(path, MED_ACC_RDONLY);
  const med_idt fid = file.id();
  const med_int meshes = medLibrary().nMesh(fid);
  if (meshes < 0) file.check(-1, "counting the meshes");
  if (meshes == 0) throw Error(path + ": the MED file holds no mesh (expected at least one unstructured mesh)");
  checkCount(path, fileSize, meshes, 64, "meshes");
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
    if (sdim < 1 || sdim > 3)
      throw Error(path + ": mesh " + std::to_string(m) + " of the MED file has space dimension " +
                  std::to_string(sdim) + " (expected 1, 2 or 3: a damaged file?)");
    // Room for 3 axes whatever the count: the names are read again below.
    std::vector<char> axisName(3 * MED_SNAME_SIZE + 1), axisUnit(3 * MED_SNAME_SIZE + 1);
    file.check(medLibrary().meshInfo(fid, m, name, &sdim, &mdim, &mtype, desc, dtunit, &sort, &nstep, &axis, axisName.data(),
                           axisUnit.data()),
               "reading the mesh list");
    if (sdim < 1 || sdim > 3)
      throw Error(path + ": mesh " + std::to_string(m) + " of the MED file has space dimension " +
                  std::to_string(sdim) + " (expected 1, 2 or 3: a damaged file?)");
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
  checkCount(path, fileSize, nn, sdim * sizeof(med_float), "nodes" + of);
  std::vector<med_float> xyz(static_cast<std::size_t>(nn) * sdim);
  if (nn > 0)
    file.check(medLibrary().meshNodeCoordinateRd(fid, mn, MED_NO_DT, MED_NO_IT, MED_FULL_INTERLACE, xyz.data()),
               "reading the coordinates" + of);

  // Names and family numbers: as many as the entities, or none.
  auto announced = [&](med_entity_type et, med_geometry_type gt, med_data_type data, med_int count,
                       const std::string& what) {
    const med_int has = medLibrary().meshnEntity(fid, mn, MED_NO_DT, MED_NO_IT, et, gt, data, MED_NO_CMODE, &changed, &transformed);
    if (has > 0 && has != count)
      throw Error(path + ": the MED file has " + std::to_string(has) + " " + what + " for " + std::to_string(count) +
                  (count == 1 ? " entity" : " entities") + of + " (expected one each: a damaged file?)");
    return has > 0;
  };
  auto readNames = [&](med_entity_type et, med_geometry_type gt, med_int count, const std::string& what) {
    std::vector<std::string> names;
    if (count == 0 || !announced(et, gt, MED_NAME, count, "names of " + what)) return names;
    std::vector<char> buf(static_cast<std::size_t>(count) * MED_SNAME_SIZE + 1);
    file.check(medLibrary().meshEntityNameRd(fid, mn, MED_NO_DT, MED_NO_IT, et, gt, buf.data()), "reading the names" + of);
    for (med_int k = 0; k < count; ++k) {
      names.push_back(fixed(buf.data() + k * MED_SNAME_SIZE, MED_SNAME_SIZE));
      if (names.back().empty())
        throw Error(path + ": the MED file gives no name to entity " + std::to_string(k + 1) + " of the " + what + of +
                    " (expected a name for each: a damaged file?)");
    }
    return names;
  };
  auto readFamilies = [&](med_entity_type et, med_geometry_type gt, med_int count, const std::string& what) {
    std::vector<med_int> fam(count, 0);
    if (count > 0 && announced(et, gt, MED_FAMILY_NUMBER, count, "family numbers of " + what))
      file.check(medLibrary().meshEntityFamilyNumberRd(fid, mn, MED_NO_DT, MED_NO_IT, et, gt, fam.data()),
                 "reading the families" + of);
    return fam;
  };

  const auto nodeNames = readNames(MED_NODE, MED_NONE, nn, "nodes");
  for (med_int i = 0; i < nn; ++i) {
    Eigen::Vector3d x = Eigen::Vector3d::Zero();
    for (int d = 0; d < sdim; ++d) x[d] = xyz[static_cast<std::size_t>(i) * sdim + d];
    const std::string nodeName = nodeNames.empty() ? "N" + std::to_string(i + 1) : nodeNames[i];
    if (!x.allFinite())
      throw Error(path + ": node " + nodeName + of + " has a coordinate that is not a finite number (" +
                  std::to_string(x[0]) + ", " + std::to_string(x[1]) + ", " + std::to_string(x[2]) + ")");
    mesh.addNode(x, nodeName);
  }
  const auto nodeFamily = readFamilies(MED_NODE, MED_NONE, nn, "nodes");

  // Cells in MED type order, of every type the file has: a type aster-lite does
  // not read, or one announced without cells (damaged metadata), is an error
  // rather than cells silently left out.
  std::vector<std::pair<med_geometry_type, CellType>> order;
  const med_int types = medLibrary().meshnEntity(fid, mn, MED_NO_DT, MED_NO_IT, MED_CELL, MED_GEO_ALL, MED_CONNECTIVITY,
                                                 MED_NODAL, &changed, &transformed);
  if (types < 0) file.check(-1, "counting the cell types" + of);
  checkCount(path, fileSize, types, MED_NAME_SIZE, "cell types" + of);
  for (med_int it = 1; it <= types; ++it) {
    char typeName[MED_NAME_SIZE + 1] = {};
    med_geometry_type mt = MED_NONE;
    file.check(medLibrary().meshEntityInfo(fid, mn, MED_NO_DT, MED_NO_IT, MED_CELL, static_cast<int>(it), typeName, &mt),
               "reading the cell types" + of);
    int t = 0;
    while (t < kCellTypeCount && medType(static_cast<CellType>(t)) != mt) ++t;
    if (t == kCellTypeCount)
      throw Error(path + ": mesh '" + meshName + "' has cells of the MED type '" + fixed(typeName, MED_NAME_SIZE) + "' (" +
                  std::to_string(mt) + "), which aster-lite does not read (expected the code_aster types POI1 to HEXA27)");
    order.emplace_back(mt, static_cast<CellType>(t));
  }
  std::sort(order.begin(), order.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<med_int> cellFamily;
  std::vector<int> nodes;
  for (const auto& [mt, type] : order) {
    const med_int count = medLibrary().meshnEntity(fid, mn, MED_NO_DT, MED_NO_IT, MED_CELL, mt, MED_CONNECTIVITY, MED_NODAL,
                                         &changed, &transformed);
    const int nnc = nodeCount(type);
    const std::string cellsOf = cellTypeName(type) + " cells";
    if (count <= 0)
      throw Error(path + ": the MED file announces " + std::to_string(count) + " " + cellsOf + of +
                  " (expected at least one for a type it lists: a damaged file)");
    checkCount(path, fileSize, count, nnc * sizeof(med_int), cellsOf + of);
    std::vector<med_int> conn(static_cast<std::size_t>(count) * nnc);
    file.check(medLibrary().meshElementConnectivityRd(fid, mn, MED_NO_DT, MED_NO_IT, MED_CELL, mt, MED_NODAL, MED_FULL_INTERLACE,
                                            conn.data()),
               "reading the " + cellsOf + of);
    const auto names = readNames(MED_CELL, mt, count, cellsOf);
    const auto fam = readFamilies(MED_CELL, mt, count, cellsOf);
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
  if (mesh.cellCount() == 0)
    throw Error(path + ": mesh '" + meshName + "' of the MED file has no cell (expected cells of the code_aster types)");
  // Families -> groups, in order of family definition.
  const med_int nfam = medLibrary().nFamily(fid, mn);
  if (nfam < 0) file.check(-1, "counting the families" + of);
  checkCount(path, fileSize, nfam, MED_NAME_SIZE, "families" + of);
  std::map<med_int, std::vector<std::string>> groupsOfFamily{{0, {}}};  // family 0: no group
  std::vector<std::string> nodeGroupOrder, cellGroupOrder;
  for (med_int f = 1; f <= nfam; ++f) {
    const med_int ng = medLibrary().nFamilyGroup(fid, mn, f);
    if (ng < 0) file.check(-1, "reading the families" + of);
    checkCount(path, fileSize, ng, MED_LNAME_SIZE, "groups in family " + std::to_string(f) + of);
    char famName[MED_NAME_SIZE + 1] = {};
    med_int number = 0;
    std::vector<char> groups(static_cast<std::size_t>(ng) * MED_LNAME_SIZE + 1);
    file.check(medLibrary().familyInfo(fid, mn, f, famName, &number, groups.data()), "reading the families" + of);
    auto& order = number > 0 ? nodeGroupOrder : cellGroupOrder;
    groupsOfFamily[number];  // defined, maybe without groups
    for (med_int g = 0; g < ng; ++g) {
      const std::string gname = fixed(groups.data() + g * MED_LNAME_SIZE, MED_LNAME_SIZE);
      if (gname.empty())
        throw Error(path + ": family '" + fixed(famName, MED_NAME_SIZE) + "'" + of +
                    " has a group without a name (a damaged file?)");
      groupsOfFamily[number].push_back(gname);
      if (std::find(order.begin(), order.end(), gname) == order.end()) order.push_back(gname);
    }
  }
  // A family number without its family is damage: the groups of the entity are lost.
  auto groupsOf = [&](med_int family, const std::string& entity) -> const std::vector<std::string>& {
    const auto it = groupsOfFamily.find(family);
    if (it == groupsOfFamily.end())
      throw Error(path + ": " + entity + of + " is in family " + std::to_string(family) +
                  ", which the MED file does not define (a damaged file?)");
    return it->second;
  };
  std::map<std::string, std::vector<int>> nodeGroups, cellGroups;
  for (int i = 0; i < mesh.nodeCount(); ++i)
    for (const auto& g : groupsOf(nodeFamily[i], "node " + mesh.nodeName(i))) nodeGroups[g].push_back(i);
  for (int c = 0; c < mesh.cellCount(); ++c)
    for (const auto& g : groupsOf(cellFamily[c], "cell " + mesh.cellName(c))) cellGroups[g].push_back(c);
  for (const auto& g : cellGroupOrder) mesh.addCellGroup(g, cellGroups[g]);
  for (const auto& g : nodeGroupOrder) mesh.addNodeGroup(g, nodeGroups[g]);
  return mesh;
}

NodalField readField(const std::string& path, const std::string& fieldName, int numdt, std::uintmax_t fileSize) {
  MedFile file(path, MED_ACC_RDONLY);
  const med_idt fid = file.id();
  const med_int nc = medLibrary().fieldnComponentByName(fid, fieldName.c_str());
  if (nc <= 0) throw Error(path + ": no field '" + fieldName + "' in the MED file");
  checkCount(path, fileSize, nc, MED_SNAME_SIZE, "components of field '" + fieldName + "'");
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
  checkCount(path, fileSize / nc, count, sizeof(double), "values of field '" + fieldName + "'");
  f.values.resize(static_cast<std::size_t>(count) * nc);
  file.check(medLibrary().fieldValueRd(fid, fieldName.c_str(), numdt, MED_NO_IT, MED_NODE, MED_NONE, MED_FULL_INTERLACE,
                             MED_ALL_CONSTITUENT, reinterpret_cast<unsigned char*>(f.values.data())),
             "reading field " + fieldName);
  return f;
}

// The size of a file that checkHdf5Signature could open.
std::uintmax_t sizeOf(const std::string& path) {
  std::error_code ec;
  const std::uintmax_t size = std::filesystem::file_size(path, ec);
  if (ec) throw Error("cannot open the MED file '" + path + "' (" + ec.message() + ")");
  return size;
}

// readMesh, with the file named in the messages of the mesh's own checks (duplicate names...).
Mesh readMeshOf(const std::string& path, const std::string& wanted) {
  checkHdf5Signature(path);
  const std::uintmax_t fileSize = sizeOf(path);
  try {
    return readMesh(path, wanted, fileSize);
  } catch (const Error& e) {
    if (std::string(e.what()).find(path) != std::string::npos) throw;
    throw Error(path + ": " + e.what());
  }
}

}  // namespace

Mesh readMedMesh(const std::string& path, const std::string& wanted) {
  checkHdf5Signature(path);  // the common mistakes, without a child process
  return unpackMesh(detail::readInChild(path, [&] { return packMesh(readMeshOf(path, wanted)); }));
}

NodalField readMedNodalField(const std::string& path, const std::string& fieldName, int numdt) {
  checkHdf5Signature(path);
  const std::uintmax_t fileSize = sizeOf(path);
  const std::string data = detail::readInChild(path, [&] {
    const NodalField f = readField(path, fieldName, numdt, fileSize);
    Packer p;
    p.put(f.components.size());
    for (const auto& c : f.components) p.put(c);
    p.put(f.values);
    return p.take();
  });
  Unpacker u(data);
  NodalField f;
  f.name = fieldName;
  const auto components = u.get<std::size_t>();
  for (std::size_t k = 0; k < components; ++k) f.components.push_back(u.getString());
  f.values = u.getVector<double>();
  return f;
}

}  // namespace aster::mesh
