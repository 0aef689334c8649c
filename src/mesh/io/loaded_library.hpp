// A shared library opened on first use rather than linked (libgmsh, libmedC: each drags
// tens of libraries that only some studies need), with errors that name the library and
// the package to install.
#pragma once
#include <string>

namespace aster::mesh {

struct LibraryToLoad {
  const char* soname;     // "libgmsh.so.4.8"
  const char* label;      // "gmsh": "the gmsh library ..."
  const char* neededFor;  // "reading or writing a GMSH file"
  std::string api;        // what aster-lite needs of it: "the C API of gmsh 4.8"
  const char* install;    // "install it with 'apt-get install ...'"
};

// dlopen(RTLD_LAZY | RTLD_LOCAL), never closed: the library's static destructors and
// atexit handlers run at exit as a linked library's would. Throws aster::Error when it
// cannot be loaded.
void* openLibrary(const LibraryToLoad& library);

// The address of `name` in the opened library; throws aster::Error when it has none.
void* librarySymbol(void* handle, const LibraryToLoad& library, const char* name);

template <typename Function>
Function libraryFunction(void* handle, const LibraryToLoad& library, const char* name) {
  return reinterpret_cast<Function>(librarySymbol(handle, library, name));
}

}  // namespace aster::mesh
