#pragma once
/// The pieces of a hand-drawn SVG chart shared by the diagnosis' and the
/// noise stage's plots: a frame with its data range, the document head, the
/// frame with its clip path (id "frame") and y label, a tick step, and
/// log-decade grid lines.
#include <string>

namespace insmc::mc {

/// A frame in pixels and the data range it shows.
struct Frame {
  double left, top, width, height;
  double x0, x1, y0, y1;
  double px(double x) const { return left + (x - x0) / (x1 - x0) * width; }
  double py(double y) const { return top + height - (y - y0) / (y1 - y0) * height; }
};

/// Text for SVG content and attributes: <, > and & escaped.
std::string svg_escape(const std::string& text);

std::string open_svg(double w, double h, const std::string& title);
/// The frame, its clip path (id "frame") and the y label.
std::string frame_svg(const Frame& f, const std::string& y_label);
/// A round step that cuts `span` into about six parts.
double nice_step(double span);
/// Grid lines and labels at every decade of a log–log frame (x0..y1 are
/// log10 values); x labels carry `x_suffix` (e.g. " s").
std::string decade_grid_svg(const Frame& f, const std::string& x_suffix);

}  // namespace insmc::mc
