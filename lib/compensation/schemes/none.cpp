#include "lib/compensation/schemes/schemes.h"

namespace insmc::schemes {

/// Uncompensated: the navigation from the first switch-over as (3.29) gives it.
const SchemeDefinition& none() {
  static const SchemeDefinition d{
      .name = "none",
      .equations = "(3.29)",
      .position_map = [](const SchemeMapContext&, ExtendedMap&) {},
      .truth_action = [](const TruthSchemeContext&, TruthOptions&, UncertaintyVector&) {},
  };
  return d;
}

}  // namespace insmc::schemes
