// PRE_GMSH: converts the gmsh mesh of UNITE_GMSH (MSH 1 or MSH 2 ASCII) into
// an ASTER mesh written on UNITE_MAILLAGE, as code_aster does
// (mesh/io/pre_gmsh_format.hpp says how nodes, cells and groups are named).
// The file written: the one bound to the unit (never an input of the study),
// else a fresh <output>/<study>.mail, to which the unit is then bound so that
// LIRE_MAILLAGE{FORMAT='ASTER', UNITE=...} reads it.
#include <filesystem>
#include <fstream>

#include "core/error.hpp"
#include "core/messages.hpp"
#include "lang/operators.hpp"
#include "mesh/io/aster_format.hpp"
#include "mesh/io/pre_gmsh_format.hpp"

namespace aster::lang {
namespace {

namespace fs = std::filesystem;

ConceptPtr preGmsh(const Keywords& k, Session& session, ConceptPtr) {
  const int gmshUnit = static_cast<int>(k.integer("UNITE_GMSH"));
  const int meshUnit = static_cast<int>(k.integer("UNITE_MAILLAGE"));
  const std::string gmshText = "UNITE_GMSH=" + std::to_string(gmshUnit);
  const std::string meshText = "UNITE_MAILLAGE=" + std::to_string(meshUnit);
  if (gmshUnit == meshUnit)
    throw Error(meshText + ": the ASTER mesh would be written over the gmsh file it is made from; give another unit");
  const fs::path input = session.unitPath(gmshUnit, ".msh");
  if (!fs::exists(input))
    throw Error(gmshText + ": the file " + input.string() +
                " does not exist (bind a file with DEFI_FICHIER{ACTION='ASSOCIER', UNITE=" + std::to_string(gmshUnit) +
                ", FICHIER='...'} or aster-lite -u " + std::to_string(gmshUnit) + "=PATH)");
  session.files.addInput(input, "read by PRE_GMSH at " + session.where);  // never written over
  mesh::Mesh m = mesh::readGmshAsPreGmsh(input.string());
  m.title = "CONVERTED BY PRE_GMSH FROM " + input.filename().string();

  const auto bound = session.units.find(meshUnit);
  fs::path output;
  if (bound != session.units.end()) {
    output = bound->second;
    session.checkUnitWritable(meshUnit, output);
  } else {
    session.outputFile("");  // creates the output folder
    output = session.files.fresh(session.outputDir, session.studyPath.stem().string(), ".mail");
  }
  session.writeFile(output, [&](const fs::path& file) {
    std::ofstream out(file);
    mesh::writeAsterMesh(m, out);
    out.flush();
    if (!out) throw Error("cannot write " + file.string());
  });
  if (bound == session.units.end()) {
    session.units[meshUnit] = output;
    session.unitsBoundByStudy.insert(meshUnit);
  }
  Messages::info("PRE_GMSH: " + input.string() + " -> " + output.string() + " (" + meshText + "): " +
                 std::to_string(m.nodeCount()) + " nodes, " + std::to_string(m.cellCount()) + " cells, " +
                 std::to_string(m.cellGroupNames().size()) + " groups of cells");
  if (k.integer("INFO") >= 2) Messages::info(m.summary());
  return nullptr;
}

RegisterOperator reg("PRE_GMSH", preGmsh);

}  // namespace
}  // namespace aster::lang
