#pragma once
/// A number or nothing, in the 8 bytes of the number: "nothing" is a quiet
/// NaN, which no record holds (readers refuse non-finite values). Used
/// where millions are kept (record rows): std::optional<double> takes 16
/// bytes. The interface is std::optional's, for what insmc uses of it.
#include <Eigen/Core>
#include <cmath>
#include <limits>
#include <optional>

#include "lib/common/assert.h"

namespace insmc {

class OptionalValue {
 public:
  constexpr OptionalValue() = default;
  constexpr OptionalValue(std::nullopt_t) {}  // NOLINT: as std::optional
  OptionalValue(double v) : v_(v) { INSMC_ASSERT(!std::isnan(v), "an OptionalValue cannot hold NaN"); }  // NOLINT
  OptionalValue(const std::optional<double>& v) : OptionalValue(v ? OptionalValue(*v) : OptionalValue()) {}  // NOLINT

  bool has_value() const { return !std::isnan(v_); }
  explicit operator bool() const { return has_value(); }
  double operator*() const { return v_; }
  double& operator*() { return v_; }  ///< of a value that is there
  double value() const {
    INSMC_ASSERT(has_value(), "no value");
    return v_;
  }
  double value_or(double other) const { return has_value() ? v_ : other; }
  void reset() { v_ = kNothing; }
  operator std::optional<double>() const { return has_value() ? std::optional<double>(v_) : std::nullopt; }  // NOLINT

  friend bool operator==(const OptionalValue& a, const OptionalValue& b) {
    return a.has_value() == b.has_value() && (!a.has_value() || a.v_ == b.v_);
  }

 private:
  static constexpr double kNothing = std::numeric_limits<double>::quiet_NaN();
  double v_ = kNothing;
};

/// Three numbers or nothing, in 24 bytes (std::optional<Eigen::Vector3d>
/// takes 32): nothing is NaN in the first.
class OptionalVector3 {
 public:
  OptionalVector3() = default;
  OptionalVector3(std::nullopt_t) {}  // NOLINT: as std::optional
  template <class Derived>
  OptionalVector3(const Eigen::MatrixBase<Derived>& v) : v_(v) {  // NOLINT: any 3-vector expression
    INSMC_ASSERT(!std::isnan(v_[0]), "an OptionalVector3 cannot hold NaN");
  }

  bool has_value() const { return !std::isnan(v_[0]); }
  explicit operator bool() const { return has_value(); }
  const Eigen::Vector3d& operator*() const { return v_; }
  Eigen::Vector3d& operator*() { return v_; }
  const Eigen::Vector3d* operator->() const { return &v_; }
  Eigen::Vector3d* operator->() { return &v_; }
  const Eigen::Vector3d& value() const {
    INSMC_ASSERT(has_value(), "no value");
    return v_;
  }
  void reset() { v_[0] = std::numeric_limits<double>::quiet_NaN(); }

  friend bool operator==(const OptionalVector3& a, const OptionalVector3& b) {
    return a.has_value() == b.has_value() && (!a.has_value() || a.v_ == b.v_);
  }

 private:
  Eigen::Vector3d v_ = Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN());
};

}  // namespace insmc
