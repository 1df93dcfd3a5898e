#pragma once
/// A quantity for a report, to the figures it supports: a fitted value whose
/// interval spans tens of percent reads "4.5mg", not "4.49740608052mg".
/// Messages that echo a user's value keep format_quantity (12 figures).
#include <string>

#include "lib/units/units.h"

namespace insmc {

/// As format_quantity (the paper's unit where one is natural), to
/// `significant_digits` significant figures.
std::string format_quantity_rounded(double value_si, Dimension dimension, int significant_digits = 3);

}  // namespace insmc
