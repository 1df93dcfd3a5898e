#pragma once
// Reading back what gnuplot drew (montecarlo/report/plot/): the panels'
// frames and each plotted element's coordinates, from the SVG. Plain string
// scanning (std::regex trips GCC 12's -Wmaybe-uninitialized in the
// sanitizer build).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
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

/// The "x,y" pairs of an SVG path or points attribute, split into subpaths
/// at each M.
inline std::vector<std::vector<std::pair<double, double>>> subpaths_of(const std::string& coords) {
  std::vector<std::vector<std::pair<double, double>>> out;
  std::vector<std::pair<double, double>> path;
  const char* p = coords.c_str();
  while (*p) {
    if (*p == 'M' && !path.empty()) {
      out.push_back(path);
      path.clear();
    }
    if ((*p >= '0' && *p <= '9') || *p == '-' || *p == '.') {
      char* end = nullptr;
      const double x = std::strtod(p, &end);
      if (end == p || *end != ',') break;
      const char* y_at = end + 1;
      const double y = std::strtod(y_at, &end);
      if (end == y_at) break;
      path.emplace_back(x, y);
      p = end;
      continue;
    }
    ++p;
  }
  if (!path.empty()) out.push_back(path);
  return out;
}

/// Every value of attribute `name` (name='...' or name = '...') in `text`, in order.
inline std::vector<std::string> attributes(const std::string& text, const std::string& name) {
  std::vector<std::string> out;
  for (std::size_t at = text.find(name); at != std::string::npos; at = text.find(name, at + 1)) {
    if (at > 0 && text[at - 1] != ' ' && text[at - 1] != '\t') continue;
    std::size_t q = at + name.size();
    while (q < text.size() && text[q] == ' ') ++q;
    if (q >= text.size() || text[q] != '=') continue;
    ++q;
    while (q < text.size() && text[q] == ' ') ++q;
    if (q >= text.size() || text[q] != '\'') continue;
    const std::size_t end = text.find('\'', q + 1);
    if (end == std::string::npos) break;
    out.push_back(text.substr(q + 1, end - q - 1));
  }
  return out;
}

/// The panel frames (the border rectangles, stroke #333333), in drawing order.
inline std::vector<Frame> frames_of(const std::string& svg) {
  const std::string border = "stroke='rgb( 51,  51,  51)'";
  std::vector<Frame> out;
  for (std::size_t at = svg.find(border); at != std::string::npos; at = svg.find(border, at + 1)) {
    const std::string tag = svg.substr(at, svg.find('>', at) - at);
    const std::vector<std::string> d = attributes(tag, "d");
    if (d.empty() || d[0].find('Z') == std::string::npos) continue;
    const auto paths = subpaths_of(d[0]);
    if (paths.size() != 1 || paths[0].size() != 5) continue;
    Frame f{1e300, 1e300, -1e300, -1e300};
    for (const auto& [x, y] : paths[0])
      f = {std::min(f.x0, x), std::min(f.y0, y), std::max(f.x1, x), std::max(f.y1, y)};
    if (out.empty() || std::abs(out.back().x0 - f.x0) + std::abs(out.back().y0 - f.y0) > 1) out.push_back(f);
  }
  return out;
}

/// Each plotted element (gnuplot's <g id="gnuplot_plot_N<panel letter>">)
/// with the coordinates of its paths, polygons and points.
inline std::vector<Group> groups_of(const std::string& svg) {
  const std::string open = "<g id=\"gnuplot_plot_";
  std::vector<Group> out;
  for (std::size_t start = svg.find(open); start != std::string::npos; start = svg.find(open, start + 1)) {
    Group g;
    const std::size_t id_at = start + 7, id_end = svg.find('"', id_at);
    g.id = svg.substr(id_at, id_end - id_at);
    const std::size_t title_at = svg.find("<title>", id_end), title_end = svg.find("</title>", title_at);
    if (title_at != std::string::npos && title_end != std::string::npos) g.title = svg.substr(title_at + 7, title_end - title_at - 7);
    // The group's own text: up to the </g> that closes it.
    std::size_t at = start, depth = 0;
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
    const std::string body = svg.substr(start, at - start);
    // Only the drawing attributes hold coordinates: d='...', points='...',
    // and the translate(x,y) of a point symbol.
    for (const std::string& name : {std::string("d"), std::string("points")})
      for (const std::string& coords : attributes(body, name))
        for (auto& path : subpaths_of(coords)) g.paths.push_back(std::move(path));
    for (std::size_t u = body.find("<use "); u != std::string::npos; u = body.find("<use ", u + 1)) {
      const std::size_t t = body.find("translate(", u);
      if (t == std::string::npos || t > body.find('>', u)) continue;
      for (auto& path : subpaths_of(body.substr(t + 10, body.find(')', t) - t - 10))) g.paths.push_back(std::move(path));
    }
    out.push_back(std::move(g));
  }
  return out;
}

/// Checks that every plotted element lies inside a panel's frame but its
/// legend sample (a small subpath, of at most 5 points, wholly outside every
/// frame); returns the number of points strictly inside a frame.
inline std::size_t plotted_points_inside(const std::string& svg, const std::string& figure) {
  const std::vector<Frame> frames = frames_of(svg);
  EXPECT_FALSE(frames.empty()) << figure;
  const auto inside = [&](double x, double y, double margin) {
    for (const Frame& f : frames)
      if (x >= f.x0 - margin && x <= f.x1 + margin && y >= f.y0 - margin && y <= f.y1 + margin) return true;
    return false;
  };
  std::size_t strictly = 0;
  for (const Group& g : groups_of(svg))
    for (const auto& path : g.paths) {
      std::size_t within = 0;
      for (const auto& [x, y] : path) {
        within += inside(x, y, 0.5);
        strictly += inside(x, y, -0.5);
      }
      if (within == 0 && path.size() <= 5) continue;  // the legend's sample
      EXPECT_EQ(within, path.size()) << figure << ": " << g.id << " has points outside the frames";
    }
  return strictly;
}

}  // namespace insmc::testing
