// The built-in candidates, one line each, in registry order (equal held-out
// gaps keep this order in the ranking: a stable sort, so another order
// changes the report). Each NAME is defined in NAME.cpp of this folder as
// `Candidate candidates::NAME()`, named as the truth simulator's effect it
// stands for (lib/truth/effects/effect_list.h), plus the model-level
// `bounds` and `nonlinearity`. Included with INSMC_CANDIDATE defined
// (definitions.h, registry.cpp).
INSMC_CANDIDATE(bounds)
INSMC_CANDIDATE(quantization)
INSMC_CANDIDATE(sway)
INSMC_CANDIDATE(accel_bias_instability)
INSMC_CANDIDATE(gyro_drift_instability)
INSMC_CANDIDATE(angle_random_walk)
INSMC_CANDIDATE(velocity_random_walk)
INSMC_CANDIDATE(thermal_transient)
INSMC_CANDIDATE(anisoelastic_drift)
INSMC_CANDIDATE(scale_factor_nonlinearity)
INSMC_CANDIDATE(deflection_of_vertical)
INSMC_CANDIDATE(gravity_model)
INSMC_CANDIDATE(alignment_transient)
INSMC_CANDIDATE(switch_transient)
INSMC_CANDIDATE(nonlinearity)
