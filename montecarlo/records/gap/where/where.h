#pragma once
/// Where the gap lies (docs/gap-method.md): per group, shares by axis, stage and
/// window; the post-test innovations on the error's time functions; the
/// Allan deviation of the f residuals against the null's.
#include <functional>
#include <string>
#include <vector>

#include "montecarlo/records/gap/diagnosis_results.h"

namespace insmc::gap {

/// Per scatter and coherent group: power, the calibrated expected power, ℓ,
/// its p-value against the null files' |ℓ|, its share of Σ ℓ², and the
/// null files' ℓ band (quantiles α/2 and 1 − α/2).
std::vector<GroupResult> group_results(const Pooled& observed, const NullCalibration& calibration,
                                       const std::vector<LogRatios>& null_log_ratios, double alpha);

/// Each group's band of ℓ over null files of the sensor's own noise
/// through the import, read with the model's expectations
/// (null_file_log_ratios): where that noise alone puts the group.
void add_own_noise_bands(std::vector<GroupResult>& groups, const std::vector<LogRatios>& own_noise_log_ratios,
                         double alpha);

/// The groups where the data show less than the model (ℓ < 0) beyond what
/// the null files show there (lower-tail p < alpha), most negative first;
/// when none is beyond alone, the most negative one.
std::vector<std::string> pessimistic_groups(const std::vector<GroupResult>& groups,
                                            const std::vector<LogRatios>& null_log_ratios, double alpha);

/// Σ of the groups' shares under each key (key order of first appearance).
std::vector<Share> shares_by(const std::vector<GroupResult>& groups,
                             const std::function<std::string(const GroupResult&)>& key);

/// Per axis: the share of the post-test r innovation energy (normalized, all
/// runs) explained by, in this order, the Schuler terms sin/cos ω_s t, the
/// earth-rate terms sin/cos ω_ie t, then t², t³, t⁴ (each after the ones
/// before, least squares per run), and what is left ("rest").
std::vector<TimeFunctionShares> time_function_shares(const std::vector<const runs::Layout*>& layouts,
                                                     const std::vector<Eigen::VectorXd>& z,
                                                     const runs::RecordSite& site);

/// Per axis: Allan deviation of the f residuals (all f rows of a run in
/// time order, non-overlapping clusters of 1, 2, 4, ... rows) of the data
/// and of the null runs, with the null band: 5–95 % over null files of as
/// many runs as the data (consecutive null runs).
std::vector<AllanCurve> allan_curves(const std::vector<const runs::Layout*>& layouts,
                                     const std::vector<Eigen::VectorXd>& z,
                                     const std::vector<const Eigen::VectorXd*>& expected,
                                     const std::vector<const runs::Layout*>& null_layouts,
                                     const std::vector<Eigen::VectorXd>& null_z,
                                     const std::vector<const Eigen::VectorXd*>& null_expected,
                                     double filter_interval_s);

}  // namespace insmc::gap
