#pragma once
/// A count matrix as a gnuplot heat map (e.g. gap-validate's confusion
/// matrix: true effect × reported one): each non-empty cell a filled square
/// shaded by its share of the row's total, with its count written in it.
/// Rendered like panel_figure.h.
#include <string>
#include <vector>

#include "montecarlo/report/plot/gnuplot.h"

namespace insmc::mc {

struct MatrixFigure {
  std::string stem, title, x_label, y_label;
  std::vector<std::string> rows, columns;
  std::vector<std::vector<int>> counts;  ///< [row][column]
};

RenderedFigure render_matrix_figure(const MatrixFigure& figure);

}  // namespace insmc::mc
