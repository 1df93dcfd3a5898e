// The truth simulator against the report's short-run form (3.29) — the
// `paper` level — term by term (docs/truth-vs-models.md): each uncertainty alone at its
// Table 3.1 bound, t = 1..90 min, continuous outputs, the truth by its odd
// part (r(x) − r(−x))/2 (first order; the even, second-order part is
// measured in tests/unit/lib/truth). The report keeps a term when it gives
// more than 1,300 ft after 1.5 h (§3.4, before (3.29)), so after the report's
// errors are corrected the truth must lie within 1,300 ft of (3.29) for every
// term. Where the printed form is further away the test names the reason
// and applies the correction (tables/notes/errata.md):
//  * g·MUY x, y, z: (3.13) lacks cos L0 — the printed columns × cos L0;
//  * ζ_rx, system 2: (2.17d) passes ζ_rx through the gyrocompass, (2.18a)
//    makes it a step of C'_x — the column of the step, which after switch-over
//    is system 1's (the navigation mode is the same for both systems);
//  * δf_y, system 2: the report's own cut is exceeded by the K4 bias terms
//    (3.29d) drops — the un-truncated closed form (3.27) for this column.
// Every other term must already be within the cut as printed, and every
// named term must be outside it as printed (else the attribution is stale).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "lib/propagation/closed_form.h"
#include "lib/propagation/k_matrices.h"
#include "lib/propagation/paper_model.h"
#include "lib/propagation/position_maps.h"
#include "lib/truth/simulator.h"
#include "lib/uncertainty/catalogue.h"
#include "lib/units/units.h"
#include "tests/unit/lib/propagation/test_support.h"

namespace insmc {
namespace {

constexpr double kCutFt = 1300.0;  // §3.4: terms under 1,300 ft after 1.5 h are dropped

using testing::minutes_1_to_90;

enum class Correction { kNone, kMuyCosL0, kZetaRxAsStep, kUntruncatedK4 };

Correction correction_for(System s, int i) {
  if (i >= uncertainty_slot::kGyroMuyDrift && i < uncertainty_slot::kGyroMuyDrift + 3) return Correction::kMuyCosL0;
  if (s == System::kGyrocompass && i == uncertainty_slot::kMisalignAlign + 0) return Correction::kZetaRxAsStep;
  if (s == System::kGyrocompass && i == uncertainty_slot::kAccelBias + 1) return Correction::kUntruncatedK4;
  return Correction::kNone;
}

const char* reason(Correction c) {
  switch (c) {
    case Correction::kNone: return "";
    case Correction::kMuyCosL0: return "(3.13) x cos L0";
    case Correction::kZetaRxAsStep: return "(2.18a) zeta_rx a step of C'_x";
    case Correction::kUntruncatedK4: return "(3.29d) cut exceeded: (3.27)";
  }
  return "";
}

TEST(TruthVsPaper, EveryTermWithinTheReportsCutOnceItsErrorsAreCorrected) {
  const ModelOptions o;
  const std::vector<double> times = minutes_1_to_90();
  const UncertaintyVector bounds = default_bounds();
  const auto paper1 = position_maps(System::kTheodolite, Fidelity::kPaper, o, times);
  std::printf("  max over 1-90 min of |truth - paper| at the Table 3.1 bound [ft]\n");
  for (System s : {System::kTheodolite, System::kGyrocompass}) {
    const auto paper = position_maps(s, Fidelity::kPaper, o, times);
    const KMatrices k = paper_k_matrices(s, o);
    const ShortRunMatrices m = paper_short_run_matrices(s, o);
    TruthOptions t;
    t.system = s;
    t.dv_pulse_mps = 0.0;
    for (int i = 0; i < uncertainty_slot::kDim; ++i) {
      if (bounds[i] == 0.0) continue;
      UncertaintyVector x = UncertaintyVector::Zero();
      x[i] = bounds[i];
      const TruthRun plus = simulate_truth(t, x, times), minus = simulate_truth(t, -x, times);
      const Correction c = correction_for(s, i);
      double raw_ft = 0.0, corrected_ft = 0.0;
      for (std::size_t n = 0; n < times.size(); ++n) {
        const Vec3 truth = 0.5 * (plus.position_error_ap_m[n] - minus.position_error_ap_m[n]);
        const Vec3 printed = paper[n] * x;
        Vec3 corrected = printed;
        switch (c) {
          case Correction::kNone: break;
          case Correction::kMuyCosL0: corrected = std::cos(o.latitude_rad) * printed; break;
          case Correction::kZetaRxAsStep: corrected = paper1[n] * x; break;
          case Correction::kUntruncatedK4:
            corrected = closed_form_position_map(k, m.initial_position_m, m.initial_velocity_mps, times[n], o, false) * x;
            break;
        }
        raw_ft = std::max(raw_ft, (truth - printed).norm() / kFtToM);
        corrected_ft = std::max(corrected_ft, (truth - corrected).norm() / kFtToM);
      }
      const std::string name(catalogue()[i].name);
      std::printf("  system %d %-22s printed %7.0f  corrected %7.0f  %s\n", system_number(s), name.c_str(), raw_ft,
                  corrected_ft, reason(c));
      EXPECT_LT(corrected_ft, kCutFt) << "system " << system_number(s) << " " << name;
      if (c != Correction::kNone) {
        EXPECT_GT(raw_ft, kCutFt) << "system " << system_number(s) << " " << name << ": attribution no longer needed";
      }
    }
  }
}

}  // namespace
}  // namespace insmc
