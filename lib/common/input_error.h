#pragma once
/// Bad user input (CLI, INI, record files). Raised only by parsing and
/// validation code; caught only in apps/insmc.cpp, which prints the one-line
/// message and exits with code 2.
#include <stdexcept>
#include <string>

namespace insmc {

class InputError : public std::runtime_error {
 public:
  /// `field = value: allowed` (e.g. "samples = 0: must be >= 2").
  InputError(std::string field, std::string value, std::string allowed)
      : std::runtime_error(field + " = " + value + ": " + allowed),
        field_(std::move(field)), value_(std::move(value)), allowed_(std::move(allowed)) {}

  /// A message that does not fit the field/value/allowed shape (e.g. a
  /// record-file error that names file, line and column).
  explicit InputError(const std::string& message) : std::runtime_error(message) {}

  const std::string& field() const { return field_; }
  const std::string& value() const { return value_; }
  const std::string& allowed() const { return allowed_; }

 private:
  std::string field_, value_, allowed_;
};

}  // namespace insmc
