#include "mesh/io/loaded_library.hpp"

#include <dlfcn.h>

#include "core/error.hpp"

namespace aster::mesh {

namespace {

std::string lastDlError() {
  const char* text = dlerror();
  return text ? text : "unknown reason";
}

}  // namespace

void* openLibrary(const LibraryToLoad& library) {
  void* handle = dlopen(library.soname, RTLD_LAZY | RTLD_LOCAL);
  if (!handle)
    throw Error(std::string(library.neededFor) + " needs the " + library.label + " library " + library.soname +
                ", which cannot be loaded (" + lastDlError() + "): " + library.install);
  return handle;
}

void* librarySymbol(void* handle, const LibraryToLoad& library, const char* name) {
  void* symbol = dlsym(handle, name);
  if (!symbol)
    throw Error(std::string("the ") + library.label + " library " + library.soname + " has no function " + name +
                " (" + lastDlError() + "): aster-lite needs " + library.api + "; " + library.install);
  return symbol;
}

}  // namespace aster::mesh
