#include "montecarlo/study/write/envelope_summary.h"

#include <algorithm>
#include <optional>
#include <string_view>
#include <fmt/format.h>
#include <fmt/ranges.h>

#include "montecarlo/report/csv.h"
#include "montecarlo/report/interval_format.h"
#include "montecarlo/report/markdown.h"

namespace insmc::mc {
namespace {

// The linear covariance is exact for its model; five figures resolve it to
// the metre or better at the report times without a wall of digits.
constexpr int kExactFigures = 5;

std::string cell(const HorizontalPoint& p) {
  return p.half_width ? format_with_interval(p.rms, *p.half_width) : format_significant(p.rms, kExactFigures);
}

/// An accuracy figure: with its interval (Monte Carlo), or exact (half-width 0: the covariance level).
std::string figure(double value, double half) {
  return half > 0 ? format_with_interval(value, half) : format_significant(value, kExactFigures);
}

/// Where t = 0 is, for a clock_of() name.
std::string clock_phrase(const std::string& clock) {
  return clock == "switchover" ? "switch-over" : clock == "realignment" ? "new switch-over"
                                             : clock == "test_end"   ? "test end" : clock;
}

/// The caption's width on a terminal (the table below it is as wide as its columns).
constexpr std::size_t kSummaryWidth = 100;

/// `text` broken at spaces into lines of at most `width` characters (a word
/// longer than that stands alone); width counts UTF-8 code points.
std::string wrap_words(const std::string& text, std::size_t width) {
  const auto points = [](std::string_view s) {
    return static_cast<std::size_t>(std::count_if(s.begin(), s.end(), [](char ch) { return (ch & 0xC0) != 0x80; }));
  };
  std::string out, line;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t end = std::min(text.find(' ', start), text.size());
    const std::string_view word(text.data() + start, end - start);
    if (!line.empty() && points(line) + 1 + points(word) > width) {
      out += line + "\n";
      line.clear();
    }
    if (!line.empty()) line += ' ';
    line += word;
    start = end + 1;
  }
  return out + line;
}

}  // namespace

std::string render_horizontal_summary(const std::vector<HorizontalPoint>& points, const std::string& caption) {
  std::vector<double> times;
  struct Row {
    const HorizontalPoint* first;
    std::vector<std::string> cells;
  };
  std::vector<Row> rows;
  for (const HorizontalPoint& p : points) {
    if (std::find(times.begin(), times.end(), p.t_min) == times.end()) times.push_back(p.t_min);
    const auto row = std::find_if(rows.begin(), rows.end(), [&](const Row& r) {
      return r.first->scheme == p.scheme && r.first->system == p.system;
    });
    if (row == rows.end()) rows.push_back({&p, {}});
  }
  // The accuracy columns: at the latest time whose points carry metrics.
  std::optional<double> accuracy_t;
  for (const HorizontalPoint& p : points)
    if (p.accuracy && (!accuracy_t || p.t_min > *accuracy_t)) accuracy_t = p.t_min;
  // Each scheme's clock goes in a line under the caption, not in a column:
  // the table stays near a terminal's width.
  std::vector<std::pair<std::string, std::vector<std::string>>> clocks;  // clock, its schemes
  for (const Row& r : rows) {
    auto c = std::find_if(clocks.begin(), clocks.end(), [&](const auto& e) { return e.first == r.first->clock; });
    if (c == clocks.end()) c = clocks.insert(clocks.end(), {r.first->clock, {}});
    if (std::find(c->second.begin(), c->second.end(), r.first->scheme) == c->second.end())
      c->second.push_back(r.first->scheme);
  }
  std::string clock_line = "t = 0:";
  for (std::size_t i = 0; i < clocks.size(); ++i)
    clock_line += fmt::format("{} {} ({})", i ? ";" : "", clock_phrase(clocks[i].first),
                              fmt::format("{}", fmt::join(clocks[i].second, ", ")));
  std::vector<std::string> header = {"scheme", "sys"};
  for (double t : times) header.push_back(fmt::format("{} min", format_number(t)));
  if (accuracy_t) {
    header.push_back(fmt::format("CEP50 {}", format_number(*accuracy_t)));
    header.push_back(fmt::format("2DRMS {}", format_number(*accuracy_t)));
    header.emplace_back("CEP/t nmi/h");
  }
  header.emplace_back("ready");
  Table table(header);
  for (Row& r : rows) {
    std::vector<std::string> cells = {r.first->scheme, std::to_string(r.first->system)};
    const auto at = [&](double t) {
      const auto p = std::find_if(points.begin(), points.end(), [&](const HorizontalPoint& q) {
        return q.scheme == r.first->scheme && q.system == r.first->system && q.t_min == t;
      });
      return p == points.end() ? nullptr : &*p;
    };
    for (double t : times) {
      const HorizontalPoint* p = at(t);
      cells.push_back(p ? cell(*p) : "");
    }
    if (accuracy_t) {
      const HorizontalPoint* p = at(*accuracy_t);
      const std::optional<AccuracyFigures> a = p ? p->accuracy : std::nullopt;
      cells.push_back(a ? figure(a->cep50, a->cep50_half) : "");
      cells.push_back(a ? figure(a->drms2, a->drms2_half) : "");
      cells.push_back(a ? figure(a->rate_nmiph, a->rate_half_nmiph) : "");
    }
    cells.push_back(format_number(r.first->ready_min));
    table.add_row(std::move(cells));
  }
  return fmt::format("{}\n{}\n\n{}", wrap_words(caption, kSummaryWidth), wrap_words(clock_line + ".", kSummaryWidth),
                     render_markdown(table));
}

}  // namespace insmc::mc
