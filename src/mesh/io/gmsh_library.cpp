#include "mesh/io/gmsh_library.hpp"

#include "mesh/io/loaded_library.hpp"

// The soname of the libgmsh found at configure time (cmake/Dependencies.cmake):
// the functions' types come from that version's gmshc.h.
#ifndef ASTER_GMSH_LIBRARY
#define ASTER_GMSH_LIBRARY "libgmsh.so"
#endif

namespace aster::mesh {

namespace {

GmshLibrary load() {
  const LibraryToLoad library{ASTER_GMSH_LIBRARY, "gmsh", "reading or writing a GMSH file", std::string("the C API of gmsh ") + GMSH_API_VERSION,
                              "install it with 'apt-get install libgmsh4.8' (or libgmsh-dev)"};
  void* handle = openLibrary(library);
  GmshLibrary api{};
  // One name per function: its type (decltype) and its symbol cannot disagree.
#define ASTER_GMSH_RESOLVE(name) api.name = libraryFunction<decltype(&gmsh##name)>(handle, library, "gmsh" #name)
  ASTER_GMSH_RESOLVE(Free);
  ASTER_GMSH_RESOLVE(Initialize);
  ASTER_GMSH_RESOLVE(Finalize);
  ASTER_GMSH_RESOLVE(Open);
  ASTER_GMSH_RESOLVE(Write);
  ASTER_GMSH_RESOLVE(OptionSetNumber);
  ASTER_GMSH_RESOLVE(OnelabSetNumber);
  ASTER_GMSH_RESOLVE(LoggerGetLastError);
  ASTER_GMSH_RESOLVE(ModelAdd);
  ASTER_GMSH_RESOLVE(ModelGetDimension);
  ASTER_GMSH_RESOLVE(ModelGetEntities);
  ASTER_GMSH_RESOLVE(ModelGetPhysicalGroups);
  ASTER_GMSH_RESOLVE(ModelGetPhysicalName);
  ASTER_GMSH_RESOLVE(ModelGetEntitiesForPhysicalGroup);
  ASTER_GMSH_RESOLVE(ModelAddDiscreteEntity);
  ASTER_GMSH_RESOLVE(ModelAddPhysicalGroup);
  ASTER_GMSH_RESOLVE(ModelSetPhysicalName);
  ASTER_GMSH_RESOLVE(ModelMeshGetNodes);
  ASTER_GMSH_RESOLVE(ModelMeshGetElements);
  ASTER_GMSH_RESOLVE(ModelMeshGetElementProperties);
  ASTER_GMSH_RESOLVE(ModelMeshAddNodes);
  ASTER_GMSH_RESOLVE(ModelMeshAddElementsByType);
  ASTER_GMSH_RESOLVE(ModelMeshGenerate);
  ASTER_GMSH_RESOLVE(ViewAdd);
  ASTER_GMSH_RESOLVE(ViewAddHomogeneousModelData);
  ASTER_GMSH_RESOLVE(ViewWrite);
#undef ASTER_GMSH_RESOLVE
  return api;
}

}  // namespace

const GmshLibrary& gmshLibrary() {
  static const GmshLibrary api = load();  // a throw leaves it unset: the next call retries
  return api;
}

}  // namespace aster::mesh
