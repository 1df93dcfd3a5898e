#pragma once
/// The diagnosis' two figures (docs/gap-method.md §3), drawn by gnuplot
/// (montecarlo/report/plot/): the groups' ln ratios by name against the null
/// files' band, and the Allan deviation of the f residuals on log–log axes
/// against the null runs' band, in µg.
#include "montecarlo/records/gap/diagnosis.h"
#include "montecarlo/report/plot/gnuplot.h"
#include "montecarlo/report/plot/panel_figure.h"

namespace insmc::gap {

/// `gap_groups`: one slot per group, the null files' band as a grey box,
/// the observed ln ratio as a stem coloured by where it lies (legend).
/// Its gnuplot script (mc::render_figure draws it).
std::string groups_figure_script(const Diagnosis& d);
/// `gap_allan`: per axis, the data (solid, points) and the null runs
/// (dashed, shaded 5–95 % band).
mc::PanelFigure allan_figure(const Diagnosis& d);

}  // namespace insmc::gap
