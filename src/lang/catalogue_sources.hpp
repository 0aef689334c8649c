// The catalogue files (commands/*.lua), compiled into the program at build time.
#pragma once
#include <string>
#include <vector>

namespace aster::lang {

struct CatalogueSource {
  const char* name;  // file name without .lua: the command's name
  const char* text;
};

const std::vector<CatalogueSource>& catalogueSources();

}  // namespace aster::lang
