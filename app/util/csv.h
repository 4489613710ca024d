// CSV cells for every table the project writes (sweeps, gradebooks, class reports, soak logs).
#pragma once
#include <string>

namespace shadelab {

// One CSV field: quoted where it must be (a comma, a quote, a line break), and text that a
// spreadsheet would run as a formula (a leading = + - @, a tab or a carriage return) defused with
// a leading apostrophe, so a student's folder name or a preset's file name stays text. A number
// ("-0.25", "1e-3") is written as it is: it is read as a number, never as a formula.
std::string csvField(const std::string& text);

}  // namespace shadelab
