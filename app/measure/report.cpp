#include "app/measure/report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>

#include <stb_image_write.h>

#include "app/util/csv.h"
#include "app/util/format.h"
#include "app/util/output_files.h"

namespace shadelab {

double SweepRow::value(const std::string& key) const {
  for (auto& [k, v] : values)
    if (k == key) return v;
  return std::nan("");
}

std::string writeTextFile(const std::string& path, const std::string& text) {
  if (auto err = makeParentFolder(path); !err.empty()) return err;
  const std::string tmp = path + ".tmp";
  {
    std::ofstream out(tmp, std::ios::binary);
    if (!(out << text)) return path + ": cannot write";
  }
  std::error_code ec;
  std::filesystem::rename(tmp, path, ec);
  return ec ? path + ": " + ec.message() : std::string();
}

std::vector<std::string> truthsOf(const SweepReport& r) {
  std::vector<std::string> out;
  for (auto& row : r.rows)
    if (std::find(out.begin(), out.end(), row.truth) == out.end()) out.push_back(row.truth);
  return out;
}

std::string sweepCsv(const SweepReport& r) {
  if (r.rows.empty()) return "";
  std::string csv;
  for (auto& [key, note] : r.metricNotes) csv += "# " + key + ": " + note + "\n";
  const auto& first = r.rows.front();
  for (auto& [k, v] : first.params) csv += csvField(k) + ",";
  csv += "truth,";
  for (size_t i = 0; i < first.values.size(); ++i)
    csv += csvField(first.values[i].first) + (i + 1 < first.values.size() ? "," : "\n");
  for (auto& row : r.rows) {
    for (auto& [k, v] : row.params) csv += csvField(v) + ",";
    csv += csvField(row.truth) + ",";
    for (size_t i = 0; i < row.values.size(); ++i)
      csv += formatNumber(row.values[i].second) + (i + 1 < row.values.size() ? "," : "\n");
  }
  return csv;
}

static bool inTruth(const SweepRow& row, const std::string& truth) { return truth.empty() || row.truth == truth; }

std::vector<size_t> paretoFront(const SweepReport& r, const PlotSpec& plot, const std::string& truth) {
  std::vector<size_t> order;
  for (size_t i = 0; i < r.rows.size(); ++i)
    if (inTruth(r.rows[i], truth) && std::isfinite(r.rows[i].value(plot.error)) &&
        std::isfinite(r.rows[i].value(plot.cost)))
      order.push_back(i);
  std::sort(order.begin(), order.end(),
            [&](size_t a, size_t b) { return r.rows[a].value(plot.cost) < r.rows[b].value(plot.cost); });
  std::vector<size_t> front;
  double best = INFINITY;
  for (size_t i : order)
    if (r.rows[i].value(plot.error) < best) {
      best = r.rows[i].value(plot.error);
      front.push_back(i);
    }
  return front;
}

std::string htmlEscape(const std::string& s) {
  std::string o;
  for (char c : s) {
    if (c == '<')
      o += "&lt;";
    else if (c == '>')
      o += "&gt;";
    else if (c == '&')
      o += "&amp;";
    else if (c == '"')
      o += "&quot;";
    else
      o += c;
  }
  return o;
}

static std::string base64(const std::vector<unsigned char>& data) {
  static const char* t = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (size_t i = 0; i < data.size(); i += 3) {
    const unsigned v = unsigned(data[i]) << 16 | (i + 1 < data.size() ? unsigned(data[i + 1]) << 8 : 0u) |
                       (i + 2 < data.size() ? unsigned(data[i + 2]) : 0u);
    out += t[(v >> 18) & 63];
    out += t[(v >> 12) & 63];
    out += i + 1 < data.size() ? t[(v >> 6) & 63] : '=';
    out += i + 2 < data.size() ? t[v & 63] : '=';
  }
  return out;
}

std::string pngDataUri(const ImageF& img) {
  if (img.rgba.empty()) return "";
  std::vector<unsigned char> rgb(size_t(img.size.x) * img.size.y * 3), png;
  for (size_t i = 0; i < rgb.size() / 3; ++i)
    for (int c = 0; c < 3; ++c) {
      const float v = img.rgba[i * 4 + size_t(c)];
      rgb[i * 3 + size_t(c)] = (unsigned char)std::lround(std::isfinite(v) ? std::clamp(v, 0.0f, 1.0f) * 255 : 255);
    }
  stbi_write_png_to_func(
      [](void* ctx, void* d, int n) {
        auto* out = static_cast<std::vector<unsigned char>*>(ctx);
        out->insert(out->end(), static_cast<unsigned char*>(d), static_cast<unsigned char*>(d) + n);
      },
      &png, img.size.x, img.size.y, 3, rgb.data(), img.size.x * 3);
  return "data:image/png;base64," + base64(png);
}

namespace {

std::string fourDigits(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4g", v);
  return buf;
}

const char* kPalette[] = {"#d62728", "#1f77b4", "#2ca02c", "#ff7f0e", "#9467bd", "#8c564b", "#e377c2", "#17becf"};

// Nice axis ticks: 1, 2 or 5 times a power of ten.
std::vector<double> ticks(double lo, double hi) {
  const double span = std::max(hi - lo, 1e-12), raw = span / 5;
  const double mag = std::pow(10.0, std::floor(std::log10(raw)));
  const double step = raw / mag < 2 ? 2 * mag : raw / mag < 5 ? 5 * mag : 10 * mag;
  std::vector<double> t;
  for (double v = std::ceil(lo / step) * step; v <= hi + 1e-9 * span; v += step) t.push_back(v);
  return t;
}

// One axis of a plot: linear, or logarithmic where every value is positive and they span more than
// a decade and a half (a sweep's cheapest and dearest configurations, or its worst and best errors,
// often differ a hundredfold, and a linear axis squeezes every useful point into a corner).
struct Axis {
  double lo = 0, hi = 1;
  bool log = false;

