// How aster-lite writes a number: one family of formatters for messages,
// check reports and text outputs (each output keeps the format it documents).
#pragma once
#include <string>

namespace aster::format {

// Fewest significant digits that read back as the same double ("2.5", "0",
// "1e-05"); integers up to 1e16 plainly ("1000", not "1e+03"). For messages.
std::string shortest(double v);

// printf's %.<digits>g: at most `digits` significant digits ("0.1", "1e-05").
std::string significant(double v, int digits);

// code_aster's way of printing checked values and instants: 12 significant
// digits, capital exponent (printf's %.12G: "0.1", "1.5E-05").
std::string asterValue(double v);

// printf's %.<digits>E: `digits` decimals in scientific notation ("1.50E-03").
std::string scientific(double v, int digits);

// The same with a blank where the sign of a positive value goes (printf's
// % .<digits>E), so that columns of signed values line up.
std::string scientificAligned(double v, int digits);

}  // namespace aster::format
