#pragma once
/// A small, dependency-free SVG line plot (envelopes against time, sweeps):
/// one polyline per series with an optional shaded confidence band.
#include <string>
#include <vector>

namespace insmc::mc {

struct PlotSeries {
  std::string name;
  std::vector<double> x, y;
  std::vector<double> lo, hi;  ///< optional band (same length as y, or empty)
  int colour = -1;             ///< palette index; -1: the series' position
  bool dashed = false;
};

/// Text for SVG content and attributes: <, > and & escaped.
std::string svg_escape(const std::string& text);

std::string svg_line_plot(const std::string& title, const std::string& x_label, const std::string& y_label,
                          const std::vector<PlotSeries>& series);

}  // namespace insmc::mc
