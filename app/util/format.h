// Number-to-text for everything that writes numbers people read back: CLI values, JSON, CSV,
// camera strings, SVG coordinates. The shortest text that parses back to the same float, so a
// value saved and loaded again is bit-identical.
#pragma once
#include <string>
#include <vector>

namespace shadelab {

std::string formatNumber(double v);

// A fixed number of decimals, for tables people compare by eye (panel rows, notes).
std::string formatFixed(double v, int decimals = 3);
// `digits` significant digits, printf's %g ("0.35", "1.2e-05"), for numbers quoted in sentences.
std::string formatSignificant(double v, int digits = 6);
// Between single quotes, as sentences name a check, a configuration or a setting: "'no acne'".
std::string quoted(const std::string& s);

// Names as an English list, each between `quote`s: "'a', 'b' and 'c'"; past `most` of them, the
// rest counted: "'a', 'b' and 3 more".
std::string englishList(const std::vector<std::string>& names, const std::string& quote, size_t most = size_t(-1));

// Now as text in strftime's `format`: the local time ("%Y-%m-%d %H:%M" for people, "%Y%m%d-%H%M%S"
// in file names), or UTC ("%Y-%m-%dT%H:%M:%SZ" for gradebooks).
std::string localTimeNow(const char* format);
std::string utcTimeNow(const char* format);

// Text to number for values a user types (an option, a link): a whole number in [lo, hi] and
// nothing else ("8", not "8x" or "" or "1e3"). False, leaving `out` as it was, otherwise.
bool parseWholeNumber(const std::string& text, long lo, long hi, long& out);

}  // namespace shadelab
