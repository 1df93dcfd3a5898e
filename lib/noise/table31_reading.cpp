#include "lib/noise/table31_reading.h"

#include <cmath>

#include "lib/noise/noise_budget.h"

namespace insmc::noise {

Table31Reading table31_reading(const ChannelNoise& ch) {
  Table31Reading out;
  const double ts = schuler_period_s();
  out.extrapolation = ch.longest_stretch_s > 0 ? ts / ch.longest_stretch_s : INFINITY;
  out.extrapolated = out.extrapolation > 1;
  if (ch.stuck) {
    out.source = Table31Source::kStuck;
    return out;
  }
  double rss = 0, biggest = -1;
  const auto add = [&](NoiseTerm t, double value_si, double tc) {
    const double e = equivalent_constant(t, value_si, tc);
    rss += e * e;
    if (e > biggest) biggest = e, out.largest_term = std::string(term_name(t, ch.kind));
  };
  if (ch.fit.fits) {
    out.source = Table31Source::kFit;
    for (const TermFit& t : ch.fit.terms) add(t.term, t.value_si, ch.fit.model.correlation_time_s);
  } else {
    out.source = Table31Source::kSlopeReadings;
    const SlopeReadings& r = ch.readings;
    if (r.white.found) add(NoiseTerm::kWhiteRate, r.white.value_si, 0);
    if (r.instability.found) add(NoiseTerm::kBiasInstability, r.instability.value_si, 0);
    if (r.walk.found) add(NoiseTerm::kRateRandomWalk, r.walk.value_si, 0);
  }
  out.equivalent_si = std::sqrt(rss);
  out.ratio = out.equivalent_si / table31_bound_si(ch.kind);
  return out;
}

std::string_view table31_source_text(Table31Source s) {
  switch (s) {
    case Table31Source::kFit: return "the fitted model (it passes its fit test)";
    case Table31Source::kSlopeReadings: return "the IEEE slope readings (no fitted model passes its fit test)";
    case Table31Source::kStuck: return "none: the output never changes";
  }
  return "";
}

}  // namespace insmc::noise
