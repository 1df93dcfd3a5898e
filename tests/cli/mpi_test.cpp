// End-to-end tests of the MPI build (label mpi): `mpirun -n P insmc run`
// splits the blocks over the ranks and gives the bytes of a single-process
// run; a sweep too; an MPI run interrupted by SIGTERM (sent to mpirun, which
// passes it on to the ranks) resumes, on another number of ranks, to the
// bytes of an uninterrupted single-process run.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <csignal>

#include "tests/cli/checkpoint_helpers.h"
#include "tests/cli/run_program.h"

namespace insmc::testing {
namespace {

// --oversubscribe: more ranks than cores on a CI machine; root in containers.
std::string mpirun(int ranks, const std::string& mpirun_options = "") {
  return fmt::format("{} -n {} --oversubscribe --allow-run-as-root{} {}", INSMC_MPIEXEC, ranks, mpirun_options,
                     insmc_path());
}

const std::string kStudy = " --scheme none,5.2 --grid-step 30min --seed 23";

TEST(Mpi, RanksGiveTheBytesOfTheSingleProcessRun) {
  TempDir dir;
  const std::string study = " --samples 20487" + kStudy;  // 20 blocks and a partial one
  const auto single = run_insmc("run" + study + " --out " + dir.str() + "/single --format csv");
  ASSERT_EQ(single.exit_code, 0) << single.err;
  for (const int ranks : {2, 3}) {
    const std::string out = dir.str() + "/ranks" + std::to_string(ranks);
    const auto r = run_shell(mpirun(ranks) + " run" + study + " --out " + out + " --format csv");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(r.out, single.out) << "rank 0 alone prints, the same envelope";
    expect_same_envelopes(dir.path() / "single", out);
    const std::string run_json = read_file(std::filesystem::path(out) / "run.json");
    EXPECT_NE(run_json.find("\"ranks\": " + std::to_string(ranks)), std::string::npos) << run_json.substr(0, 400);
    EXPECT_NE(run_json.find("\"rank_sample_ranges\""), std::string::npos);
  }
  EXPECT_EQ(read_file(dir.path() / "single" / "run.json").find("\"ranks\""), std::string::npos);
}

TEST(Mpi, ASweepGivesTheBytesOfTheSingleProcessSweep) {
  const std::string sweep = " run --samples 5000 --scheme none --test-duration 10min,15min --format csv";
  const auto single = run_insmc(sweep);
  ASSERT_EQ(single.exit_code, 0) << single.err;
  const auto two = run_shell(mpirun(2) + sweep);
  ASSERT_EQ(two.exit_code, 0) << two.err;
  EXPECT_EQ(two.out, single.out);
}

TEST(Mpi, BadInputIsReportedOnceWithExitTwo) {
  const auto r = run_shell(mpirun(2) + " run --samples 0");
  EXPECT_EQ(r.exit_code, 2);
  const std::size_t at = r.err.find("insmc run: --samples = 0: must");
  EXPECT_NE(at, std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("insmc run:", at + 1), std::string::npos) << "rank 0 alone reports it\n" << r.err;
}

TEST(Mpi, ResumeAfterSigtermGivesTheBytesOfAnUninterruptedRun) {
  TempDir dir;
  const std::string cheap = " --scheme none --grid-step 30min --seed 23";
  // mpirun passes SIGTERM on to the ranks odls_base_sigkill_timeout seconds
  // after it gets it, and kills them as long again after that (docs/mpi.md).
  // At the default 1 s, the block in flight, the merge and the write lost the
  // race on a loaded 2-core machine; 5 s each way, and a run long enough to
  // be still under way when the ranks get the signal.
  constexpr int kSigkillTimeout_s = 5;
  const std::uint64_t samples = samples_for_seconds(cheap, 2.5 * kSigkillTimeout_s);
  const std::string study = fmt_samples(samples) + cheap;
  const std::string ck = dir.str() + "/run.ck";
  const std::string mpirun_options = fmt::format(" --mca odls_base_sigkill_timeout {}", kSigkillTimeout_s);
  BackgroundProgram run(mpirun(2, mpirun_options) + " run" + study + " --checkpoint " + ck +
                        " --checkpoint-every 0.2s --out " + dir.str() + "/killed");
  wait_for_a_periodic_checkpoint(ck);
  run.send(SIGTERM);
  const ProgramResult killed = run.wait();
  EXPECT_NE(killed.exit_code, 0) << killed.err;
  EXPECT_NE(killed.err.find("interrupted by SIGTERM: checkpoint " + ck + " written"), std::string::npos)
      << killed.err;
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "killed"));
  ASSERT_TRUE(std::filesystem::exists(ck));

  // Another split of what is left; fewer checkpoints (each is a collective
  // pause, slow with 3 ranks on 2 cores).
  const auto resumed = run_shell(mpirun(3) + " run --resume " + ck + " --checkpoint-every 10s --out " + dir.str() + "/killed");
  ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
  const std::uint64_t from = resumed_from_sample(dir.path() / "killed" / "run.json");
  EXPECT_GT(from, 0u);
  const auto whole = run_insmc("run" + study + " --out " + dir.str() + "/whole");
  ASSERT_EQ(whole.exit_code, 0) << whole.err;
  EXPECT_LT(from, samples) << "interrupted before the end";
  expect_same_envelopes(dir.path() / "whole", dir.path() / "killed");
}

}  // namespace
}  // namespace insmc::testing
