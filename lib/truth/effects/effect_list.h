// The built-in effects, one line each, in registry order (the order is
// each effect's index and its random stream, effect_stream(): add new ones
// at the end). Each NAME is defined in NAME.cpp of this folder as
// `const EffectDefinition& effects::NAME()`. Included with INSMC_EFFECT
// defined (effects.h, effect.cpp).
INSMC_EFFECT(quantization)
INSMC_EFFECT(sway)
INSMC_EFFECT(accel_bias_instability)
INSMC_EFFECT(gyro_drift_instability)
INSMC_EFFECT(angle_random_walk)
INSMC_EFFECT(velocity_random_walk)
INSMC_EFFECT(thermal_transient)
INSMC_EFFECT(anisoelastic_drift)
INSMC_EFFECT(scale_factor_nonlinearity)
INSMC_EFFECT(gravity_model)
INSMC_EFFECT(deflection_of_vertical)
INSMC_EFFECT(alignment_transient)
INSMC_EFFECT(switch_transient)
