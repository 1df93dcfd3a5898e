#include "lib/truth/simulator.h"

#include <gtest/gtest.h>
#include <chrono>
#include <iostream>

#include "lib/propagation/position_maps.h"
#include "lib/uncertainty/catalogue.h"

namespace insmc {
namespace {

TEST(Explore, OddEven) {
  for (System s : {System::kTheodolite, System::kGyrocompass}) {
    TruthOptions o;
    o.system = s;
    o.dv_pulse_mps = 0;
    std::vector<double> lt;
    for (int m = 1; m <= 90; ++m) lt.push_back(60.0 * m);
    auto maps = position_maps(s, Fidelity::kLinear, o.model, lt);
    const UncertaintyVector b = default_bounds();
    for (int i = 0; i < ux::kDim; ++i) {
      UncertaintyVector xi = UncertaintyVector::Zero();
      xi[i] = b[i];
      auto rp = simulate_truth(o, xi, lt);
      auto rm = simulate_truth(o, -xi, lt);
      double raw_abs = 0, raw_rel = 0, odd_abs = 0, odd_rel = 0, even = 0, lin_max = 0, raw_ex = -9, odd_ex = -9;
      for (size_t k = 0; k < lt.size(); ++k) {
        Vec3 lin = maps[k] * xi;
        Vec3 raw = rp.position_error_ap_m[k] - lin;
        Vec3 odd = 0.5 * (rp.position_error_ap_m[k] - rm.position_error_ap_m[k]) - lin;
        Vec3 ev = 0.5 * (rp.position_error_ap_m[k] + rm.position_error_ap_m[k]);
        double n = std::max(lin.norm(), 1.0);
        raw_abs = std::max(raw_abs, raw.norm()); raw_rel = std::max(raw_rel, raw.norm() / n);
        odd_abs = std::max(odd_abs, odd.norm()); odd_rel = std::max(odd_rel, odd.norm() / n);
        raw_ex = std::max(raw_ex, raw.norm() - 0.01 * lin.norm() - 1);
        odd_ex = std::max(odd_ex, odd.norm() - 0.01 * lin.norm() - 1);
        even = std::max(even, ev.norm()); lin_max = std::max(lin_max, lin.norm());
      }
      printf("sys%d %-22s lin %9.1f raw %8.3f (%.4f) ex %7.2f | odd %8.3f (%.4f) ex %7.2f | even %8.3f\n",
             int(s), std::string(catalogue()[i].name).c_str(), lin_max, raw_abs, raw_rel, raw_ex, odd_abs, odd_rel, odd_ex, even);
    }
  }
}

}  // namespace
}  // namespace insmc
