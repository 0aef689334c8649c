// The catalogue files, compiled into the program at build time.
#pragma once
#include <string>
#include <vector>

namespace aster::lang {

struct CatalogueSource {
  const char* name;  // file name without .lua: the command's name, or the common group's
  const char* text;
};

// commands/*.lua: one command each.
const std::vector<CatalogueSource>& catalogueSources();
// commands/commons/*.lua: the keyword groups several commands share; the file
// C_NAME.lua defines the global C_NAME that command files use.
const std::vector<CatalogueSource>& catalogueCommons();

}  // namespace aster::lang
