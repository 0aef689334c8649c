#include "mesh/io/gmsh_format.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <type_traits>
#include <unordered_map>

#include "core/error.hpp"
#include "mesh/io/gmsh_library.hpp"
#include "mesh/io/msh2_writer.hpp"
#include "mesh/group_ops.hpp"
#include "mesh/io/msh_check.hpp"
#include "mesh/node_ordering.hpp"

namespace aster::mesh {

namespace {

// What gmsh's C++ API threw: gmsh's C API sets its last argument (ierr) instead.
// The callers' catch (...) then reports gmsh's last error.
struct GmshFailed {};

// Calls a function of gmsh's C API, adding its ierr argument.
template <typename Function, typename... Args>
auto call(Function function, Args... args) {
  int ierr = 0;
  if constexpr (std::is_void_v<decltype(function(args..., &ierr))>) {
    function(args..., &ierr);
    if (ierr) throw GmshFailed{};
  } else {
    const auto result = function(args..., &ierr);
    if (ierr) throw GmshFailed{};
    return result;
  }
}

// The C API takes its input arrays as non-const pointers; it does not write to them.
template <typename T>
T* input(const std::vector<T>& v) {
  return const_cast<T*>(v.data());
}

// Copies an array gmsh returned and frees it (it was allocated by gmsh).
template <typename T>
std::vector<T> take(T* data, std::size_t size) {
  std::vector<T> v(data, data + size);
  gmshLibrary().Free(data);
  return v;
}

std::string take(char* text) {
  std::string s = text ? text : "";
  gmshLibrary().Free(text);
  return s;
}

std::vector<std::pair<int, int>> takeDimTags(int* data, std::size_t size) {
  const auto flat = take(data, size);
  std::vector<std::pair<int, int>> dimTags;
  for (std::size_t i = 0; i + 1 < flat.size(); i += 2) dimTags.emplace_back(flat[i], flat[i + 1]);
  return dimTags;
}

std::vector<std::vector<std::size_t>> take(std::size_t** data, std::size_t* sizes, std::size_t count) {
  std::vector<std::vector<std::size_t>> v;
  for (std::size_t k = 0; k < count; ++k) v.push_back(take(data[k], sizes[k]));
  gmshLibrary().Free(data);
  gmshLibrary().Free(sizes);
  return v;
}

std::string lastError() {
  char* text = nullptr;
  int ierr = 0;
  gmshLibrary().LoggerGetLastError(&text, &ierr);
  return take(text);
}

// The getters of gmsh's C++ API that the reader uses, over the C API.
std::vector<std::pair<int, int>> getPhysicalGroups() {
  int* dimTags = nullptr;
  std::size_t size = 0;
  call(gmshLibrary().ModelGetPhysicalGroups, &dimTags, &size, -1);
  return takeDimTags(dimTags, size);
}

std::string getPhysicalName(int dim, int tag) {
  char* name = nullptr;
  call(gmshLibrary().ModelGetPhysicalName, dim, tag, &name);
  return take(name);
}

std::vector<int> getEntitiesForPhysicalGroup(int dim, int tag) {
  int* tags = nullptr;
  std::size_t size = 0;
  call(gmshLibrary().ModelGetEntitiesForPhysicalGroup, dim, tag, &tags, &size);
  return take(tags, size);
}

std::vector<std::pair<int, int>> getEntities() {
  int* dimTags = nullptr;
  std::size_t size = 0;
  call(gmshLibrary().ModelGetEntities, &dimTags, &size, -1);
  return takeDimTags(dimTags, size);
}

// Per element type: its number, the tags of its elements and their nodes.
struct Elements {
  std::vector<int> types;
  std::vector<std::vector<std::size_t>> tags, nodeTags;
};

Elements getElements(int dim, int tag) {
  int* types = nullptr;
  std::size_t typeCount = 0;
  std::size_t **tags = nullptr, **nodeTags = nullptr;
  std::size_t *tagSizes = nullptr, *nodeTagSizes = nullptr;
  std::size_t tagLists = 0, nodeTagLists = 0;
  call(gmshLibrary().ModelMeshGetElements, &types, &typeCount, &tags, &tagSizes, &tagLists, &nodeTags, &nodeTagSizes,
       &nodeTagLists, dim, tag);
  return {take(types, typeCount), take(tags, tagSizes, tagLists), take(nodeTags, nodeTagSizes, nodeTagLists)};
}

// Every node of the model: tags and coordinates (x y z per node).
std::pair<std::vector<std::size_t>, std::vector<double>> getNodes() {
  std::size_t* tags = nullptr;
  double *coords = nullptr, *parametric = nullptr;
  std::size_t tagSize = 0, coordSize = 0, parametricSize = 0;
  call(gmshLibrary().ModelMeshGetNodes, &tags, &tagSize, &coords, &coordSize, &parametric, &parametricSize, -1, -1, 0,
       0);
  take(parametric, parametricSize);  // not asked for, freed
  return {take(tags, tagSize), take(coords, coordSize)};
}

// One gmsh session per call: gmsh keeps global state, it must not leak between calls.
// Its constructor loads libgmsh (gmsh_library.hpp) the first time.
class GmshSession {
 public:
  GmshSession() {
    call(gmshLibrary().Initialize, 0, nullptr, 1);  // no arguments, read gmsh's config files (C++ defaults)
    call(gmshLibrary().OptionSetNumber, "General.Terminal", 0.0);
  }
  ~GmshSession() {
    int ierr = 0;
    gmshLibrary().Finalize(&ierr);  // a failure to clean up is not the study's concern
  }
  GmshSession(const GmshSession&) = delete;
  GmshSession& operator=(const GmshSession&) = delete;
};

// gmsh reports errors to its logger (and sometimes fails): turn both into aster::Error.
// `expected` ends the message ("" or " (expected ...)").
void checkGmsh(const std::string& context, const std::string& expected = "") {
  const std::string last = lastError();
  if (!last.empty()) throw Error(context + ": gmsh error: " + last + expected);
}

std::string elementName(int number) {
  char* name = nullptr;
  int dim = 0, order = 0, nn = 0, nv = 0;
  double* coords = nullptr;
  std::size_t size = 0;
  call(gmshLibrary().ModelMeshGetElementProperties, number, &name, &dim, &order, &nn, &coords, &size, &nv);
  take(coords, size);  // not needed, freed
  return take(name);
}

CellType asterType(int number, const std::string& path) {
  if (const auto type = cellTypeOfGmshElement(number)) return *type;
  std::string name;
  try {
    name = elementName(number);
  } catch (...) {
    name = "?";
  }
  throw Error(path + ": gmsh element type " + std::to_string(number) + " (" + name +
              ") has no code_aster equivalent (expected one of the gmsh types " + supportedGmshElementTypes() + ")");
}

bool hasExtension(const std::string& path, const std::string& ext) {
  if (path.size() < ext.size()) return false;
  std::string tail = path.substr(path.size() - ext.size());
  std::transform(tail.begin(), tail.end(), tail.begin(), [](unsigned char c) { return std::tolower(c); });
  return tail == ext;
}

Mesh readCurrentModel(const std::string& path) {
  // Physical groups of each entity; the reserved group only marks entities to keep.
  const auto physicals = getPhysicalGroups();
  std::map<std::pair<int, int>, std::vector<std::string>> groupsOfEntity;
  std::set<std::pair<int, int>> kept;
  std::map<std::pair<int, int>, int> physicalCount;
  std::vector<std::string> groupOrder;
  for (const auto& [dim, tag] : physicals) {
    std::string name = getPhysicalName(dim, tag);
    const std::vector<int> entities = getEntitiesForPhysicalGroup(dim, tag);
    for (int e : entities) ++physicalCount[{dim, e}];
    if (name == kGmshUngroupedName) {
      for (int e : entities) kept.insert({dim, e});
      continue;
    }
    if (name.empty()) name = "GM" + std::to_string(tag);
    if (std::find(groupOrder.begin(), groupOrder.end(), name) == groupOrder.end()) groupOrder.push_back(name);
    for (int e : entities) groupsOfEntity[{dim, e}].push_back(name);
  }

  struct RawCell {
    CellType type;
    std::size_t tag;
    std::vector<std::size_t> nodes;
  };
  std::vector<RawCell> cells;
  std::map<std::string, std::vector<int>> groupCells;
  std::set<std::size_t> seenCells;
  const auto entities = getEntities();
  for (const auto& [dim, tag] : entities) {
    const auto groups = groupsOfEntity.find({dim, tag});
    if (dim == 0 && groups == groupsOfEntity.end() && !kept.count({dim, tag})) continue;
    const auto [types, elementTags, nodeTags] = getElements(dim, tag);
    // MSH 2.2 has one physical tag per element line: gmsh writes an element of an
    // entity in several physical groups once per group, under new numbers. Such
    // copies (same entity, type and nodes) are one cell.
    const bool copies = physicalCount[{dim, tag}] > 1;
    std::set<std::pair<CellType, std::vector<std::size_t>>> seenInEntity;
    for (std::size_t k = 0; k < types.size(); ++k) {
      const CellType type = asterType(types[k], path);
      const int nn = nodeCount(type);
      const auto& perm = asterFromForeign(NodeConvention::Gmsh, type);
      for (std::size_t e = 0; e < elementTags[k].size(); ++e) {
        if (!seenCells.insert(elementTags[k][e]).second) continue;  // already met in another entity
        RawCell c{type, elementTags[k][e], std::vector<std::size_t>(nn)};
        for (int j = 0; j < nn; ++j) c.nodes[j] = nodeTags[k][e * nn + perm[j]];
        if (copies && !seenInEntity.emplace(type, c.nodes).second) continue;
        if (groups != groupsOfEntity.end())
          for (const auto& g : groups->second) groupCells[g].push_back(static_cast<int>(cells.size()));
        cells.push_back(std::move(c));
      }
    }
  }

  const auto [nodeTags, coords] = getNodes();
  std::unordered_map<std::size_t, std::size_t> position;
  for (std::size_t i = 0; i < nodeTags.size(); ++i) position[nodeTags[i]] = i;
  std::set<std::size_t> used;
  for (const auto& c : cells)
    for (auto n : c.nodes) {
      if (!position.count(n))
        throw Error(path + ": element " + std::to_string(c.tag) + " refers to node " + std::to_string(n) +
                    " that is not defined");
      used.insert(n);
    }

  Mesh mesh;
  bool flat = true;
  std::unordered_map<std::size_t, int> index;
  for (auto tag : used) {  // ascending tags
    const double* x = &coords[3 * position[tag]];
    if (x[2] != 0.0) flat = false;
    index[tag] = mesh.addNode({x[0], x[1], x[2]}, "N" + std::to_string(tag));
  }
  mesh.setSpaceDimension(flat ? 2 : 3);
  std::vector<int> conn;
  for (const auto& c : cells) {
    conn.clear();
    for (auto n : c.nodes) conn.push_back(index[n]);
    mesh.addCell(c.type, conn, "M" + std::to_string(c.tag));
  }
  for (const auto& g : groupOrder) {
    auto& members = groupCells[g];
    mesh.addCellGroup(g, members);
  }
  for (const auto& g : groupOrder) mesh.addNodeGroup(g, mesh.nodesOfCells(mesh.cellGroup(g)));
  return mesh;
}

}  // namespace

std::string gmshScriptRisk(const std::string& path) {
  if (hasExtension(path, ".geo")) return "a gmsh script (.geo), whose commands gmsh runs (SystemCall included)";
  if (!hasExtension(path, ".msh"))
    return "not a .msh file (gmsh chooses by the extension how to open a file: a .geo is a script, a .py or .exe "
           "a program; a mesh file handed to it must end in .msh)";
  std::error_code ec;
  if (std::filesystem::exists(path + ".opt", ec))
    return "next to an option file, " + path + ".opt, which gmsh would run as a script";
  return "";
}

Mesh readGmshMesh(const std::string& path, const GmshReadOptions& options) {
  if (!std::ifstream(path)) throw Error("cannot open the gmsh file '" + path + "'");
  if (!options.scripts) {
    const std::string risk = gmshScriptRisk(path);
    if (!risk.empty()) throw Error(path + " is " + risk + ": it is not opened with gmsh");
  }
  const bool script = hasExtension(path, ".geo");
  if (!script) checkMshFile(path);
  // gmsh's own message is kept; for a mesh file, say what aster-lite expected.
  const std::string expected = script ? std::string() : std::string(" (expected ") + kMshExpected + ")";
  GmshSession session;
  try {
    for (const auto& [name, value] : options.numbers) {
      double v = value;
      call(gmshLibrary().OnelabSetNumber, name.c_str(), &v, std::size_t{1});
    }
    call(gmshLibrary().Open, path.c_str());
    checkGmsh(path, expected);
    if (script) {
      call(gmshLibrary().ModelMeshGenerate, call(gmshLibrary().ModelGetDimension));
      checkGmsh(path + " (meshing)");
    }
    Mesh mesh = readCurrentModel(path);
    if (mesh.cellCount() == 0) throw Error(path + ": the gmsh file holds no mesh cell");
    return mesh;
  } catch (const Error&) {
    throw;
  } catch (const std::exception& e) {
    throw Error(path + ": gmsh error: " + e.what() + expected);
  } catch (...) {
    const std::string last = lastError();
    throw Error(path + ": gmsh error: " + (last.empty() ? std::string("unknown") : last) + expected);
  }
}

namespace {

// Builds the gmsh model of a mesh: one discrete entity per (dimension, set of
// groups) so that overlapping groups stay exact; returns the model name.
std::string buildModel(const Mesh& mesh) {
  const std::string model = "aster";
  call(gmshLibrary().ModelAdd, model.c_str());
  const auto groupNames = mesh.cellGroupNames();
  const std::vector<std::vector<int>> groupsOfCell = groupsOfEachCell(mesh);
  std::map<std::pair<int, std::vector<int>>, int> entityOf;
  std::vector<std::pair<int, int>> entityOrder;  // (dim, tag)
  std::map<int, std::vector<int>> cellsOfEntity;
  for (int c = 0; c < mesh.cellCount(); ++c) {
    auto key = groupsOfCell[c];
    std::sort(key.begin(), key.end());
    const int dim = topologicalDimension(mesh.cellType(c));
    auto it = entityOf.find({dim, key});
    if (it == entityOf.end()) {
      // Tags unique across dimensions: gmsh's MSH 2.2 writer duplicates elements otherwise.
      const int tag = static_cast<int>(entityOrder.size()) + 1;
      call(gmshLibrary().ModelAddDiscreteEntity, dim, tag, nullptr, std::size_t{0});
      it = entityOf.emplace(std::make_pair(dim, key), tag).first;
      entityOrder.emplace_back(dim, tag);
    }
    cellsOfEntity[it->second].push_back(c);
  }
  // All nodes on one entity (gmsh only needs them classified somewhere).
  int nodeDim = 0, nodeEntity = 0;
  if (entityOrder.empty()) {
    nodeEntity = call(gmshLibrary().ModelAddDiscreteEntity, 0, -1, nullptr, std::size_t{0});
  } else {
    for (const auto& [d, t] : entityOrder)
      if (d >= nodeDim) nodeDim = d, nodeEntity = t;
    // Keep the first entity of the highest dimension.
    for (const auto& [d, t] : entityOrder)
      if (d == nodeDim) {
        nodeEntity = t;
        break;
      }
  }
  std::vector<std::size_t> nodeTags(mesh.nodeCount());
  for (int i = 0; i < mesh.nodeCount(); ++i) nodeTags[i] = static_cast<std::size_t>(i + 1);
  const auto& coords = mesh.coordinates();
  call(gmshLibrary().ModelMeshAddNodes, nodeDim, nodeEntity, input(nodeTags), nodeTags.size(), input(coords),
       coords.size(), nullptr, std::size_t{0});

  for (const auto& [dim, tag] : entityOrder) {
    std::map<int, std::pair<std::vector<std::size_t>, std::vector<std::size_t>>> byType;
    for (int c : cellsOfEntity[tag]) {
      const CellType t = mesh.cellType(c);
      auto& [tags, nodes] = byType[gmshElementType(t)];
      tags.push_back(static_cast<std::size_t>(c + 1));
      const auto n = mesh.cellNodes(c);
      const auto foreign = fromAsterOrder(NodeConvention::Gmsh, t, std::vector<int>(n.begin(), n.end()));
      for (int k : foreign) nodes.push_back(static_cast<std::size_t>(k + 1));
    }
    for (const auto& [type, data] : byType)
      call(gmshLibrary().ModelMeshAddElementsByType, tag, type, input(data.first), data.first.size(),
           input(data.second), data.second.size());
  }
  // Physical groups: one per group and dimension, plus the reserved one per
  // dimension for the cells in no group (see the header).
  auto addPhysical = [](const std::map<int, std::vector<int>>& entitiesByDim, const std::string& name) {
    for (const auto& [dim, tags] : entitiesByDim) {
      const int phys = call(gmshLibrary().ModelAddPhysicalGroup, dim, input(tags), tags.size(), -1);
      call(gmshLibrary().ModelSetPhysicalName, dim, phys, name.c_str());
    }
  };
  for (std::size_t g = 0; g < groupNames.size(); ++g) {
    std::map<int, std::vector<int>> entitiesByDim;
    for (const auto& [key, tag] : entityOf)
      if (std::find(key.second.begin(), key.second.end(), static_cast<int>(g)) != key.second.end())
        entitiesByDim[key.first].push_back(tag);
    addPhysical(entitiesByDim, groupNames[g]);
  }
  std::map<int, std::vector<int>> ungrouped;
  for (const auto& [key, tag] : entityOf)
    if (key.second.empty()) ungrouped[key.first].push_back(tag);
  addPhysical(ungrouped, kGmshUngroupedName);
  return model;
}

void setWriteOptions(const GmshWriteOptions& options) {
  if (options.version != 2.2 && options.version != 4.1)
    throw Error("gmsh writer: MSH version must be 2.2 or 4.1, got " + std::to_string(options.version));
  call(gmshLibrary().OptionSetNumber, "Mesh.MshFileVersion", options.version);
  call(gmshLibrary().OptionSetNumber, "Mesh.Binary", options.binary ? 1.0 : 0.0);
  call(gmshLibrary().OptionSetNumber, "Mesh.SaveAll", 0.0);
}

void writeModel(const std::string& path) {
  call(gmshLibrary().Write, path.c_str());
  checkGmsh("writing " + path);
}

}  // namespace

void writeGmshMesh(const Mesh& mesh, const std::string& path, const GmshWriteOptions& options) {
  writeGmshResults(mesh, path, {}, options);
}

void writeGmshResults(const Mesh& mesh, const std::string& path, const std::vector<FieldInstant>& instants,
                      const GmshWriteOptions& options) {
  // Check the fields before touching any file.
  for (const auto& inst : instants)
    for (const auto& f : inst.fields)
      if (f.components.empty() || f.values.size() != f.components.size() * static_cast<std::size_t>(mesh.nodeCount()))
        throw Error("gmsh writer: field '" + f.name + "' has " + std::to_string(f.values.size()) +
                    " values, expected " + std::to_string(mesh.nodeCount()) + " nodes x " +
                    std::to_string(f.components.size()) + " components");
  for (const auto& inst : instants)
    for (const auto& f : inst.cellFields) {
      checkCellValues(mesh, f, "gmsh writer");
      if (options.version != 2.2 || options.binary)
        throw Error("gmsh writer: the cell field '" + f.name + "' is written in MSH 2.2 ASCII only");
    }
  if (options.version == 2.2 && !options.binary) return writeMsh2(mesh, path, instants);  // no libgmsh
  GmshSession session;
  try {
    setWriteOptions(options);
    // Every cell is in a physical group (maybe the reserved one): no SaveAll,
    // which would write MSH 2.2 elements without their physical groups.
    const std::string model = buildModel(mesh);
    writeModel(path);

    std::vector<std::size_t> tags(mesh.nodeCount());
    for (int i = 0; i < mesh.nodeCount(); ++i) tags[i] = static_cast<std::size_t>(i + 1);
    std::map<std::string, int> views;
    int step = 0;
    for (const auto& inst : instants) {
      for (const auto& f : inst.fields) {
        const int nc = static_cast<int>(f.components.size());
        auto addView = [&](const std::string& name, int width, auto value) {
          auto it = views.find(name);
          if (it == views.end()) it = views.emplace(name, call(gmshLibrary().ViewAdd, name.c_str(), -1)).first;
          std::vector<double> data(static_cast<std::size_t>(mesh.nodeCount()) * width, 0.0);
          for (int i = 0; i < mesh.nodeCount(); ++i)
            for (int k = 0; k < width; ++k) data[static_cast<std::size_t>(i) * width + k] = value(i, k);
          call(gmshLibrary().ViewAddHomogeneousModelData, it->second, step, model.c_str(), "NodeData", input(tags),
               tags.size(), data.data(), data.size(), inst.time, width, 0);
        };
        if (nc == 1 || nc == 3 || nc == 9) {
          addView(f.name, nc, [&](int i, int k) { return f.values[static_cast<std::size_t>(i) * nc + k]; });
        } else if (nc == 2) {
          addView(f.name, 3, [&](int i, int k) { return k < 2 ? f.values[static_cast<std::size_t>(i) * 2 + k] : 0.0; });
        } else {
          for (int c = 0; c < nc; ++c)
            addView(f.name + "_" + f.components[c], 1,
                    [&](int i, int) { return f.values[static_cast<std::size_t>(i) * nc + c]; });
        }
      }
      ++step;
    }
    for (const auto& [name, tag] : views) {
      call(gmshLibrary().ViewWrite, tag, path.c_str(), 1);
      checkGmsh("writing view " + name + " to " + path);
    }
  } catch (const Error&) {
    throw;
  } catch (const std::exception& e) {
    throw Error("writing " + path + ": gmsh error: " + e.what());
  } catch (...) {
    const std::string last = lastError();
    throw Error("writing " + path + ": gmsh error: " + (last.empty() ? std::string("unknown") : last));
  }
}

}  // namespace aster::mesh
