#pragma once
/// Plots through gnuplot (Debian gnuplot-nox): insmc writes a self-contained
/// gnuplot script (data inline) beside its results, and gnuplot renders it
/// to SVG and PNG. A script the user can edit and run again
/// (`gnuplot envelope.gp`) is what a report needs; the drawing itself is
/// gnuplot's (axes, ticks, clipping, transparency, fonts), not insmc's.
#include <string>
#include <utility>
#include <vector>

namespace insmc::mc {

/// The program's name, looked up on PATH.
inline constexpr const char* kGnuplotProgram = "gnuplot";

/// Whether gnuplot can be run (on PATH and executable).
bool gnuplot_available();

/// The one-line reason plots cannot be made, naming the Debian package.
std::string gnuplot_missing_message();

/// Runs gnuplot on `script` and returns the bytes of `outputs` (the file
/// names the script's `set output` lines use), in that order. Script,
/// outputs and messages pass through in-memory files only: no temporary
/// file or folder exists that a killed run could leave. When gnuplot fails
/// or is killed: InputError (exit 2) with its first error line.
std::vector<std::string> render_gnuplot(const std::string& script, const std::vector<std::string>& outputs);

/// A figure's script: a head comment, the data blocks and settings, then
/// `body` drawn twice, to `<stem>.svg` and `<stem>.png` (width × height px).
struct FigureScript {
  std::string stem, title;
  std::string data_and_settings, body;
  int width = 1120, height = 800;
};
std::string figure_script(const FigureScript& figure);

/// A figure's script and what gnuplot drew from it.
struct RenderedFigure {
  std::string script, svg, png;
};
/// Runs `script` (from figure_script) and returns it with its SVG and PNG.
RenderedFigure render_figure(const std::string& stem, std::string script);

/// The names a figure adds to an output set: `<stem>.gp`, `.svg`, `.png`.
std::vector<std::string> figure_file_names(const std::string& stem);
/// Those files with their contents, in the same order.
std::vector<std::pair<std::string, std::string>> figure_files(const std::string& stem, RenderedFigure figure);

/// The plot command of a panel with nothing to draw: `note` in its middle
/// over fixed ranges that are valid on linear and log axes (gnuplot refuses
/// to autoscale a plot without a single point).
std::string empty_panel_plot(const std::string& note);

/// A string as a gnuplot string literal: double-quoted with \, " and `
/// escaped (gnuplot runs a backquoted command even inside double quotes),
/// line breaks as \n, other control bytes dropped.
std::string gnuplot_quote(const std::string& text);
/// A string on one gnuplot comment line: control bytes as blanks (a line
/// break would end the comment and start a command).
std::string gnuplot_comment(const std::string& text);

}  // namespace insmc::mc
