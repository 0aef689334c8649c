// libgmsh, loaded on first use rather than linked: relocating it and its ~120
// libraries (OpenCASCADE, FLTK, X11, MPI...) cost every run most of its start-up
// time, and only studies reading or writing GMSH files need it. The functions are
// gmsh's C API, typed from gmshc.h so that the compiler checks every call.
#pragma once
#include <gmshc.h>

namespace aster::mesh {

// The functions aster-lite calls, named as in gmshc.h without the "gmsh" prefix.
// Arrays they return are gmsh's: release them with Free.
struct GmshLibrary {
  decltype(&gmshFree) Free;
  decltype(&gmshInitialize) Initialize;
  decltype(&gmshFinalize) Finalize;
  decltype(&gmshOpen) Open;
  decltype(&gmshWrite) Write;
  decltype(&gmshOptionSetNumber) OptionSetNumber;
  decltype(&gmshOnelabSetNumber) OnelabSetNumber;
  decltype(&gmshLoggerGetLastError) LoggerGetLastError;
  decltype(&gmshModelAdd) ModelAdd;
  decltype(&gmshModelGetDimension) ModelGetDimension;
  decltype(&gmshModelGetEntities) ModelGetEntities;
  decltype(&gmshModelGetPhysicalGroups) ModelGetPhysicalGroups;
  decltype(&gmshModelGetPhysicalName) ModelGetPhysicalName;
  decltype(&gmshModelGetEntitiesForPhysicalGroup) ModelGetEntitiesForPhysicalGroup;
  decltype(&gmshModelAddDiscreteEntity) ModelAddDiscreteEntity;
  decltype(&gmshModelAddPhysicalGroup) ModelAddPhysicalGroup;
  decltype(&gmshModelSetPhysicalName) ModelSetPhysicalName;
  decltype(&gmshModelMeshGetNodes) ModelMeshGetNodes;
  decltype(&gmshModelMeshGetElements) ModelMeshGetElements;
  decltype(&gmshModelMeshGetElementProperties) ModelMeshGetElementProperties;
  decltype(&gmshModelMeshAddNodes) ModelMeshAddNodes;
  decltype(&gmshModelMeshAddElementsByType) ModelMeshAddElementsByType;
  decltype(&gmshModelMeshGenerate) ModelMeshGenerate;
  decltype(&gmshViewAdd) ViewAdd;
  decltype(&gmshViewAddHomogeneousModelData) ViewAddHomogeneousModelData;
  decltype(&gmshViewWrite) ViewWrite;
};

// Loads the library on the first call. Throws aster::Error, naming the library
// and the package to install, when it or one of the functions is missing (the
// next call tries again).
const GmshLibrary& gmshLibrary();

}  // namespace aster::mesh
