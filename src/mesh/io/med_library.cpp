#include "mesh/io/med_library.hpp"

#include <dlfcn.h>

#include "mesh/io/loaded_library.hpp"

// The soname of the libmedC found at configure time (cmake/Dependencies.cmake).
#ifndef ASTER_MED_LIBRARY
#define ASTER_MED_LIBRARY "libmedC.so"
#endif

namespace aster::mesh {

namespace {

MedLibrary load() {
  const LibraryToLoad library{ASTER_MED_LIBRARY, "MED", "reading or writing a MED file", "MED 4",
                              "install it with 'apt-get install libmedc11' (or libmedc-dev)"};
  void* handle = openLibrary(library);
  MedLibrary api{};
  // One name per function: its type (decltype) and its symbol cannot disagree.
#define ASTER_MED_RESOLVE(name) api.name = libraryFunction<decltype(&MED##name)>(handle, library, "MED" #name)
  ASTER_MED_RESOLVE(familyCr);
  ASTER_MED_RESOLVE(familyInfo);
  ASTER_MED_RESOLVE(fieldCr);
  ASTER_MED_RESOLVE(fieldInfoByName);
  ASTER_MED_RESOLVE(fieldValueRd);
  ASTER_MED_RESOLVE(fieldValueWr);
  ASTER_MED_RESOLVE(fieldValueWithProfileWr);
  ASTER_MED_RESOLVE(fieldnComponentByName);
  ASTER_MED_RESOLVE(fieldnValue);
  ASTER_MED_RESOLVE(fileClose);
  ASTER_MED_RESOLVE(fileOpen);
  ASTER_MED_RESOLVE(localizationInfo);
  ASTER_MED_RESOLVE(localizationRd);
  ASTER_MED_RESOLVE(localizationWr);
  ASTER_MED_RESOLVE(meshCr);
  ASTER_MED_RESOLVE(meshElementConnectivityRd);
  ASTER_MED_RESOLVE(meshElementConnectivityWr);
  ASTER_MED_RESOLVE(meshEntityInfo);
  ASTER_MED_RESOLVE(meshEntityFamilyNumberRd);
  ASTER_MED_RESOLVE(meshEntityFamilyNumberWr);
  ASTER_MED_RESOLVE(meshEntityNameRd);
  ASTER_MED_RESOLVE(meshEntityNameWr);
  ASTER_MED_RESOLVE(meshInfo);
  ASTER_MED_RESOLVE(meshNodeCoordinateRd);
  ASTER_MED_RESOLVE(meshNodeCoordinateWr);
  ASTER_MED_RESOLVE(meshnAxis);
  ASTER_MED_RESOLVE(meshnEntity);
  ASTER_MED_RESOLVE(nFamily);
  ASTER_MED_RESOLVE(nFamilyGroup);
  ASTER_MED_RESOLVE(nLocalization);
  ASTER_MED_RESOLVE(nMesh);
  ASTER_MED_RESOLVE(nProfile);
  ASTER_MED_RESOLVE(profileInfo);
  ASTER_MED_RESOLVE(profileWr);
#undef ASTER_MED_RESOLVE
  // No HDF5 clean-up at exit: aster-lite closes every MED file it opens, and after a
  // close that failed (full disk) HDF5's clean-up crashes on the file it kept.
  // Must come before HDF5's first call, which registers that clean-up.
  if (auto dontAtExit = reinterpret_cast<int (*)()>(dlsym(handle, "H5dont_atexit"))) dontAtExit();
  return api;
}

}  // namespace

const MedLibrary& medLibrary() {
  static const MedLibrary api = load();  // a throw leaves it unset: the next call retries
  return api;
}

}  // namespace aster::mesh
