#pragma once
/// One definition per candidate, one file each in this folder, listed once
/// in candidate_list.h; registry.cpp gathers them.
#include "montecarlo/records/gap/candidates/candidates.h"

namespace insmc::gap::candidates {

#define INSMC_CANDIDATE(name) Candidate name();
#include "montecarlo/records/gap/candidates/candidate_list.h"
#undef INSMC_CANDIDATE

}  // namespace insmc::gap::candidates
