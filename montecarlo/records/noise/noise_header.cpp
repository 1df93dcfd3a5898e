#include "montecarlo/records/noise/noise_header.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include "lib/common/input_error.h"
#include "lib/common/input_text.h"
#include "lib/noise/noise_analysis.h"
#include "lib/noise/noise_budget.h"
#include "lib/records/import_keys.h"
#include "lib/units/units.h"

namespace insmc::noise {

void write_noise_header(const std::vector<ImuSamples>& samples, RecordHeader& header) {
  NoiseAnalysis a;
  try {
    for (const ImuSamples& s : samples)
      if (s.size() < 300) throw InputError("--input", s.source, "fewer than 300 samples");
    a = analyse_noise(make_recording(samples));
  } catch (const std::exception& e) {
    header.set(import_keys::kNoise, one_line_value(std::string("skipped: ") + e.what()));
    return;
  }
  header.set(import_keys::kNoise, std::string("on"));
  // A value the fit could not give (not finite) is left out, as an absent
  // term: the record reader refuses a raw-stage key that is not a
  // non-negative number.
  const auto put = [&header](const std::string& key, double v) {
    if (std::isfinite(v) && v >= 0) header.set(key, v);
  };
  for (const ChannelNoise& ch : a.channels) {
    const auto key = [&ch](std::string_view what) { return import_keys::noise_key(ch.name, what); };
    for (const TermFit& t : ch.fit.terms) {
      const std::string term(term_name(t.term, ch.kind));
      put(key(term + "_si"), t.value_si);
      put(key(term + "_lower_si"), t.lower_si);
      put(key(term + "_upper_si"), t.upper_si);
    }
    if (ch.fit.model[NoiseTerm::kGaussMarkov] > 0) put(key("correlation_time_s"), ch.fit.model.correlation_time_s);
    put(key("equivalent_si"), equivalent_constant(ch.fit.model));
    // What the Allan deviation allows each term at most, selected or not
    // (σ(τ)² ≥ each term's own σ²(τ) at every τ; upper interval ends):
    // white N ≤ min σ⁺√τ (after 1 h: × √3600 s), wander ≤ the larger of
    // B ≤ min σ⁺/0.664 and K after 1 h ≤ min σ⁺ √(3/τ) √3600 s,
    // quantization Q ≤ min σ⁺ τ/√3.
    double white = std::numeric_limits<double>::infinity(), flat = white, walk = white, quant = white;
    for (const AllanRow& r : ch.allan) {
      quant = std::min(quant, r.upper * r.tau_s / std::sqrt(3.0));  // σ² = 3Q²/τ²
      white = std::min(white, r.upper * std::sqrt(r.tau_s));
      flat = std::min(flat, r.upper / std::sqrt(2 * std::numbers::ln2 / std::numbers::pi));
      walk = std::min(walk, r.upper * std::sqrt(3 / r.tau_s));
    }
    if (std::isfinite(white)) {
      put(key("white_1h_bound_si"), white * std::sqrt(kHourToS));
      put(key("wander_bound_si"), std::max(flat, walk * std::sqrt(kHourToS)));
      put(key("quantization_bound_si"), quant);
    }
    header.set(key("warm_up_excluded"), ch.first_part_excluded ? 1.0 : 0.0);
  }
  put(std::string(import_keys::kNoiseMaskedS), static_cast<double>(a.mask.masked_samples) * a.dt_s);
  put(std::string(import_keys::kNoiseSampleIntervalS), a.dt_s);
}

}  // namespace insmc::noise
