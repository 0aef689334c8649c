// libFuzzer target: the translator of code_aster command files on any bytes.
// translateCommandFile never throws: it returns the Lua or an error naming the
// line. A crash, a hang or an exception is a finding.
#include <cstddef>
#include <cstdint>
#include <string>

#include "comm/translate.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  const auto t = aster::comm::translateCommandFile(text, "fuzz.comm");
  if (t.ok == !t.error.empty()) __builtin_trap();  // exactly one of the Lua and the error
  return 0;
}
