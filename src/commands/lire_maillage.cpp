// LIRE_MAILLAGE: reads a mesh from the file bound to UNITE (default unit 20:
// the study's name with the format's extension).
// gmsh runs the commands of scripts (.geo, an .opt beside the mesh): a study in
// the Lua sandbox reads .msh files only (mesh::gmshScriptRisk).
#include <cctype>
#include <filesystem>

#include "commands/mesh_concept.hpp"
#include "core/error.hpp"
#include "core/messages.hpp"
#include "lang/operators.hpp"
#include "mesh/io/aster_format.hpp"
#include "mesh/io/gmsh_format.hpp"
#include "mesh/io/pre_gmsh_format.hpp"
#include "mesh/mesh_check.hpp"
#if __has_include("mesh/io/med_format.hpp")
#include "mesh/io/med_format.hpp"
#define ASTER_HAS_MED 1
#endif

namespace aster::lang {
namespace {

ConceptPtr lireMaillage(const Keywords& k, Session& session, ConceptPtr) {
  const std::string format = k.text("FORMAT");
  const int unit = static_cast<int>(k.integer("UNITE"));
  const std::string ext = format == "ASTER" ? ".mail" : format == "GMSH" ? ".msh" : ".med";
  const auto path = session.unitPath(unit, ext);
  if (!std::filesystem::exists(path))
    throw Error("UNITE=" + std::to_string(unit) + ": the file " + path.string() +
                " does not exist (bind a file with DEFI_FICHIER{ACTION='ASSOCIER', UNITE=" + std::to_string(unit) +
                ", FICHIER='...'} or aster-lite -u " + std::to_string(unit) + "=PATH)");
  session.files.addInput(path, "read by LIRE_MAILLAGE at " + session.where);  // never written over
  auto m = std::make_shared<mesh::Mesh>();
  if (format == "ASTER") {
    std::vector<std::string> alarms;
    *m = mesh::readAsterMesh(path.string(), &alarms);
    for (const auto& a : alarms) Messages::alarm("LIRE_MAILLAGE", session.where + ": " + a);
  } else if (format == "GMSH" && mesh::isPreGmshOnlyFile(path.string())) {
    // MSH 1, 2.0, 2.1 (code_aster's test meshes): converted as code_aster's PRE_GMSH does.
    *m = mesh::readGmshAsPreGmsh(path.string());
  } else if (format == "GMSH") {
    mesh::GmshReadOptions options;
    options.scripts = session.unsafeLua;  // gmsh scripts run commands: not in the Lua sandbox
    const std::string risk = options.scripts ? std::string() : mesh::gmshScriptRisk(path.string());
    if (!risk.empty()) {
      std::string ext = path.extension().string();
      for (auto& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
      throw Error("UNITE=" + std::to_string(unit) + ": " + path.string() + " is " + risk +
                  "; a sandboxed study does not hand it to gmsh (aster-lite --unsafe-lua does" +
                  (ext == ".geo" ? "; or mesh it beforehand, gmsh -2 FILE.geo -o FILE.msh, and read the .msh)" : ")"));
    }
    *m = mesh::readGmshMesh(path.string(), options);
  } else {
#ifdef ASTER_HAS_MED
    *m = mesh::readMedMesh(path.string(), k.has("NOM_MED") ? k.text("NOM_MED") : "");
#else
    throw Error("FORMAT='MED': this build of aster-lite has no MED library (install libmedc-dev and rebuild)");
#endif
  }
  // Whatever the format: a NaN or an infinity would surface later as a wrong
  // or misleading message.
  try {
    mesh::checkFiniteCoordinates(*m);
  } catch (const Error& e) {
    throw Error(path.string() + ": " + e.what());
  }
  const Keywords& veri = k.factor("VERI_MAIL").front();
  if (veri.text("VERIF") == "OUI") {
    const auto defects = mesh::findDefects(*m, veri.real("APLAT"));
    for (const auto& a : defects.alarms) Messages::alarm("LIRE_MAILLAGE", session.where + ": " + path.string() + ": " + a);
    if (!defects.fatal.empty()) throw Error(path.string() + ": " + defects.fatal);
  }
  if (k.integer("INFO") >= 1) Messages::info(m->summary());
  return std::make_shared<MeshConcept>(m);
}

RegisterOperator reg("LIRE_MAILLAGE", lireMaillage);

}  // namespace
}  // namespace aster::lang
