#include "mesh/io/loaded_library.hpp"

#include <gtest/gtest.h>

#include <string>

#include "core/error.hpp"

namespace aster::mesh {
namespace {

const LibraryToLoad kMissing{"libaster-lite-missing.so.0", "missing", "reading a file", "its C API",
                             "install it with 'apt-get install nothing'"};

TEST(LoadedLibrary, AMissingLibraryIsNamedWithWhatNeedsItAndThePackage) {
  try {
    openLibrary(kMissing);
    FAIL() << "a library that does not exist was loaded";
  } catch (const Error& e) {
    const std::string what = e.what();
    EXPECT_EQ(what.rfind("reading a file needs the missing library libaster-lite-missing.so.0, which cannot be "
                         "loaded (", 0),
              0u)
        << what;
    EXPECT_NE(what.find("): install it with 'apt-get install nothing'"), std::string::npos) << what;
  }
}

TEST(LoadedLibrary, AMissingFunctionIsNamed) {
  LibraryToLoad libc = kMissing;
  libc.soname = "libc.so.6";
  void* handle = openLibrary(libc);
  EXPECT_NE(librarySymbol(handle, libc, "strlen"), nullptr);
  try {
    librarySymbol(handle, libc, "no_such_function_in_libc");
    FAIL() << "a function that does not exist was found";
  } catch (const Error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("the missing library libc.so.6 has no function no_such_function_in_libc"), std::string::npos)
        << what;
    EXPECT_NE(what.find("aster-lite needs its C API; install it with"), std::string::npos) << what;
  }
}

}  // namespace
}  // namespace aster::mesh
