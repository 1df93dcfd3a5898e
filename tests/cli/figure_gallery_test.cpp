// Every figure every command writes, as scripts/figures.sh makes the
// gallery of docs/figures.md: each SVG has its panels' frames with data
// inside them, and no text that runs past the canvas (each text's extent
// estimated from its font size, anchor and rotation); each PNG is a PNG of
// the SVG's size.
#include <gtest/gtest-spi.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <numbers>
#include <string>
#include <vector>

#include "tests/cli/run_program.h"
#include "tests/cli/svg_figure.h"

namespace insmc::testing {
namespace {

/// The figures scripts/figures.sh writes: every figure of every command.
const char* const kFigures[] = {"envelope", "sweep",   "fig3_2",    "budget", "rank",         "compensate",
                                "gap_groups", "gap_allan", "confusion", "allan",  "stationarity"};

struct Canvas {
  double width = 0, height = 0;
};

Canvas canvas_of(const std::string& svg) {
  const auto number_after = [&](const std::string& key) {
    const std::size_t at = svg.find(key);
    return at == std::string::npos ? 0.0 : std::strtod(svg.c_str() + at + key.size(), nullptr);
  };
  return {number_after(" width=\""), number_after(" height=\"")};
}

/// A text gnuplot drew: its anchor point, rotation (degrees, clockwise as
/// SVG's), font size, anchoring and characters.
struct Text {
  double x = 0, y = 0, angle = 0, size = 0;
  std::string anchor, text;
};

std::size_t characters(const std::string& utf8) {
  std::size_t n = 0;
  for (const char c : utf8) n += (static_cast<unsigned char>(c) & 0xC0) != 0x80;
  return n;
}

std::vector<Text> texts_of(const std::string& svg) {
  std::vector<Text> out;
  const std::string open = "<g transform=\"translate(";
  for (std::size_t at = svg.find(open); at != std::string::npos; at = svg.find(open, at + 1)) {
    const std::size_t tag_end = svg.find('>', at);
    const std::string tag = svg.substr(at, tag_end - at);
    const std::size_t text_at = svg.find("<text", tag_end), close_at = svg.find("</g>", tag_end);
    if (text_at == std::string::npos || text_at > close_at) continue;
    Text t;
    const char* p = tag.c_str() + open.size();
    char* end = nullptr;
    t.x = std::strtod(p, &end);
    t.y = std::strtod(end + 1, nullptr);
    if (const std::size_t r = tag.find("rotate("); r != std::string::npos) t.angle = std::strtod(tag.c_str() + r + 7, nullptr);
    if (const std::size_t s = tag.find("font-size=\""); s != std::string::npos) t.size = std::strtod(tag.c_str() + s + 11, nullptr);
    const std::size_t a = tag.find("text-anchor=\"");
    t.anchor = a == std::string::npos ? "start" : tag.substr(a + 13, tag.find('"', a + 13) - a - 13);
    // Each line of the text (a <tspan> per line when it has several): the longest counts.
    std::string body = svg.substr(text_at, close_at - text_at), line;
    bool in_tag = false;
    for (std::size_t i = 0; i < body.size(); ++i) {
      if (body[i] == '<') {
        in_tag = true;
        if (body.compare(i, 6, "<tspan") == 0 || body.compare(i, 5, "<text") == 0) {
          if (characters(line) > characters(t.text)) t.text = line;
          line.clear();
        }
        continue;
      }
      if (body[i] == '>') {
        in_tag = false;
        continue;
      }
      if (!in_tag && body[i] != '\n' && body[i] != '\t') line += body[i];
    }
    if (characters(line) > characters(t.text)) t.text = line;
    while (!t.text.empty() && t.text.back() == ' ') t.text.pop_back();
    if (!t.text.empty()) out.push_back(t);
  }
  return out;
}

/// The text's two ends along its baseline, from the anchor, at 0.6 em a
/// character (sans at its widest on average; digits and capitals 0.55-0.7).
void expect_inside_canvas(const Text& t, const Canvas& c, const std::string& figure) {
  const double length = 0.6 * t.size * static_cast<double>(characters(t.text));
  const double from = t.anchor == "middle" ? -length / 2 : t.anchor == "end" ? -length : 0;
  const double rad = t.angle * std::numbers::pi / 180;
  for (const double along : {from, from + length}) {
    const double x = t.x + along * std::cos(rad), y = t.y + along * std::sin(rad);
    EXPECT_GE(x, -1) << figure << ": \"" << t.text << "\" starts left of the canvas";
    EXPECT_LE(x, c.width + 1) << figure << ": \"" << t.text << "\" runs past the canvas's right edge";
    // The baseline: the letters stand 0.75 em above it.
    EXPECT_GE(y - 0.75 * t.size * std::abs(std::cos(rad)), -1) << figure << ": \"" << t.text << "\" above the canvas";
    EXPECT_LE(y, c.height + 1) << figure << ": \"" << t.text << "\" below the canvas";
  }
}

TEST(FigureGallery, EveryFigureOfEveryCommandHasItsDataInsideTheFramesAndNoTextOutside) {
  TempDir out;
  const char* src = std::getenv("INSMC_SOURCE_DIR");
  ASSERT_NE(src, nullptr);
  const ProgramResult r = run_shell("bash " + std::string(src) + "/scripts/figures.sh " + out.str() + " " +
                                    insmc_path() + " --svg");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const char* name : kFigures) {
    SCOPED_TRACE(name);
    const std::string svg = read_file(out.path() / (std::string(name) + ".svg"));
    const std::string png = read_file(out.path() / (std::string(name) + ".png"));
    ASSERT_GE(png.size(), 1000u);
    ASSERT_EQ(png.substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8));
    // IHDR: width and height, big-endian, at bytes 16 and 20.
    const auto be32 = [&](std::size_t at) {
      return (static_cast<unsigned char>(png[at]) << 24) | (static_cast<unsigned char>(png[at + 1]) << 16) |
             (static_cast<unsigned char>(png[at + 2]) << 8) | static_cast<unsigned char>(png[at + 3]);
    };
    const Canvas c = canvas_of(svg);
    EXPECT_EQ(be32(16), static_cast<unsigned>(c.width));
    EXPECT_EQ(be32(20), static_cast<unsigned>(c.height));
    // Fit for an A4 page: no taller than about 1.5 times its width.
    EXPECT_LE(c.height, 1.5 * c.width);
    const std::vector<Text> texts = texts_of(svg);
    EXPECT_GE(texts.size(), 5u);  // title, axis labels, ticks
    for (const Text& t : texts) expect_inside_canvas(t, c, name);
    EXPECT_GE(plotted_points_inside(svg, name), 2u) << "no data inside the frames";
  }
}

// The test's own eye: a title longer than the canvas is caught.
TEST(FigureGallery, ATextPastTheCanvasIsCaught) {
  const Canvas c{400, 300};
  const Text inside{200, 20, 0, 14, "middle", "short title"};
  const Text past{200, 20, 0, 14, "start", std::string(60, 'x')};
  expect_inside_canvas(inside, c, "inside");
  EXPECT_NONFATAL_FAILURE(expect_inside_canvas(past, c, "past"), "runs past the canvas's right edge");
}

}  // namespace
}  // namespace insmc::testing
