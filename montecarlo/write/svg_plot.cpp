#include "montecarlo/write/svg_plot.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <limits>

namespace insmc::mc {
namespace {

constexpr double kWidth = 760, kHeight = 460, kLeft = 80, kRight = 200, kTop = 40, kBottom = 60;
constexpr const char* kColours[] = {"#1f77b4", "#d62728", "#2ca02c", "#ff7f0e", "#9467bd",
                                    "#8c564b", "#e377c2", "#7f7f7f", "#bcbd22", "#17becf"};


/// A "nice" tick step (1, 2 or 5 × 10^k) giving about five ticks.
double nice_step(double span) {
  if (!(span > 0)) return 1.0;
  const double raw = span / 5, p = std::pow(10.0, std::floor(std::log10(raw)));
  for (double m : {1.0, 2.0, 5.0, 10.0})
    if (m * p >= raw) return m * p;
  return 10 * p;
}

}  // namespace

std::string svg_escape(const std::string& s) {
  std::string out;
  for (char c : s) {
    if (c == '<') out += "&lt;";
    else if (c == '>') out += "&gt;";
    else if (c == '&') out += "&amp;";
    else out += c;
  }
  return out;
}

std::string svg_line_plot(const std::string& title, const std::string& x_label, const std::string& y_label,
                          const std::vector<PlotSeries>& series) {
  double x0 = std::numeric_limits<double>::infinity(), x1 = -x0, y1 = 0.0;
  for (const auto& s : series) {
    for (double v : s.x) x0 = std::min(x0, v), x1 = std::max(x1, v);
    for (double v : s.y) if (std::isfinite(v)) y1 = std::max(y1, v);
    for (double v : s.hi) if (std::isfinite(v)) y1 = std::max(y1, v);
  }
  if (!(x1 > x0)) x0 = 0, x1 = 1;
  if (!(y1 > 0)) y1 = 1;
  const double ystep = nice_step(y1), xstep = nice_step(x1 - x0);
  y1 = std::ceil(y1 / ystep) * ystep;
  const double pw = kWidth - kLeft - kRight, ph = kHeight - kTop - kBottom;
  auto px = [&](double x) { return kLeft + (x - x0) / (x1 - x0) * pw; };
  auto py = [&](double y) { return kTop + ph - y / y1 * ph; };
  std::string svg = fmt::format(
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{}\" height=\"{}\" font-family=\"sans-serif\" "
      "font-size=\"12\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
      "<text x=\"{}\" y=\"24\" font-size=\"15\">{}</text>\n",
      kWidth, kHeight, kLeft, svg_escape(title));
  for (double y = 0; y <= y1 + 1e-9 * y1; y += ystep) {
    svg += fmt::format("<line x1=\"{:.1f}\" y1=\"{:.1f}\" x2=\"{:.1f}\" y2=\"{:.1f}\" stroke=\"#ddd\"/>"
                       "<text x=\"{:.1f}\" y=\"{:.1f}\" text-anchor=\"end\">{:g}</text>\n",
                       kLeft, py(y), kLeft + pw, py(y), kLeft - 6, py(y) + 4, y);
  }
  for (double x = std::ceil(x0 / xstep) * xstep; x <= x1 + 1e-9; x += xstep) {
    svg += fmt::format("<line x1=\"{:.1f}\" y1=\"{:.1f}\" x2=\"{:.1f}\" y2=\"{:.1f}\" stroke=\"#ddd\"/>"
                       "<text x=\"{:.1f}\" y=\"{:.1f}\" text-anchor=\"middle\">{:g}</text>\n",
                       px(x), kTop, px(x), kTop + ph, px(x), kTop + ph + 18, x);
  }
  svg += fmt::format("<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"none\" stroke=\"black\"/>\n",
                     kLeft, kTop, pw, ph);
  svg += fmt::format("<text x=\"{:.1f}\" y=\"{:.1f}\" text-anchor=\"middle\">{}</text>\n", kLeft + pw / 2,
                     kHeight - 15, svg_escape(x_label));
  svg += fmt::format("<text transform=\"translate(18,{:.1f}) rotate(-90)\" text-anchor=\"middle\">{}</text>\n",
                     kTop + ph / 2, svg_escape(y_label));
  for (size_t i = 0; i < series.size(); ++i) {
    const auto& s = series[i];
    const char* colour = kColours[static_cast<std::size_t>(s.colour >= 0 ? s.colour : static_cast<int>(i)) % std::size(kColours)];
    const char* dash = s.dashed ? " stroke-dasharray=\"7,4\"" : "";
    if (s.lo.size() == s.x.size() && s.hi.size() == s.x.size() && !s.x.empty()) {
      std::string pts;
      for (size_t k = 0; k < s.x.size(); ++k) pts += fmt::format("{:.1f},{:.1f} ", px(s.x[k]), py(s.hi[k]));
      for (size_t k = s.x.size(); k-- > 0;) pts += fmt::format("{:.1f},{:.1f} ", px(s.x[k]), py(s.lo[k]));
      svg += fmt::format("<polygon points=\"{}\" fill=\"{}\" fill-opacity=\"0.2\" stroke=\"none\"/>\n", pts, colour);
    }
    std::string pts;
    for (size_t k = 0; k < s.x.size(); ++k)
      if (std::isfinite(s.y[k])) pts += fmt::format("{:.1f},{:.1f} ", px(s.x[k]), py(s.y[k]));
    svg += fmt::format("<polyline points=\"{}\" fill=\"none\" stroke=\"{}\" stroke-width=\"2\"{}/>\n", pts, colour, dash);
    svg += fmt::format("<line x1=\"{:.1f}\" y1=\"{:.1f}\" x2=\"{:.1f}\" y2=\"{:.1f}\" stroke=\"{}\" stroke-width=\"3\"{}/>"
                       "<text x=\"{:.1f}\" y=\"{:.1f}\">{}</text>\n",
                       kLeft + pw + 12, kTop + 10 + 20.0 * i, kLeft + pw + 36, kTop + 10 + 20.0 * i, colour, dash,
                       kLeft + pw + 42, kTop + 14 + 20.0 * i, svg_escape(s.name));
  }
  svg += "</svg>\n";
  return svg;
}

}  // namespace insmc::mc
