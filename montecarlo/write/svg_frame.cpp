#include "montecarlo/write/svg_frame.h"

#include <cmath>
#include <fmt/format.h>


namespace insmc::mc {

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


std::string open_svg(double w, double h, const std::string& title) {
  return fmt::format("<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{}\" height=\"{}\" font-family=\"sans-serif\" "
                     "font-size=\"11\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
                     "<text x=\"60\" y=\"22\" font-size=\"14\">{}</text>\n",
                     w, h, svg_escape(title));
}

std::string frame_svg(const Frame& f, const std::string& y_label) {
  return fmt::format("<defs><clipPath id=\"frame\"><rect x=\"{:.1f}\" y=\"{:.1f}\" width=\"{:.1f}\" height=\"{:.1f}\"/>"
                     "</clipPath></defs>\n<rect class=\"frame\" x=\"{:.1f}\" y=\"{:.1f}\" width=\"{:.1f}\" "
                     "height=\"{:.1f}\" fill=\"none\" stroke=\"black\"/>\n"
                     "<text transform=\"translate(16,{:.1f}) rotate(-90)\" text-anchor=\"middle\">{}</text>\n",
                     f.left, f.top, f.width, f.height, f.left, f.top, f.width, f.height, f.top + f.height / 2,
                     svg_escape(y_label));
}

double nice_step(double span) {
  if (!(span > 0)) return 1.0;
  const double raw = span / 6, p = std::pow(10.0, std::floor(std::log10(raw)));
  for (double m : {1.0, 2.0, 5.0, 10.0})
    if (m * p >= raw) return m * p;
  return 10 * p;
}

std::string decade_grid_svg(const Frame& f, const std::string& x_suffix) {
  std::string svg;
  for (double e = f.y0; e <= f.y1 + 1e-9; e += 1)
    svg += fmt::format("<line x1=\"{:.1f}\" y1=\"{:.1f}\" x2=\"{:.1f}\" y2=\"{:.1f}\" stroke=\"#ddd\"/>"
                       "<text x=\"{:.1f}\" y=\"{:.1f}\" text-anchor=\"end\">1e{:g}</text>\n",
                       f.left, f.py(e), f.left + f.width, f.py(e), f.left - 5, f.py(e) + 4, e);
  for (double e = f.x0; e <= f.x1 + 1e-9; e += 1)
    svg += fmt::format("<line x1=\"{:.1f}\" y1=\"{:.1f}\" x2=\"{:.1f}\" y2=\"{:.1f}\" stroke=\"#ddd\"/>"
                       "<text x=\"{:.1f}\" y=\"{:.1f}\" text-anchor=\"middle\">{:g}{}</text>\n",
                       f.px(e), f.top, f.px(e), f.top + f.height, f.px(e), f.top + f.height + 16, std::pow(10.0, e),
                       svg_escape(x_suffix));
  return svg;
}

}  // namespace insmc::mc
