// The MED library (libmedC and, through it, HDF5 and Open MPI: about 45 libraries), loaded
// on first use rather than linked, as libgmsh (gmsh_library.hpp): loading them took
// 15-40 ms of every run's start-up, and only
// studies reading or writing MED files need them. The functions are MED's C API, typed
// from med.h so that the compiler checks every call.
#pragma once
#include <med.h>

namespace aster::mesh {

// The functions aster-lite calls, named as in med.h without the "MED" prefix.
struct MedLibrary {
  decltype(&MEDfamilyCr) familyCr;
  decltype(&MEDfamilyInfo) familyInfo;
  decltype(&MEDfieldCr) fieldCr;
  decltype(&MEDfieldInfoByName) fieldInfoByName;
  decltype(&MEDfieldValueRd) fieldValueRd;
  decltype(&MEDfieldValueWr) fieldValueWr;
  decltype(&MEDfieldValueWithProfileWr) fieldValueWithProfileWr;
  decltype(&MEDfieldnComponentByName) fieldnComponentByName;
  decltype(&MEDfieldnValue) fieldnValue;
  decltype(&MEDfileClose) fileClose;
  decltype(&MEDfileOpen) fileOpen;
  decltype(&MEDlocalizationInfo) localizationInfo;
  decltype(&MEDlocalizationRd) localizationRd;
  decltype(&MEDlocalizationWr) localizationWr;
  decltype(&MEDmeshCr) meshCr;
  decltype(&MEDmeshElementConnectivityRd) meshElementConnectivityRd;
  decltype(&MEDmeshElementConnectivityWr) meshElementConnectivityWr;
  decltype(&MEDmeshEntityInfo) meshEntityInfo;
  decltype(&MEDmeshEntityFamilyNumberRd) meshEntityFamilyNumberRd;
  decltype(&MEDmeshEntityFamilyNumberWr) meshEntityFamilyNumberWr;
  decltype(&MEDmeshEntityNameRd) meshEntityNameRd;
  decltype(&MEDmeshEntityNameWr) meshEntityNameWr;
  decltype(&MEDmeshInfo) meshInfo;
  decltype(&MEDmeshNodeCoordinateRd) meshNodeCoordinateRd;
  decltype(&MEDmeshNodeCoordinateWr) meshNodeCoordinateWr;
  decltype(&MEDmeshnAxis) meshnAxis;
  decltype(&MEDmeshnEntity) meshnEntity;
  decltype(&MEDnFamily) nFamily;
  decltype(&MEDnFamilyGroup) nFamilyGroup;
  decltype(&MEDnLocalization) nLocalization;
  decltype(&MEDnMesh) nMesh;
  decltype(&MEDnProfile) nProfile;
  decltype(&MEDprofileInfo) profileInfo;
  decltype(&MEDprofileWr) profileWr;
};

// Loads the library on the first call. Throws aster::Error, naming the library and the
// package to install, when it or one of the functions is missing (the next call tries again).
const MedLibrary& medLibrary();

}  // namespace aster::mesh
