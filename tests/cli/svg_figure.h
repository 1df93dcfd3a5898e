#pragma once
// Reading back what gnuplot drew (montecarlo/write/plot/): the panels'
// frames and each plotted element's coordinates, from the SVG.
#include <algorithm>
#include <cmath>
#include <regex>
#include <string>
#include <utility>
#include <vector>

namespace insmc::testing {

struct Frame {
  double x0, y0, x1, y1;
};

struct Group {
  std::string id, title;
  std::vector<std::vector<std::pair<double, double>>> paths;  ///< subpaths, polygons, points
};

/// The panel frames (the border rectangles, stroke #333333), in drawing order.
inline std::vector<Frame> frames_of(const std::string& svg) {
  static const std::regex border(
      R"(stroke='rgb\( 51,  51,  51\)'\s+d='M([\d.]+),([\d.]+) L([\d.]+),([\d.]+) L([\d.]+),([\d.]+) L([\d.]+),([\d.]+) L[\d.]+,[\d.]+ Z)");
  std::vector<Frame> out;
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), border); it != std::sregex_iterator(); ++it) {
    std::vector<double> v;
    for (int i = 1; i <= 8; ++i) v.push_back(std::stod((*it)[i]));
    const Frame f{std::min({v[0], v[2], v[4], v[6]}), std::min({v[1], v[3], v[5], v[7]}),
                  std::max({v[0], v[2], v[4], v[6]}), std::max({v[1], v[3], v[5], v[7]})};
    if (out.empty() || std::abs(out.back().x0 - f.x0) + std::abs(out.back().y0 - f.y0) > 1) out.push_back(f);
  }
  return out;
}

/// Each plotted element (gnuplot's <g id="gnuplot_plot_N<panel letter>">)
/// with the coordinates of its paths, polygons and points.
inline std::vector<Group> groups_of(const std::string& svg) {
  static const std::regex open(R"re(<g id="(gnuplot_plot_\d+[a-z]?)" ><title>([^<]*)</title>)re");
  static const std::regex pair(R"((-?[\d.]+),(-?[\d.]+))");
  static const std::regex use(R"(<use xlink:href='#gpPt\d+' transform='translate\((-?[\d.]+),(-?[\d.]+)\))");
  std::vector<Group> out;
  std::vector<std::size_t> starts;
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), open); it != std::sregex_iterator(); ++it) {
    out.push_back({(*it)[1], (*it)[2], {}});
    starts.push_back(static_cast<std::size_t>(it->position()));
  }
  for (std::size_t g = 0; g < out.size(); ++g) {
    // The group's own text: up to the </g> that closes it.
    std::size_t at = starts[g], depth = 0;
    while (at < svg.size()) {
      const std::size_t open_at = svg.find("<g", at), close_at = svg.find("</g>", at);
      if (close_at == std::string::npos) break;
      if (open_at < close_at) {
        ++depth;
        at = open_at + 2;
      } else {
        at = close_at + 4;
        if (--depth == 0) break;
      }
    }
    const std::string body = svg.substr(starts[g], at - starts[g]);
    // Only the drawing attributes: d='...' and points='...' hold coordinates.
    static const std::regex attr(R"((?:\sd|points)\s*=\s*'([^']*)')");
    for (auto a = std::sregex_iterator(body.begin(), body.end(), attr); a != std::sregex_iterator(); ++a) {
      const std::string coords = (*a)[1];
      // Each subpath ("M ...") apart: the key's sample of a line is one.
      std::vector<std::pair<double, double>> path;
      for (auto p = std::sregex_iterator(coords.begin(), coords.end(), pair); p != std::sregex_iterator(); ++p) {
        const std::size_t pos = static_cast<std::size_t>(p->position());
        const std::size_t letter = pos == 0 ? std::string::npos : coords.find_last_not_of(" \t\n", pos - 1);
        if (letter != std::string::npos && coords[letter] == 'M' && !path.empty()) {
          out[g].paths.push_back(path);
          path.clear();
        }
        path.emplace_back(std::stod((*p)[1]), std::stod((*p)[2]));
      }
      if (!path.empty()) out[g].paths.push_back(std::move(path));
    }
    for (auto u = std::sregex_iterator(body.begin(), body.end(), use); u != std::sregex_iterator(); ++u)
      out[g].paths.push_back({{std::stod((*u)[1]), std::stod((*u)[2])}});
  }
  return out;
}

}  // namespace insmc::testing
