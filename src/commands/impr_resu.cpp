// IMPR_RESU: writes meshes, nodal fields (cham_no_sdaster) and results
// (evol_noli, evol_elas: every selected instant's nodal and cell fields) as
// readable text (RESULTAT), MED (a result's fields under code_aster's names,
// RESU____SIEF_ELGA), GMSH (.msh 2.2 ASCII) or VTK (.vtu, or a .pvd collection
// for a result); what each format makes of a cell field: docs/manual.md.
// The file is the one bound to UNITE (DEFI_FICHIER, -u N=path), else
// <output>/<study>.resu.txt|.med|.msh|.vtu|.pvd. Files are written in a private
// folder beside the target and renamed into place: an interrupted run or a full
// disk never leaves a half-written file. A second write of the run to one file
// adds to it (text, MED) or goes to <name>-2.<ext> (GMSH, VTK); a file the study
// read is never written over.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <memory>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "commands/field_concepts.hpp"
#include "commands/field_output.hpp"
#include "commands/function_concepts.hpp"
#include "commands/instant_selection.hpp"
#include "commands/mesh_concept.hpp"
#include "commands/result_concepts.hpp"
#include "commands/selection.hpp"
#include "core/atomic_write.hpp"
#include "core/error.hpp"
#include "core/messages.hpp"
#include "core/number_format.hpp"
#include "lang/operators.hpp"
#include "mesh/io/aster_format.hpp"
#include "mesh/io/gmsh_format.hpp"
#include "mesh/io/med_format.hpp"
#include "mesh/io/vtk_format.hpp"

