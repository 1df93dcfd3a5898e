#pragma once
/// The split of Table 3.1's ζ (< 1 mrad, the alignment electronics'
/// misalignment) and ∂f (< 0.1 mg, the accelerometer bias change at the
/// switch-over) into a part constant from one alignment to the next
/// (misalign_const, bias_change_const) and a part drawn anew at each
/// alignment (misalign_align, bias_change_align). The report gives the totals
/// only; how much is redrawn is the project's choice (catalogue.cpp: half and
/// half) and decides what a realignment (5.1.x) or a test-run estimate
/// carried into flight can remove, so it is a study parameter
/// (`--random-fraction`, sweepable).
#include "lib/uncertainty/uncertainty_model.h"

namespace insmc {

inline constexpr double kDefaultRandomFraction = 0.5;

/// Sets the bounds: the redrawn parts to F times the totals, the constant
/// parts to (1 − F) times them. F in [0, 1] (checked by the caller).
void apply_random_fraction(UncertaintyModel& model, double fraction);

}  // namespace insmc
