#pragma once
/// The report's compensation schemes, one definition file each
/// (scheme_definition.h). registry.cpp lists them in report order.
#include "lib/compensation/schemes/scheme_definition.h"

namespace insmc::schemes {

const SchemeDefinition& none();
const SchemeDefinition& scheme_5_1_1();
const SchemeDefinition& scheme_5_1_2();
const SchemeDefinition& combined();
const SchemeDefinition& scheme_5_2();
const SchemeDefinition& scheme_5_3();
const SchemeDefinition& scheme_5_4();

}  // namespace insmc::schemes
