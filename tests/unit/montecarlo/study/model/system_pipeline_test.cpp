// One system's sample path (montecarlo/study/model/system_pipeline.h): a
// sample's extended vector z is a function of the seed and its index alone,
// whichever block it is computed in and in either layout of the draws.
#include "montecarlo/study/model/system_pipeline.h"

#include <gtest/gtest.h>

#include <cstdint>

#include "montecarlo/study/sampler/sampler.h"

namespace insmc::mc {
namespace {

StudyConfig config_with_sway() {
  StudyConfig c;
  c.seed = 5;
  c.test.sway.velocity_rms_mps = 1e-3;  // the sway's own stream too
  return c;
}

Eigen::MatrixXd draws(const StudyConfig& c, std::uint64_t first, std::size_t n) {
  Eigen::MatrixXd x(uncertainty_slot::kDim, static_cast<Eigen::Index>(n));
  const Sampler sampler(c.uncertainties);
  for (std::size_t s = 0; s < n; ++s) x.col(static_cast<Eigen::Index>(s)) = sampler.draw(c.seed, first + s);
  return x;
}

TEST(SystemPipeline, ASamplesZDependsOnItsIndexNotOnItsBlock) {
  const StudyConfig c = config_with_sway();
  for (const System system : {System::kTheodolite, System::kGyrocompass}) {
    const SystemPipeline pipeline(c, system);
    Eigen::MatrixXd whole(z_slot::kDim, 8), tail(z_slot::kDim, 5);
    pipeline.extended_vectors(0, 8, draws(c, 0, 8), whole);
    pipeline.extended_vectors(3, 5, draws(c, 3, 5), tail);
    for (int s = 0; s < 5; ++s)
      for (int i = 0; i < z_slot::kDim; ++i) EXPECT_EQ(whole(i, 3 + s), tail(i, s)) << "sample " << 3 + s << " row " << i;
  }
}

TEST(SystemPipeline, TheDrawMajorFormGivesTheSameBits) {
  const StudyConfig c = config_with_sway();
  const std::size_t n = 6;
  const Eigen::MatrixXd x = draws(c, 10, n);
  std::vector<double> by_draw(uncertainty_slot::kDim * n);
  for (int j = 0; j < uncertainty_slot::kDim; ++j)
    for (std::size_t s = 0; s < n; ++s) by_draw[j * n + s] = x(j, static_cast<Eigen::Index>(s));
  for (const System system : {System::kTheodolite, System::kGyrocompass}) {
    const SystemPipeline pipeline(c, system);
    Eigen::MatrixXd columns(z_slot::kDim, static_cast<Eigen::Index>(n)), rows(static_cast<Eigen::Index>(n), z_slot::kDim);
    pipeline.extended_vectors(10, n, x, columns);
    pipeline.extended_vectors_by_draw(10, n, by_draw.data(), rows);
    for (std::size_t s = 0; s < n; ++s)
      for (int i = 0; i < z_slot::kDim; ++i)
        EXPECT_EQ(columns(i, static_cast<Eigen::Index>(s)), rows(static_cast<Eigen::Index>(s), i));
  }
}

TEST(SystemPipeline, AnotherSeedGivesAnotherTestRun) {
  StudyConfig a = config_with_sway(), b = a;
  b.seed = 6;
  const Eigen::MatrixXd x = draws(a, 0, 1);  // the same uncertainties: only the test run's own draws differ
  Eigen::MatrixXd za(z_slot::kDim, 1), zb(z_slot::kDim, 1);
  SystemPipeline(a, System::kTheodolite).extended_vectors(0, 1, x, za);
  SystemPipeline(b, System::kTheodolite).extended_vectors(0, 1, x, zb);
  EXPECT_NE(za, zb);
}

}  // namespace
}  // namespace insmc::mc
