#include "montecarlo/report/plot/matrix_figure.h"

#include <algorithm>
#include <numeric>

#include <fmt/format.h>

#include "montecarlo/report/plot/palette.h"

namespace insmc::mc {
namespace {

/// `set xtics ("a" 0, "b" 1, ...)`.
std::string tic_labels(const std::vector<std::string>& names) {
  std::string out = "(";
  for (std::size_t i = 0; i < names.size(); ++i)
    out += fmt::format("{}{} {}", i ? ", " : "", gnuplot_quote(names[i]), i);
  return out + ")";
}

std::string matrix_figure_script(const MatrixFigure& f) {
  const int rows = static_cast<int>(f.rows.size()), columns = static_cast<int>(f.columns.size());
  FigureScript script{f.stem, f.title, "", "", std::max(700, 260 + 46 * columns), std::max(400, 230 + 30 * rows)};
  // One line per non-empty cell: column, row, share of the row, count.
  std::string& data = script.data_and_settings;
  data += "$cells << EOD\n";
  for (int r = 0; r < rows; ++r) {
    const std::vector<int>& row = f.counts[static_cast<std::size_t>(r)];
    const int total = std::accumulate(row.begin(), row.end(), 0);
    for (int c = 0; c < columns && c < static_cast<int>(row.size()); ++c)
      if (row[static_cast<std::size_t>(c)] > 0)
        data += fmt::format("{} {} {} {}\n", c, r, plot_number(double(row[static_cast<std::size_t>(c)]) / total),
                            row[static_cast<std::size_t>(c)]);
  }
  data += "EOD\n";
  data += fmt::format("set xrange [-0.5:{}]\nset yrange [{}:-0.5]\n", columns - 0.5, rows - 0.5);
  data += fmt::format("set xtics {} rotate by -40 left nomirror font \",9\"\nset ytics {} nomirror font \",9\"\n",
                      tic_labels(f.columns), tic_labels(f.rows));
  data += fmt::format("set xlabel {}\nset ylabel {}\n", gnuplot_quote(f.x_label), gnuplot_quote(f.y_label));
  data += fmt::format("set palette defined (0 \"#ffffff\", 1 \"{}\")\nset cbrange [0:1]\n", palette_colour(0));
  data += "set cblabel \"share of the row's files\"\nunset key\nset grid front noxtics noytics\n";
  script.body = fmt::format(
      "set title {}\n"
      "plot $cells using 1:2:(0.5):(0.5):3 with boxxyerror fillcolor palette fillstyle solid noborder, \\\n"
      "     $cells using 1:2:(sprintf(\"%d\", $4)) with labels font \",9\"\n",
      gnuplot_quote(f.title));
  return figure_script(script);
}

}  // namespace

RenderedFigure render_matrix_figure(const MatrixFigure& f) { return render_figure(f.stem, matrix_figure_script(f)); }

}  // namespace insmc::mc