namespace aster::lang {
namespace {

namespace fs = std::filesystem;

// ------------------------------------------------------------ what to write

// One RESU occurrence, resolved.
struct Item {
  ConceptPtr owner;                            // the mesh, field or result named
  std::shared_ptr<mesh::Mesh> mesh;            // its mesh
  bool meshOnly = false;                       // MAILLAGE alone
  bool isResult = false;
  std::vector<mesh::FieldInstant> instants;    // nodal fields (CHAM_GD: one instant)
  std::vector<std::vector<const CellField*>> cellFields;  // per instant (results, RESULTAT format)
  std::vector<const ResultInstant*> resultInstants;       // per instant (results): nodal fields' supports
  std::vector<int> nodes;                      // RESULTAT format: the nodes to print
  std::vector<int> cells;                      // RESULTAT format: the cells of Gauss fields (empty: all)
};

mesh::NodalField keepComponents(const mesh::NodalField& f, const std::vector<std::string>& wanted, int nodeCount,
                                const std::string& fieldName) {
  if (wanted.empty()) return f;
  std::vector<int> index;
  for (const auto& w : wanted) {
    auto it = std::find(f.components.begin(), f.components.end(), w);
    if (it == f.components.end()) {
      std::string list;
      for (const auto& c : f.components) list += (list.empty() ? "" : ", ") + c;
      throw Error("NOM_CMP: the field " + fieldName + " has no component " + w + " (components: " + list + ")");
    }
    index.push_back(static_cast<int>(it - f.components.begin()));
  }
  mesh::NodalField out;
  out.name = f.name;
  const std::size_t nc = f.components.size();
  for (int i : index) out.components.push_back(f.components[i]);
  out.values.reserve(static_cast<std::size_t>(nodeCount) * index.size());
  for (int n = 0; n < nodeCount; ++n)
    for (int i : index) out.values.push_back(f.values[static_cast<std::size_t>(n) * nc + i]);
  return out;
}

// A cell field for the writers, with the components NOM_CMP names (all when empty).
mesh::CellValues cellComponents(const mesh::Mesh& mesh, const CellField& f, const std::vector<std::string>& wanted) {
  mesh::CellValues v = cellValuesOf(mesh, f);
  if (wanted.empty()) return v;
  std::vector<int> index;
  for (const auto& w : wanted) index.push_back(componentIndex(f.components, w, f.name));
  const std::size_t nc = f.components.size();
  std::vector<double> values;
  std::vector<int> offsets{0};
  for (std::size_t k = 0; k < f.cells.size(); ++k) {
    for (int p = 0; p < pointsOf(f, k); ++p)
      for (int i : index) values.push_back(f.values[static_cast<std::size_t>(f.offsets[k]) + p * nc + i]);
    offsets.push_back(static_cast<int>(values.size()));
  }
  v.components = wanted;
  v.values = std::move(values);
  v.offsets = std::move(offsets);
  return v;
}

Item resolve(const Keywords& occ, bool textFormat, bool vtk) {
  Item item;
  const std::vector<std::string> cmps = occ.texts("NOM_CMP");
  std::shared_ptr<mesh::Mesh> given;
  if (occ.has("MAILLAGE")) {
    item.owner = occ.conceptPtr("MAILLAGE");
    given = std::static_pointer_cast<MeshConcept>(item.owner)->mesh;
    item.mesh = given;
  }
  if (occ.has("CHAM_GD") && occ.concept<CellFieldConcept>("CHAM_GD")) {
    auto g = occ.concept<CellFieldConcept>("CHAM_GD");  // a field on cells, known by its concept's name
    item.owner = g;
    item.mesh = g->mesh;
    mesh::FieldInstant fi;
    if (!textFormat) fi.cellFields.push_back(cellComponents(*g->mesh, g->field, cmps));
    item.instants.push_back(std::move(fi));
    item.cellFields.push_back({&g->field});
  } else if (occ.has("CHAM_GD")) {
    auto f = occ.concept<NodalFieldConcept>("CHAM_GD");
    if (!f) throw Error("CHAM_GD: only nodal fields (cham_no_sdaster) and fields on cells (cham_elem) can be written");
    item.owner = f;
    item.mesh = f->mesh;
    mesh::FieldInstant fi;
    fi.fields.push_back(keepComponents(f->field, cmps, f->mesh->nodeCount(), f->field.name));
    item.instants.push_back(std::move(fi));
    item.cellFields.emplace_back();
    item.nodes = f->support;
  } else if (occ.has("RESULTAT")) {
    auto r = occ.concept<ResultConcept>("RESULTAT");
    item.owner = r;
    item.isResult = true;
    item.mesh = r->model->meshPtr();
    const std::vector<std::string> names = occ.texts("NOM_CHAM");
    for (const ResultInstant* ri : selectedInstants(*r, occ)) {
      mesh::FieldInstant fi;
      fi.index = ri->index;
      fi.time = ri->time;
      std::vector<const CellField*> gauss;
      if (names.empty()) {
        for (const auto& f : ri->nodal) fi.fields.push_back(keepComponents(f, cmps, item.mesh->nodeCount(), f.name));
        for (const auto& g : ri->cells) gauss.push_back(&g);
      } else {
        for (const auto& name : names) {
          const CellField* g = nullptr;
          for (const auto& x : ri->cells)
            if (x.name == name) g = &x;
          if (g) {
            gauss.push_back(g);
            continue;
          }
          const auto& f = ResultConcept::nodalField(*ri, name);
          fi.fields.push_back(keepComponents(f, cmps, item.mesh->nodeCount(), f.name));
        }
      }
      if (!textFormat)
        for (const CellField* g : gauss) fi.cellFields.push_back(cellComponents(*item.mesh, *g, cmps));
      if (vtk) {
        for (auto& f : fi.fields) nameInternalVariables(f.name, f.components, r->variableNames);
        for (auto& f : fi.cellFields) nameInternalVariables(f.name, f.components, r->variableNames);
      }
      item.instants.push_back(std::move(fi));
      item.cellFields.push_back(std::move(gauss));
      item.resultInstants.push_back(ri);
    }
  } else {
    item.meshOnly = true;
  }
  if (given && given != item.mesh)
    throw Error("MAILLAGE: the mesh given is not the mesh of the " +
                std::string(occ.has("RESULTAT") ? "result (RESULTAT)" : "field (CHAM_GD)"));
  // Restrictions (text format): the nodes and cells of TOUT / GROUP_MA / MAILLE / GROUP_NO / NOEUD.
  if (occ.has("GROUP_MA") || occ.has("GROUP_NO") || occ.has("MAILLE") || occ.has("NOEUD")) {
    item.nodes = selectNodes(*item.mesh, occ);
    item.cells = selectCells(*item.mesh, occ);
  }
  return item;
}

// ------------------------------------------------------------ RESULTAT (text)

std::string number(double v) { return format::scientificAligned(v, 8); }

void printNodalField(std::ostream& out, const mesh::Mesh& m, const mesh::NodalField& f, std::vector<int> nodes,
                     bool vmax, bool vmin) {
  if (nodes.empty())
    for (int n = 0; n < m.nodeCount(); ++n) nodes.push_back(n);
  const std::size_t nc = f.components.size();
  std::size_t width = 8;
  for (int n : nodes) width = std::max(width, m.nodeName(n).size());
  out << " " << std::string("NOEUD") << std::string(width - 5 + 1, ' ');
  for (const auto& c : f.components) {
    std::string h = " " + c;  // above the sign column of the numbers
    h.resize(std::max<std::size_t>(h.size(), 15), ' ');
    out << " " << h << "  ";
  }
  out << "\n";
  for (int n : nodes) {
    std::string name = m.nodeName(n);
    name.resize(width, ' ');
    out << " " << name << " ";
    for (std::size_t c = 0; c < nc; ++c) out << " " << number(f.values[static_cast<std::size_t>(n) * nc + c]) << "  ";
    out << "\n";
  }
  for (int which = 0; which < 2; ++which) {
    if (!(which == 0 ? vmax : vmin) || nodes.empty()) continue;
    out << " " << (which == 0 ? "VALE_MAX" : "VALE_MIN") << "\n";
    for (std::size_t c = 0; c < nc; ++c) {
      int best = nodes.front();
      for (int n : nodes) {
        const double v = f.values[static_cast<std::size_t>(n) * nc + c];
        const double b = f.values[static_cast<std::size_t>(best) * nc + c];
        if (which == 0 ? v > b : v < b) best = n;
      }
      out << "   " << f.components[c] << " " << number(f.values[static_cast<std::size_t>(best) * nc + c])
          << " at node " << m.nodeName(best) << "\n";
    }
  }
}

void printGaussField(std::ostream& out, const mesh::Mesh& m, const CellField& g, const std::vector<int>& cells) {
  std::set<int> keep(cells.begin(), cells.end());
  const std::size_t nc = g.components.size();
  const bool atNodes = g.location == CellLocation::Nodes;  // ELNO: the cell's nodes by name
  out << (atNodes ? " MAILLE   NOEUD    " : " MAILLE   POINT    ");
  for (const auto& c : g.components) {
    std::string h = " " + c;
    h.resize(std::max<std::size_t>(h.size(), 15), ' ');
    out << " " << h << "  ";
  }
  out << "\n";
  for (std::size_t k = 0; k < g.cells.size(); ++k) {
    if (!keep.empty() && !keep.count(g.cells[k])) continue;
    const int begin = g.offsets[k], end = g.offsets[k + 1];
    const int points = nc ? static_cast<int>((end - begin) / static_cast<int>(nc)) : 0;
    for (int p = 0; p < points; ++p) {
      std::string name = m.cellName(g.cells[k]);
      name.resize(std::max<std::size_t>(name.size(), 8), ' ');
      std::string point = atNodes ? m.nodeName(m.cellNodes(g.cells[k])[p]) : std::to_string(p + 1);
      point.resize(std::max<std::size_t>(point.size(), 5), ' ');
      out << " " << name << " " << point << "    ";
      for (std::size_t c = 0; c < nc; ++c) out << " " << number(g.values[begin + p * nc + c]) << "  ";
      out << "\n";
    }
  }
}

std::string textOf(const std::vector<Item>& items, const std::vector<Keywords>& occs, Session& session) {
  std::ostringstream out;
  for (std::size_t k = 0; k < items.size(); ++k) {
    const Item& it = items[k];
    const bool vmax = occs[k].has("VALE_MAX"), vmin = occs[k].has("VALE_MIN");
    const std::string name = session.nameOf(*it.owner);
    if (it.meshOnly) {
      out << "% MAILLAGE " << name << "\n";
      mesh::writeAsterMesh(*it.mesh, out);
      continue;
    }
    for (std::size_t i = 0; i < it.instants.size(); ++i) {
      const auto& fi = it.instants[i];
      for (const auto& f : fi.fields) {
        // A field computed on part of the model (CALC_CHAMP's GROUP_MA) is printed where it is defined.
        std::vector<int> nodes = it.nodes;
        if (it.isResult) {
          const auto& supports = it.resultInstants[i]->nodalSupport;
          if (auto s = supports.find(f.name); s != supports.end()) {
            if (nodes.empty()) {
              nodes = s->second;
            } else {
              nodes.erase(std::remove_if(nodes.begin(), nodes.end(),
                                         [&](int n) { return !std::binary_search(s->second.begin(), s->second.end(), n); }),
                          nodes.end());
            }
            if (nodes.empty()) continue;
          }
        }
        if (it.isResult)
          out << "\n CHAMP AUX NOEUDS " << f.name << " DU RESULTAT " << name << "  NUME_ORDRE " << fi.index
              << "  INST " << number(fi.time) << "\n";
        else
          out << "\n CHAMP AUX NOEUDS " << name << "\n";
        printNodalField(out, *it.mesh, f, nodes, vmax, vmin);
      }
      for (const CellField* g : it.cellFields[i]) {
        const char* kind = g->location == CellLocation::Nodes ? "PAR ELEMENT AUX NOEUDS" : "AUX POINTS DE GAUSS";
        if (it.isResult)
          out << "\n CHAMP " << kind << " " << g->name << " DU RESULTAT " << name << "  NUME_ORDRE " << fi.index
              << "  INST " << number(fi.time) << "\n";
        else
          out << "\n CHAMP " << kind << " " << name << "\n";
        printGaussField(out, *it.mesh, *g, it.cells);
      }
    }
  }
  return out.str();
}

// ------------------------------------------------------------ binary formats

// Every occurrence on one mesh; fields merged per instant (NUME_ORDRE, INST).
struct Merged {
  std::shared_ptr<mesh::Mesh> mesh;
  ConceptPtr meshConcept;
  std::vector<mesh::FieldInstant> instants;
  bool hasResult = false;
};

// code_aster's name of a result's field in a MED file: the result's name padded
// to 8 characters with '_', then the field's (RESU____SIEF_ELGA).
std::string medFieldName(const std::string& result, const std::string& field) {
  std::string name = result;
  if (name.size() < 8) name.resize(8, '_');
  return name + field;
}

Merged merge(const std::vector<Item>& items, const std::string& format, Session& session) {
  Merged m;
  for (const Item& it : items) {
    if (!m.mesh) m.mesh = it.mesh;
    if (m.mesh != it.mesh)
      throw Error("RESU: FORMAT='" + format + "' writes one mesh per file, the occurrences of RESU are on different "
                  "meshes (call IMPR_RESU once per mesh, with different units)");
    if (it.meshOnly || (!m.meshConcept && std::dynamic_pointer_cast<MeshConcept>(it.owner)))
      m.meshConcept = it.owner;
    m.hasResult = m.hasResult || it.isResult;
    for (const auto& fi : it.instants) {
      mesh::FieldInstant* into = nullptr;
      for (auto& x : m.instants)
        if (x.index == fi.index && x.time == fi.time) into = &x;
      if (!into) {
        m.instants.push_back({fi.index, fi.time, {}, {}});
        into = &m.instants.back();
      }
      const std::string owner = session.nameOf(*it.owner);
      // A CHAM_GD is known by its concept's name; in MED a result's field by code_aster's name.
      auto nameOf = [&](const std::string& field) {
        std::string name = !it.isResult ? owner : format == "MED" ? medFieldName(owner, field) : field;
        for (const auto& other : into->fields)
          if (other.name == name) return owner + "_" + name;
        for (const auto& other : into->cellFields)
          if (other.name == name) return owner + "_" + name;
        return name;
      };
      for (auto f : fi.fields) {
        f.name = nameOf(f.name);
        into->fields.push_back(std::move(f));
      }
      for (auto f : fi.cellFields) {
        f.name = nameOf(f.name);
        into->cellFields.push_back(std::move(f));
      }
    }
  }
  std::sort(m.instants.begin(), m.instants.end(),
            [](const mesh::FieldInstant& a, const mesh::FieldInstant& b) { return a.time < b.time; });
  return m;
}

std::string medMeshName(const Merged& m, Session& session) {
  if (!m.meshConcept) return "MAIL";
  const std::string name = session.nameOf(*m.meshConcept);
  return name.find('@') == std::string::npos && !name.empty() ? name : "MAIL";
}

// ------------------------------------------------------------ files of the run

// What this run put in a file of IMPR_RESU, so that a later IMPR_RESU to the
// same unit adds to it as code_aster does: a MED file takes more meshes and
// fields, a text file more listings. Keyed by the file; reset when a run writes
// the file afresh.
struct Written {
  std::string format;
  std::vector<std::pair<std::weak_ptr<mesh::Mesh>, std::string>> meshes;  // MED: mesh and its name in the file
  std::set<std::string> fields;                                    // MED field names
};
std::map<std::string, Written>& writtenFiles() {
  static std::map<std::string, Written> files;
  return files;
}
std::string keyOf(const fs::path& p) { return fs::absolute(p).lexically_normal().string(); }

// `name`, else name_2, name_3...: the first not in `used`.
std::string freeName(const std::string& name, const std::set<std::string>& used) {
  if (!used.count(name)) return name;
  for (int n = 2;; ++n)
    if (!used.count(name + "_" + std::to_string(n))) return name + "_" + std::to_string(n);
}

// Removes the .vtu of a collection that an earlier run wrote beyond this one's instants.
void removeStaleInstants(Session& session, const fs::path& pvd) {
  const std::string stem = pvd.stem().string();
  session.files.removeStale(pvd.parent_path(),
                            [&](const std::string& f) { return isNumberedFile(f, stem, ".vtu"); });
}

// ------------------------------------------------------------ operator

ConceptPtr imprResu(const Keywords& k, Session& session, ConceptPtr) {
  const std::string format = k.text("FORMAT");
  const int unit = static_cast<int>(k.integer("UNITE"));
  const bool text = format == "RESULTAT";
  const auto& occs = k.factor("RESU");
  std::vector<Item> items;
  for (std::size_t i = 0; i < occs.size(); ++i) {
    try {
      items.push_back(resolve(occs[i], text, format == "VTK"));
    } catch (const Error& e) {
      const std::string what = e.what();
      if (what.rfind(occs[i].path + "/", 0) == 0) throw;  // already names the occurrence
      throw Error((occs.size() > 1 ? "RESU[" + std::to_string(i + 1) + "]: " : std::string("RESU: ")) + what);
    }
    if (!text && (occs[i].has("GROUP_MA") || occs[i].has("GROUP_NO") || occs[i].has("MAILLE") || occs[i].has("NOEUD")))
      Messages::alarm("IMPR_RESU", "GROUP_MA / MAILLE / GROUP_NO / NOEUD restrict FORMAT='RESULTAT' only; FORMAT='" +
                                       format + "' writes the whole mesh");
  }

  Merged merged;
  if (!text) merged = merge(items, format, session);
  std::string ext = text ? ".resu.txt" : format == "MED" ? ".med" : format == "GMSH" ? ".msh"
                                        : merged.hasResult ? ".pvd" : ".vtu";

  // The file: the one bound to the unit, else <output>/<study><ext>. Never an
  // input of the study; a second write of the run adds to a text or MED file
  // (code_aster's units 8 and 80) and goes to a file of its own in GMSH and VTK
  // (<name>-2.msh), which cannot hold two writes.
  const std::string unitText = "UNITE=" + std::to_string(unit);
  const auto bound = session.units.find(unit);
  fs::path path = bound != session.units.end() ? bound->second
                                               : session.outputFile(session.studyPath.stem().string() + ext);
  const fs::path folder = path.parent_path();
  const std::string stem = fs::path(path).replace_extension("").filename().string();
  const std::string pathExt = path.extension().string();
  std::string note;
  if (bound != session.units.end()) session.checkUnitWritable(unit, path);
  if (const std::string how = session.inputOf(path); !how.empty()) {
    note = path.filename().string() + " is an input of the study, never written over";
    for (int n = 2; !session.inputOf(path).empty(); ++n) path = folder / (stem + "-" + std::to_string(n) + pathExt);
  }
  const bool canAdd = text || format == "MED";
  const bool add = canAdd && session.files.written(path);
  if (add) {
    const auto it = writtenFiles().find(keyOf(path));
    const std::string before = it == writtenFiles().end() ? std::string("another command") : it->second.format;
    if (before != format && !(text && it == writtenFiles().end()))
      throw Error(unitText + ": " + path.string() + " holds " +
                  (it == writtenFiles().end() ? "what another command wrote" : "FORMAT='" + before + "'") +
                  " from earlier in this run; write FORMAT='" + format + "' to another unit");
  }
  if (!canAdd && session.files.written(path)) {
    note = path.filename().string() + " holds an earlier IMPR_RESU of this run";
    path = session.files.fresh(folder, stem, pathExt, [&](const std::string& name) {
      if (pathExt != ".pvd") return false;
      bool taken = false;
      std::error_code ec;
      for (fs::directory_iterator d(folder, ec), end; !ec && d != end && !taken; d.increment(ec))
        taken = isNumberedFile(d->path().filename().string(), name, ".vtu") && session.files.written(d->path());
      return taken;
    });
  }

  Written& record = writtenFiles()[keyOf(path)];
  if (!add) record = Written{format, {}, {}};
  std::string meshName;
  bool meshPresent = false;
  std::vector<mesh::FieldInstant> instants = merged.instants;
  if (format == "MED") {
    for (const auto& [m, name] : record.meshes)
      if (!m.owner_before(merged.mesh) && !merged.mesh.owner_before(m)) {  // the same mesh object
        meshName = name;
        meshPresent = true;
      }
    if (!meshPresent) {
      std::set<std::string> used;
      for (const auto& [m, name] : record.meshes) used.insert(name);
      meshName = freeName(medMeshName(merged, session), used);
    }
    // Field names must be new in the file: else a number (RESU____DEPL_2).
    std::map<std::string, std::string> renamed;
    std::set<std::string> used = record.fields;
    auto rename = [&](const std::string& name) {
      if (!renamed.count(name)) {
        renamed[name] = freeName(name, used);
        used.insert(renamed[name]);
      }
    };
    for (const auto& fi : instants) {
      for (const auto& f : fi.fields) rename(f.name);
      for (const auto& f : fi.cellFields) rename(f.name);
    }
    for (auto& fi : instants) {
      for (auto& f : fi.fields) f.name = renamed[f.name];
      for (auto& f : fi.cellFields) f.name = renamed[f.name];
    }
  }

  try {
    // Text: the listings of a run's IMPR_RESU to one file follow each other (code_aster's unit 8).
    if (text) appendAtomically(path, textOf(items, occs, session), add, &session.files);
    else session.writeFile(path, [&](const fs::path& tmp) {
      const std::string p = tmp.string();
      if (format == "MED") {
        if (add) {
          std::error_code ec;
          fs::copy_file(path, tmp, ec);
          if (ec) throw Error("cannot write " + p + ": " + ec.message());
          mesh::addMedResults(*merged.mesh, p, instants, meshName, meshPresent);
        } else if (instants.empty()) {
          mesh::writeMedMesh(*merged.mesh, p, meshName);
        } else {
          mesh::writeMedResults(*merged.mesh, p, instants, meshName);
        }
      } else if (format == "GMSH") {
        mesh::GmshWriteOptions options;
        options.version = 2.2;  // the catalogue's promise: version 2 ASCII
        if (instants.empty())
          mesh::writeGmshMesh(*merged.mesh, p, options);
        else
          mesh::writeGmshResults(*merged.mesh, p, instants, options);
      } else if (merged.hasResult) {
        mesh::writePvd(*merged.mesh, p, instants);
      } else {
        std::vector<mesh::NodalField> fields;
        std::vector<mesh::CellValues> cellFields;
        for (const auto& fi : instants) {
          for (const auto& f : fi.fields) fields.push_back(f);
          for (const auto& f : fi.cellFields) cellFields.push_back(f);
        }
        mesh::writeVtu(*merged.mesh, p, fields, cellFields);
      }
    });
  } catch (...) {
    if (!add) writtenFiles().erase(keyOf(path));
    throw;
  }
  if (format == "MED") {
    if (!meshPresent) record.meshes.emplace_back(merged.mesh, meshName);
    for (const auto& fi : instants) {
      for (const auto& f : fi.fields) record.fields.insert(f.name);
      for (const auto& f : fi.cellFields) record.fields.insert(f.name);
    }
  }
  if (format == "VTK" && merged.hasResult) removeStaleInstants(session, path);

  if (k.integer("INFO") >= 1) {
    std::string how = add ? " (added to the file of an earlier IMPR_RESU of this run" : "";
    if (add && format == "MED") {
      how += ": mesh " + meshName + (meshPresent ? " (already there)" : "");
      std::set<std::string> names;
      for (const auto& fi : instants) {
        for (const auto& f : fi.fields) names.insert(f.name);
        for (const auto& f : fi.cellFields) names.insert(f.name);
      }
      if (!names.empty()) {
        how += ", fields";
        for (const auto& n : names) how += " " + n;
      }
    }
    if (add) how += ")";
    if (!note.empty()) how += " (" + note + ")";
    Messages::info("IMPR_RESU: FORMAT='" + format + "' (" + unitText + ") written to " + path.string() + how);
  }
  return nullptr;
}

RegisterOperator reg("IMPR_RESU", imprResu);

}  // namespace
}  // namespace aster::lang
