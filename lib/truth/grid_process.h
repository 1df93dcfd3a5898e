#pragma once
/// A random 3-vector process realized on a fixed time grid t_k = k Δ,
/// k = 0 … n−1, piecewise linear between the nodes and constant after the
/// last. Stochastic effects are realized on this grid (Δ = the noise grid of
/// TruthOptions), independent of the integration step, so that halving the
/// step leaves the realization unchanged.
#include <vector>

#include "lib/frames/frames.h"

namespace insmc {

class GridProcess {
 public:
  GridProcess() = default;
  GridProcess(double grid_s, std::vector<Vec3> nodes);

  bool empty() const { return nodes_.empty(); }
  double grid_s() const { return grid_s_; }
  const std::vector<Vec3>& nodes() const { return nodes_; }

  /// p(t), t ≥ 0.
  Vec3 at(double t_s) const;

  /// ∫_{t0}^{t1} (t1 − s)^{n−1}/(n−1)! p(s) ds for n = 1, 2, 3 (the n-fold
  /// integrals of p from t0 to t1), exact for the piecewise-linear form
  /// (Simpson per grid segment: the integrands are at most cubic).
  struct Integrals {
    Vec3 first;   ///< ∫ p
    Vec3 second;  ///< ∫ (t1 − s) p(s) ds = ∫_{t0}^{t1} ∫_{t0}^{s} p
    Vec3 third;   ///< ∫ (t1 − s)²/2 p(s) ds
  };
  Integrals integrals(double t0_s, double t1_s) const;

  /// Adds `other` node by node (same grid; the shorter one is extended by
  /// its last value).
  void add(const GridProcess& other);

 private:
  double grid_s_ = 0.0;
  std::vector<Vec3> nodes_;
};

}  // namespace insmc

#include "lib/truth/noise.h"

namespace insmc {

/// First-order Gauss–Markov process, exact on the grid: p_0 ~ N(0, σ²)
/// (stationary), p_{k+1} = e^{−Δ/τ} p_k + σ sqrt(1 − e^{−2Δ/τ}) n_k, per
/// axis; correlation time τ. With τ = 0 instead a random walk from p_0 = 0
/// whose 1σ value after one hour is σ: p_{k+1} = p_k + σ sqrt(Δ/3600 s) n_k.
/// Covers [0, duration] (at least two nodes).
GridProcess make_gauss_markov(double sigma, double tau_s, double duration_s, double grid_s,
                              NormalDraws& draws);

/// Random walk from 0 whose 1σ value after one hour is `sigma_1h`, per axis
/// (the integral of white noise of density sigma_1h/sqrt(3600 s)).
GridProcess make_random_walk(double sigma_1h, double duration_s, double grid_s, NormalDraws& draws);

}  // namespace insmc
