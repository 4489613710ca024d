// Random configurations drawn from a lab's own parameter list, for property runs and soaks:
// every value a parameter can take is reachable, and the ends of each range are drawn often
// (a quarter of the draws each end), because that is where configurations break.
#pragma once
#include <random>

#include "app/lab/lab.h"

namespace shadelab {

// Each parameter of `lab` is drawn with probability `share` (the rest keep their value), as
// "key=value" text the host applies through the same path as --set.
Settings randomSettings(Lab& lab, std::mt19937& rng, double share = 1.0);

// "--set lab.k=v --set ..." that reproduces `settings` on the command line.
std::string settingsAsArgs(std::string_view labId, const Settings& settings);

}  // namespace shadelab
