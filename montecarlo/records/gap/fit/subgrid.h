#pragma once
/// Where between its grid points a searched parameter's least G lies. The
/// grid is coarse (four points a decade) so that a candidate costs few model
/// builds; the value of least G on the grid alone would make every resampled
/// fit land on the same point and the 16–84 % range collapse to it. Along
/// each searched parameter, G² at the best point and its nearest evaluated
/// neighbours is fitted by a parabola in the parameter's logarithm (an
/// added variance's share makes ln(observed / expected), and so G², close to
/// quadratic in it) and the parameter moves to its vertex, which lies
/// between the neighbours. docs/gap-method.md §3.
#include <vector>

#include "montecarlo/records/gap/fit/candidate_fit.h"

namespace insmc::gap {

/// The parameter values of `best` (a choice of least G on `under`'s runs)
/// with every searched parameter off the grid's ends moved to its vertex
/// (amplitudes as fitted). A parameter at a grid end, next to a grid's 0,
/// or whose parabola is not convex, keeps its grid value.
std::vector<double> subgrid_values(const Candidate& c, const RunsUnderChoice& under,
                                   const Choice& best, const NullCalibration& m0);

/// The vertex of the parabola through (x[i], y[i]), i = 0..2, x ascending,
/// y[1] the least; x[1] when the parabola is not convex.
double parabola_vertex(const double (&x)[3], const double (&y)[3]);

}  // namespace insmc::gap
