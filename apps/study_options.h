#pragma once
/// The uncertainty options shared by params, run, covariance and check:
/// repeated --bound NAME=VALUE and --dist NAME=SPEC, applied in order.
#include "apps/cli_common.h"
#include "lib/uncertainty/uncertainty_model.h"

namespace insmc::app {

po::options_description uncertainty_options_description();

/// The model of Table 3.1 with every --bound and --dist applied in the order
/// given (bounds first in command-line order, then distributions).
UncertaintyModel read_uncertainty_model(const po::variables_map& vm);

}  // namespace insmc::app

#include "montecarlo/study/model/study_config.h"
#include "montecarlo/study/write/study_writer.h"

namespace insmc::app {

/// Options of run, covariance and check: the study definition.
po::options_description study_options_description(bool monte_carlo);

/// Builds and validates the StudyConfig (throws InputError).
mc::StudyConfig read_study_config(const po::variables_map& vm, bool monte_carlo);

/// The test-run, measurement and realignment options (shared by run,
/// covariance, check).
po::options_description test_run_options_description();
TestRunOptions read_test_run_options(const po::variables_map& vm);

/// For commands on the exact covariance of the paper and linear levels
/// (covariance, rank): refuses --fidelity truth (`why_not_truth` says why)
/// and the truth level's time-domain alignment options, which would change
/// nothing there.
void refuse_truth_level_options(const po::variables_map& vm, const std::string& command,
                                const std::string& why_not_truth);

/// --units si|paper.
mc::LengthUnit read_length_unit(const po::variables_map& vm);

/// Splits a comma list ("1,2", "none,5.2").
std::vector<std::string> split_commas(const std::string& text);

/// --random-fraction's value (lib/uncertainty/random_fraction.h), in [0, 1].
double parse_random_fraction(const std::string& text);

}  // namespace insmc::app
