#include "app/host/random_settings.h"

#include <cmath>

namespace shadelab {
namespace {

class DrawRandom final : public ParamVisitor {
 public:
  DrawRandom(std::mt19937& rng, double share) : rng_(rng), share_(share) {}
  void floatParam(const ParamInfo& info, float& value, float min, float max, bool logScale) override {
    if (!pick()) return;
    const double u = unit();
    float v = u < 0.25 ? min : u < 0.5 ? max : 0.0f;
    if (u >= 0.5) {
      const double t = unit();
      v = logScale && min > 0.0f ? float(min * std::pow(double(max) / min, t)) : float(min + (max - min) * t);
    }
    out.emplace_back(std::string(info.key), formatNumber(v));
  }
  void intParam(const ParamInfo& info, int& value, int min, int max) override {
    if (!pick()) return;
    const double u = unit();
    const int v = u < 0.25 ? min : u < 0.5 ? max : std::uniform_int_distribution<int>(min, max)(rng_);
    out.emplace_back(std::string(info.key), std::to_string(v));
  }
  void boolParam(const ParamInfo& info, bool& value) override {
    if (pick()) out.emplace_back(std::string(info.key), unit() < 0.5 ? "on" : "off");
  }
  void choiceParam(const ParamInfo& info, int& index, std::span<const std::string_view> names) override {
    if (!pick() || names.empty()) return;
    out.emplace_back(std::string(info.key),
                     std::string(names[std::uniform_int_distribution<size_t>(0, names.size() - 1)(rng_)]));
  }
  Settings out;

 private:
  double unit() { return std::uniform_real_distribution<double>(0.0, 1.0)(rng_); }
  bool pick() { return share_ >= 1.0 || unit() < share_; }
  std::mt19937& rng_;
  double share_;
};

}  // namespace

Settings randomSettings(Lab& lab, std::mt19937& rng, double share) {
  DrawRandom draw(rng, share);
  lab.visitParams(draw);
  return std::move(draw.out);
}

std::string settingsAsArgs(std::string_view labId, const Settings& settings) {
  std::string s;
  for (auto& [k, v] : settings)
    s += (s.empty() ? "" : " ") + std::string("--set ") + std::string(labId) + "." + k + "=" + v;
  return s;
}

}  // namespace shadelab
