#include "montecarlo/gap/report/gap_plots.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <limits>
#include <vector>

#include "montecarlo/write/svg_frame.h"

namespace insmc::mc {
namespace {

constexpr const char* kColours[] = {"#1f77b4", "#d62728", "#2ca02c"};


}  // namespace

std::string groups_svg(const Diagnosis& d) {
  const std::size_t n = d.groups.size();
  double lo = -1.0, hi = 1.0;
  for (const GroupResult& g : d.groups)
    for (double v : {g.log_ratio, g.null_low, g.null_high})
      if (std::isfinite(v)) lo = std::min(lo, v), hi = std::max(hi, v);
  const double step = nice_step(hi - lo);
  lo = std::floor(lo / step) * step;
  hi = std::ceil(hi / step) * step;
  const double slot = 22.0, width = 90 + slot * static_cast<double>(std::max<std::size_t>(n, 1)) + 30;
  const Frame f{70, 40, slot * static_cast<double>(std::max<std::size_t>(n, 1)), 300, 0, static_cast<double>(std::max<std::size_t>(n, 1)), lo, hi};
  std::string svg = open_svg(width, 40 + 300 + 150,
                             "ln(observed/expected) per group; grey: the null files' band at alpha");
  for (double y = lo; y <= hi + 1e-9 * step; y += step)
    svg += fmt::format("<line x1=\"{:.1f}\" y1=\"{:.1f}\" x2=\"{:.1f}\" y2=\"{:.1f}\" stroke=\"{}\"/>"
                       "<text x=\"{:.1f}\" y=\"{:.1f}\" text-anchor=\"end\">{:g}</text>\n",
                       f.left, f.py(y), f.left + f.width, f.py(y), std::abs(y) < 1e-9 * step ? "#888" : "#ddd",
                       f.left - 5, f.py(y) + 4, std::abs(y) < 1e-9 * step ? 0.0 : y);
  svg += frame_svg(f, "ln ratio (above 0: more than the model; below: less)");
  svg += "<g clip-path=\"url(#frame)\">\n";
  for (std::size_t i = 0; i < n; ++i) {
    const GroupResult& g = d.groups[i];
    const double x = static_cast<double>(i) + 0.5;
    svg += fmt::format("<rect class=\"band\" x=\"{:.1f}\" y=\"{:.1f}\" width=\"{:.1f}\" height=\"{:.1f}\" "
                       "fill=\"#bbb\" fill-opacity=\"0.6\"/>\n",
                       f.px(x - 0.35), f.py(g.null_high), f.px(x + 0.35) - f.px(x - 0.35),
                       std::max(1.0, f.py(g.null_low) - f.py(g.null_high)));
    const char* colour = g.log_ratio > g.null_high ? "#d62728" : g.log_ratio < g.null_low ? "#1f77b4" : "#333";
    svg += fmt::format("<line x1=\"{:.1f}\" y1=\"{:.1f}\" x2=\"{:.1f}\" y2=\"{:.1f}\" stroke=\"{}\" stroke-width=\"2\"/>"
                       "<circle class=\"point\" cx=\"{:.1f}\" cy=\"{:.1f}\" r=\"4\" fill=\"{}\"/>\n",
                       f.px(x), f.py(0), f.px(x), f.py(g.log_ratio), colour, f.px(x), f.py(g.log_ratio), colour);
  }
  svg += "</g>\n";
  for (std::size_t i = 0; i < n; ++i) {
    const double x = f.px(static_cast<double>(i) + 0.5);
    svg += fmt::format("<text transform=\"translate({:.1f},{:.1f}) rotate(-60)\" text-anchor=\"end\">{}</text>\n", x + 3,
                       f.top + f.height + 10, svg_escape(d.groups[i].name()));
  }
  return svg + "</svg>\n";
}

std::string allan_svg(const Diagnosis& d) {
  double x0 = std::numeric_limits<double>::infinity(), x1 = -x0, y0 = x0, y1 = -x0;
  for (const AllanCurve& c : d.allan)
    for (const AllanPoint& p : c.points) {
      if (!(p.cluster_s > 0)) continue;
      x0 = std::min(x0, std::log10(p.cluster_s)), x1 = std::max(x1, std::log10(p.cluster_s));
      for (double v : {p.observed, p.null, p.null_low, p.null_high})
        if (v > 0 && std::isfinite(v)) y0 = std::min(y0, std::log10(v)), y1 = std::max(y1, std::log10(v));
    }
  const bool empty = !(x1 >= x0) || !(y1 >= y0);
  if (empty) x0 = 0, x1 = 1, y0 = -6, y1 = -5;
  // Whole decades around the values, a decade at least.
  x0 = std::floor(x0), x1 = std::max(std::ceil(x1), x0 + 1);
  y0 = std::floor(y0), y1 = std::max(std::ceil(y1), y0 + 1);
  const Frame f{80, 40, 520, 340, x0, x1, y0, y1};
  std::string svg = open_svg(800, 440, "Allan deviation of the f residuals: data (solid) and the null (band, dashed)");
  svg += decade_grid_svg(f, " s");
  svg += frame_svg(f, "Allan deviation [m/s^2]");
  svg += fmt::format("<text x=\"{:.1f}\" y=\"{:.1f}\" text-anchor=\"middle\">cluster time (log scale)</text>\n",
                     f.left + f.width / 2, f.top + f.height + 40);
  if (empty)
    svg += fmt::format("<text x=\"{:.1f}\" y=\"{:.1f}\" text-anchor=\"middle\">no f residuals to show</text>\n",
                       f.left + f.width / 2, f.top + f.height / 2);
  svg += "<g clip-path=\"url(#frame)\">\n";
  for (const AllanCurve& c : d.allan) {
    const char* colour = kColours[c.axis % 3];
    std::string band, data, null;
    std::vector<const AllanPoint*> pts;
    for (const AllanPoint& p : c.points)
      if (p.cluster_s > 0 && p.observed > 0 && p.null > 0) pts.push_back(&p);
    for (const AllanPoint* p : pts) band += fmt::format("{:.1f},{:.1f} ", f.px(std::log10(p->cluster_s)), f.py(std::log10(std::max(p->null_high, p->null))));
    for (auto it = pts.rbegin(); it != pts.rend(); ++it)
      band += fmt::format("{:.1f},{:.1f} ", f.px(std::log10((*it)->cluster_s)), f.py(std::log10(std::min((*it)->null_low > 0 ? (*it)->null_low : (*it)->null, (*it)->null))));
    for (const AllanPoint* p : pts) {
      data += fmt::format("{:.1f},{:.1f} ", f.px(std::log10(p->cluster_s)), f.py(std::log10(p->observed)));
      null += fmt::format("{:.1f},{:.1f} ", f.px(std::log10(p->cluster_s)), f.py(std::log10(p->null)));
    }
    if (pts.empty()) continue;
    svg += fmt::format("<polygon points=\"{}\" fill=\"{}\" fill-opacity=\"0.15\" stroke=\"none\"/>\n", band, colour);
    svg += fmt::format("<polyline points=\"{}\" fill=\"none\" stroke=\"{}\" stroke-width=\"1.5\" "
                       "stroke-dasharray=\"6,4\"/>\n", null, colour);
    svg += fmt::format("<polyline points=\"{}\" fill=\"none\" stroke=\"{}\" stroke-width=\"2\"/>\n", data, colour);
    for (const AllanPoint* p : pts)
      svg += fmt::format("<circle class=\"point\" cx=\"{:.1f}\" cy=\"{:.1f}\" r=\"3\" fill=\"{}\"/>\n",
                         f.px(std::log10(p->cluster_s)), f.py(std::log10(p->observed)), colour);
  }
  svg += "</g>\n";
  for (const AllanCurve& c : d.allan)
    svg += fmt::format("<line x1=\"{:.1f}\" y1=\"{:.1f}\" x2=\"{:.1f}\" y2=\"{:.1f}\" stroke=\"{}\" stroke-width=\"3\"/>"
                       "<text x=\"{:.1f}\" y=\"{:.1f}\">f_{}</text>\n",
                       f.left + f.width + 20, f.top + 12 + 20.0 * c.axis, f.left + f.width + 44,
                       f.top + 12 + 20.0 * c.axis, kColours[c.axis % 3], f.left + f.width + 50,
                       f.top + 16 + 20.0 * c.axis, "xyz"[c.axis]);
  return svg + "</svg>\n";
}

}  // namespace insmc::mc
