#pragma once
// What the bench works out from measured points, apart from drawing them: the Pareto
// front of a speed/accuracy trade-off and the exponent of a power law.

#include <vector>

#include "charts.h"  // ChartPoint

namespace bench {

// The points on the front when lower x and lower y are both better: a point is on it
// unless another point is <= on both and < on one (so equal points are all on it).
// Returned sorted by x, then y. A point with a NaN coordinate cannot be compared with
// any other and is left out.
std::vector<ChartPoint> pareto_front(const std::vector<ChartPoint>& points);

// The exponent b of the power law y = a x^b that fits the points with x in
// [x_min, x_max] best: the least-squares line log y = log a + b log x. Points whose x
// or y is not a finite positive number have no logarithm and are left out. NaN when
// fewer than two different x remain (no line is fixed by them).
double fitted_exponent(const std::vector<ChartPoint>& points, double x_min, double x_max);

}  // namespace bench