  // Where v falls, 0 at lo .. 1 at hi.
  double at(double v) const {
    return log ? (std::log10(v) - std::log10(lo)) / (std::log10(hi) - std::log10(lo)) : (v - lo) / (hi - lo);
  }
  std::vector<double> ticks() const {
    if (!log) return shadelab::ticks(lo, hi);
    std::vector<double> t;
    for (int mult : {1, 2, 5})
      for (int k = int(std::floor(std::log10(lo))); k <= int(std::ceil(std::log10(hi))); ++k) {
        const double v = mult * std::pow(10.0, k);
        if (v >= lo * (1 - 1e-9) && v <= hi * (1 + 1e-9)) t.push_back(v);
      }
    std::sort(t.begin(), t.end());
    if (t.size() > 12)
      std::erase_if(t, [](double v) { return std::abs(std::log10(v) - std::round(std::log10(v))) > 1e-9; });
    return t;
  }
};

// `fromZero`: a linear axis starts at 0 (errors: 0 is the truth itself).
Axis axisFor(const std::vector<double>& values, bool fromZero) {
  Axis a;
  if (values.empty()) return a;
  const auto [mn, mx] = std::minmax_element(values.begin(), values.end());
  if (*mn > 0 && *mx / *mn > 30) {
    a.log = true;
    a.lo = *mn / 1.25;
    a.hi = *mx * 1.25;
    return a;
  }
  a.lo = fromZero ? 0.0 : *mn, a.hi = *mx;
  if (!(a.hi > a.lo)) a.lo -= 0.5, a.hi += 0.5;
  const double pad = (a.hi - a.lo) * 0.05;
  if (!fromZero) a.lo = std::max(0.0, a.lo - pad);
  a.hi += fromZero ? (a.hi - a.lo) * 0.08 : pad;
  return a;
}

std::string costAxisLabel(const std::string& cost) {
  if (cost == "gpu_ms") return "gpu_ms (median of the frame's passes, lower is cheaper)";
  if (cost == "cpu_ms") return "cpu_ms (median, lower is cheaper)";
  return cost + " (lower is cheaper)";
}

std::string plot(const SweepReport& r, const PlotSpec& spec, const std::string& truth) {
  const std::string& errorKey = spec.error;
  const std::string& costKey = spec.cost;
  std::map<std::string, int> groups;  // legend entries, coloured in order of first appearance
  size_t longest = 16;
  for (auto& row : r.rows)
    if (inTruth(row, truth) && groups.emplace(row.group, int(groups.size())).second)
      longest = std::max(longest, row.group.size());
  // The legend column is as wide as its longest name (about 7 px a character at 12 px).
  const double L = 70, R = 40 + 7.0 * double(longest), T = 26, B = 50, W = 470 + R, H = 400;
  // The frame: the Pareto front and what lies near it. A configuration more than three times the
  // front's dearest cost or worst error (a bias-0 run, a moment map ten times slower) is drawn on
  // the frame's edge, hollow, with its values on hover, so it does not squeeze the front into a corner.
  const std::vector<size_t> front = paretoFront(r, spec, truth);
  double costLimit = INFINITY, errorLimit = INFINITY;
  if (front.size() >= 2) {
    costLimit = errorLimit = 0.0;
    for (size_t i : front) {
      costLimit = std::max(costLimit, 3.0 * r.rows[i].value(costKey));
      errorLimit = std::max(errorLimit, 3.0 * r.rows[i].value(errorKey));
    }
    if (!(costLimit > 0.0)) costLimit = INFINITY;
    if (!(errorLimit > 0.0)) errorLimit = INFINITY;
  }
  auto beyond = [&](const SweepRow& row) { return row.value(costKey) > costLimit || row.value(errorKey) > errorLimit; };
  std::vector<double> costs, errors;
  for (auto& row : r.rows) {
    if (!inTruth(row, truth) || !std::isfinite(row.value(costKey)) || !std::isfinite(row.value(errorKey)) ||
        beyond(row))
      continue;
    costs.push_back(row.value(costKey));
    errors.push_back(row.value(errorKey));
  }
  const Axis ax = axisFor(costs, false), ay = axisFor(errors, true);
  auto sx = [&](double v) { return L + ax.at(std::clamp(v, ax.lo, ax.hi)) * (W - L - R); };
  auto sy = [&](double v) { return H - B - ay.at(std::clamp(v, ay.lo, ay.hi)) * (H - T - B); };
  std::string s = "<svg xmlns='http://www.w3.org/2000/svg' width='" + formatNumber(W) + "' height='" + formatNumber(H) +
                  "' font-family='sans-serif' font-size='12'>\n<rect width='100%' height='100%' fill='white'/>\n";
  for (double t : ax.ticks())
    s += "<line x1='" + formatNumber(sx(t)) + "' x2='" + formatNumber(sx(t)) + "' y1='" + formatNumber(T) + "' y2='" +
         formatNumber(H - B) + "' stroke='#eee'/><text x='" + formatNumber(sx(t)) + "' y='" + formatNumber(H - B + 16) +
         "' text-anchor='middle'>" + formatNumber(t) + "</text>\n";
  for (double t : ay.ticks())
    s += "<line x1='" + formatNumber(L) + "' x2='" + formatNumber(W - R) + "' y1='" + formatNumber(sy(t)) + "' y2='" +
         formatNumber(sy(t)) + "' stroke='#eee'/><text x='" + formatNumber(L - 6) + "' y='" + formatNumber(sy(t) + 4) +
         "' text-anchor='end'>" + formatNumber(t) + "</text>\n";
  s += "<text x='" + formatNumber(L) + "' y='" + formatNumber(T - 6) + "' fill='#555'>" +
       (truth.empty() ? std::string() : "truth: " + htmlEscape(truth) + "; ") +
       "lower is closer to the truth, left is cheaper</text>\n";
  s += "<rect x='" + formatNumber(L) + "' y='" + formatNumber(T) + "' width='" + formatNumber(W - L - R) +
       "' height='" + formatNumber(H - T - B) + "' fill='none' stroke='#333'/>\n";
  s += "<text x='" + formatNumber((L + W - R) / 2) + "' y='" + formatNumber(H - 12) + "' text-anchor='middle'>" +
       htmlEscape(costAxisLabel(costKey)) + (ax.log ? ", log scale" : "") + "</text>\n";
  s += "<text transform='translate(16," + formatNumber((T + H - B) / 2) + ") rotate(-90)' text-anchor='middle'>" +
       htmlEscape(errorKey) + (ay.log ? " (log scale)" : "") + "</text>\n";
  // Pareto front: the configurations nothing else beats on both axes.
  std::string path;
  int outside = 0;
  for (size_t i : front)
    path += (path.empty() ? "M" : " L") + formatNumber(sx(r.rows[i].value(costKey))) + "," +
            formatNumber(sy(r.rows[i].value(errorKey)));
  s += "<path d='" + path + "' fill='none' stroke='#999' stroke-dasharray='4 3'/>\n";
  for (auto& row : r.rows) {
    if (!inTruth(row, truth) || !std::isfinite(row.value(costKey)) || !std::isfinite(row.value(errorKey))) continue;
    const char* color = kPalette[groups[row.group] % 8];
    const bool out = beyond(row);
    outside += out;
    s += "<circle cx='" + formatNumber(sx(row.value(costKey))) + "' cy='" + formatNumber(sy(row.value(errorKey))) +
         "' r='5' " +
         (out ? std::string("fill='white' stroke='") + color + "' stroke-width='2'"
              : std::string("fill='") + color + "' fill-opacity='0.8'") +
         "><title>" + htmlEscape(row.label) + ": " + errorKey + " " + formatNumber(row.value(errorKey)) + ", " +
         costKey + " " + formatNumber(row.value(costKey)) + (out ? " (beyond the frame)" : "") + "</title></circle>\n";
  }
  int k = 0;
  for (auto& [name, index] : groups) {
    const double y = T + 14 + 18 * k++;
    s += "<circle cx='" + formatNumber(W - R + 16) + "' cy='" + formatNumber(y - 4) + "' r='5' fill='" +
         kPalette[index % 8] + "'/><text x='" + formatNumber(W - R + 26) + "' y='" + formatNumber(y) + "'>" +
         htmlEscape(name) + "</text>\n";
  }
  s += "<text x='" + formatNumber(W - R + 10) + "' y='" + formatNumber(T + 14 + 18 * k + 6) +
       "' fill='#777'>- - Pareto front</text>\n";
  if (outside > 0)
    s += "<circle cx='" + formatNumber(W - R + 16) + "' cy='" + formatNumber(T + 14 + 18 * (k + 1) + 2) +
         "' r='5' fill='white' stroke='#777' stroke-width='2'/><text x='" + formatNumber(W - R + 26) + "' y='" +
         formatNumber(T + 14 + 18 * (k + 1) + 6) + "' fill='#777'>" + std::to_string(outside) +
         " beyond the frame</text>\n";
  s += "</svg>\n";
  return s;
}

}  // namespace

std::string sweepPlotSvg(const SweepReport& r, const PlotSpec& spec, const std::string& truth) {
  return plot(r, spec, truth);
}

std::string sweepHtml(const SweepReport& r) {
  std::string h = "<!doctype html>\n<html><head><meta charset='utf-8'><title>" + htmlEscape(r.title) +
                  "</title>\n<style>body{font-family:sans-serif;margin:24px;max-width:1400px}"
                  "table{border-collapse:collapse;font-size:13px}td,th{border:1px solid #ccc;padding:3px 7px;"
                  "text-align:right}code{background:#f4f4f4;padding:2px 4px}.imgs{display:flex;flex-wrap:wrap;gap:10px}"
                  ".imgs figure{margin:0;font-size:12px}</style></head><body>\n";
  h += "<h1>" + htmlEscape(r.title) + "</h1>\n";
  h += "<p>Made by <code>" + htmlEscape(r.command) + "</code></p>\n";
  h += "<p>Renderer: " + htmlEscape(r.renderer) + "<br>";
  for (auto& [truth, what] : r.truths) h += "Truth <b>" + htmlEscape(truth) + "</b>: " + htmlEscape(what) + "<br>";
  h += "gpu_ms: the median over the timed frames of the summed time of every pass, measured with " +
       htmlEscape(r.costClock) + ".</p>\n";
  const auto truths = truthsOf(r);
  for (auto& spec : r.plots)
    for (auto& truth : truths)
      h += "<h2>" + htmlEscape(spec.error) + " against " + htmlEscape(spec.cost) +
           (truths.size() > 1 ? " (truth: " + htmlEscape(truth) + ")" : "") + "</h2>\n" + plot(r, spec, truth);
  h += "<h2>Configurations</h2>\n<table><tr><th>configuration</th><th>truth</th>";
  if (!r.rows.empty())
    for (auto& [k, v] : r.rows.front().values) h += "<th>" + htmlEscape(k) + "</th>";
  h += "</tr>\n";
  for (auto& row : r.rows) {
    const bool broken = row.value("shader_errors") > 0;  // a fallback was drawn: mark the row
    h += std::string(broken ? "<tr style='background:#fdd' title='a program did not build'>" : "<tr>") +
         "<td style='text-align:left'>" + htmlEscape(row.label) + "</td><td>" + htmlEscape(row.truth) + "</td>";
    for (auto& [k, v] : row.values) h += "<td>" + fourDigits(v) + "</td>";  // the CSV keeps every digit
    h += "</tr>\n";
  }
  h += "</table>\n<h2>Images</h2>\n<div class='imgs'>\n";
  for (auto& [truth, image] : r.referenceThumbnails)
    h += "<figure><img src='" + pngDataUri(image) + "'><figcaption>truth: " + htmlEscape(truth) +
         "</figcaption></figure>\n";
  for (auto& row : r.rows) {
    std::string caption = htmlEscape(row.label);
    if (!r.plots.empty()) {
      const PlotSpec& p = r.plots.front();
      caption += "<br>" + htmlEscape(p.error) + " " + fourDigits(row.value(p.error)) + ", " + htmlEscape(p.cost) + " " +
                 fourDigits(row.value(p.cost));
    }
    h += "<figure><img src='" + pngDataUri(row.thumbnail) + "'><figcaption>" + caption + "</figcaption></figure>\n";
  }
  h += "</div>\n</body></html>\n";
  return h;
}

}  // namespace shadelab
