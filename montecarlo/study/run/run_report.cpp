#include "montecarlo/study/run/run_report.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>

#include "montecarlo/report/csv.h"
#include "montecarlo/report/plot/panel_figure.h"

namespace insmc::mc {

ReportOutline envelope_report_outline() {
  return {"run", {"envelope.csv", "envelope_grid.csv", "envelope.md", "run.json"}, {"envelope"}};
}

namespace {

/// run.json: the settings, the time taken, where a resumed run started, the
/// ranks' shares and the envelope.
Json run_json(const StudyConfig& config, const RunFacts& facts, const Json& envelope) {
  Json run = Json::object();
  run["settings"] = facts.settings;
  run["elapsed_s"] = facts.elapsed_s;
  run["resumed_from_sample"] = facts.resumed_from_sample;
  if (facts.ranks > 0) {
    run["ranks"] = facts.ranks;
    Json shares = Json::array();  // per rank: its [first, end) sample ranges in this run
    for (const BlockSet& share : facts.shares) {
      Json ranges = Json::array();
      for (const BlockRange& r : share) {
        Json range = Json::array();
        range.push_back(std::min(config.samples, r.begin * kBlockSize));
        range.push_back(std::min(config.samples, r.end * kBlockSize));
        ranges.push_back(range);
      }
      shares.push_back(ranges);
    }
    run["rank_sample_ranges"] = shares;
  }
  run["envelope"] = envelope;
  return run;
}

}  // namespace

Report envelope_report(const StudyConfig& config, EnvelopeFiles files, const RunFacts& facts) {
  const std::string head = fmt::format("insmc run: {} samples, seed {}, fidelity {}, {:.2f} s\n\n", config.samples,
                                       config.seed, to_string(config.fidelity), facts.elapsed_s);
  std::string run_json_text = run_json(config, facts, files.envelope_json).dump();
  Report report(envelope_report_outline());
  report.file("envelope.csv", std::move(files.envelope_csv))
      .file("envelope_grid.csv", std::move(files.envelope_grid_csv))
      .file("envelope.md", std::move(files.envelope_md))
      .file("run.json", std::move(run_json_text))
      .figure("envelope", [plot = std::move(files.envelope_plot)] { return render_panel_figure(plot); })
      .shown(ReportFormat::kMarkdown, head + files.full_text)
      .shown_file(ReportFormat::kCsv, "envelope.csv")
      .shown_file(ReportFormat::kJson, "run.json")
      .summary({head + files.summary_text,
                [](const std::optional<std::string>& out) {
                  return full_tables_line("run", {"envelope.md", "envelope.csv"}, out);
                }});
  return report;
}

ReportOutline sweep_report_outline() { return {"run", {"sweep.csv", "sweep.md", "sweep.json"}, {"sweep"}}; }

Report sweep_report(const StudyConfig& config, SweepFiles files, const Json& settings, const SweepFacts& facts,
                    LengthUnit unit) {
  files.json["settings"] = settings;
  const std::string json = files.json.dump();
  const std::string summary = fmt::format(
      "insmc run: sweep of {} over {} points, {} samples each, seed {}, fidelity {}, {:.2f} s\n\n"
      "Horizontal RMS position error [{}] ± half its {}% interval at each report time.\n\n{}",
      fmt::join(facts.swept, " × "), facts.points, config.samples, config.seed, to_string(config.fidelity),
      facts.elapsed_s, length_suffix(unit), format_number(100 * config.confidence), files.summary_md);
  Report report(sweep_report_outline());
  report.file("sweep.csv", std::move(files.sweep_csv))
      .file("sweep.md", files.summary_md)
      .file("sweep.json", std::move(json))
      .figure("sweep", [plot = std::move(files.plot)] { return render_panel_figure(plot); })
      .shown(ReportFormat::kMarkdown, summary)  // a sweep's summary is its whole table
      .shown_file(ReportFormat::kCsv, "sweep.csv")
      .shown_file(ReportFormat::kJson, "sweep.json")
      .summary({summary,
                [](const std::optional<std::string>& out) {
                  return out ? fmt::format("Files written in {}: sweep.csv (every axis and time), sweep.md, sweep.json, "
                                           "sweep.gp, sweep.svg, sweep.png\n",
                                           *out)
                             : std::string("Every axis and time: --format csv, or --out DIR for sweep.csv, sweep.md, "
                                           "sweep.json and the figure\n");
                }});
  return report;
}

}  // namespace insmc::mc
