#include "mesh/io/gmsh_library.hpp"

#include <dlfcn.h>

#include <string>

#include "core/error.hpp"

// The soname of the libgmsh found at configure time (cmake/Dependencies.cmake):
// the functions' types come from that version's gmshc.h.
#ifndef ASTER_GMSH_LIBRARY
#define ASTER_GMSH_LIBRARY "libgmsh.so"
#endif

namespace aster::mesh {

namespace {

constexpr const char* kLibrary = ASTER_GMSH_LIBRARY;
constexpr const char* kInstall = "install it with 'apt-get install libgmsh4.8' (or libgmsh-dev)";

std::string lastDlError() {
  const char* text = dlerror();
  return text ? text : "unknown reason";
}

template <typename Function>
Function resolve(void* library, const char* name) {
  void* symbol = dlsym(library, name);
  if (!symbol)
    throw Error(std::string("the gmsh library ") + kLibrary + " has no function " + name + " (" + lastDlError() +
                "): aster-lite needs the C API of gmsh " GMSH_API_VERSION "; " + kInstall);
  return reinterpret_cast<Function>(symbol);
}

GmshLibrary load() {
  // RTLD_LOCAL: gmsh's ~120 libraries stay out of the global symbol scope.
  // The handle is never closed, not even at exit (no dlclose): gmsh's static
  // destructors then run at exit as a linked library's would, with nothing of
  // gmsh or of its libraries unloaded under them.
  void* library = dlopen(kLibrary, RTLD_LAZY | RTLD_LOCAL);
  if (!library)
    throw Error(std::string("reading or writing a GMSH file needs the gmsh library ") + kLibrary +
                ", which cannot be loaded (" + lastDlError() + "): " + kInstall);
  GmshLibrary api{};
  // One name per function: its type (decltype) and its symbol cannot disagree.
#define ASTER_GMSH_RESOLVE(name) api.name = resolve<decltype(&gmsh##name)>(library, "gmsh" #name)
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
