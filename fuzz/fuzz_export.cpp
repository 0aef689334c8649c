// libFuzzer target: code_aster's .export reader on any bytes. parseExportFile must
// return or throw aster::Error naming the line; a crash or another exception is
// a finding.
#include <cstddef>
#include <cstdint>
#include <string>

#include "core/error.hpp"
#include "core/export_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const auto ex = aster::parseExportFile(text, "fuzz.export");
    for (const auto* e : ex.commandFiles()) (void)ex.resolve(*e);
    (void)ex.timeLimit();
  } catch (const aster::Error&) {
  }
  return 0;
}
