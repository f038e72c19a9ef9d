// atan2 for projecting every point of a scan onto angles (the sensor view
// needs two a point): a polynomial the compiler inlines into the caller's
// loop, instead of glibc's correctly rounded call. Within 6e-9 rad of it (a
// view's pixel is 1e-3 to 1e-2 rad); the 64-beam bench's view renders
// 0.2-0.4 ms faster a scan (docs/PERFORMANCE.md, stop 44).
#pragma once

#include <cmath>

namespace tagmap
{
/** atan2(y, x) in [-pi, pi], absolute error under 6e-9 rad (test_core);
 *  0 at the origin. Unlike std::atan2, -0 is not told from +0: atan2(-0,
 *  -1) is pi, not -pi (the same direction). */
inline double fastAtan2(double y, double x)
{
	const double ax = std::abs(x), ay = std::abs(y);
	const double hi = ax > ay ? ax : ay, lo = ax > ay ? ay : ax;
	if (!(hi > 0)) return 0;
	// atan(a) = a P(a^2) on [0, 1], P a degree-8 minimax fit (Lawson
	// iterations on 4000 Chebyshev nodes), evaluated by Horner's rule.
	const double a = lo / hi, s = a * a;
	double p = 0.0024567225490758154;
	p = p * s - 0.014401349345270782;
	p = p * s + 0.039781208701037782;
	p = p * s - 0.072348559981482721;
	p = p * s + 0.1049894535626802;
	p = p * s - 0.14161228977311061;
	p = p * s + 0.19985906731377898;
	p = p * s - 0.33332597025548794;
	p = p * s + 0.9999998863824181;
	double r = p * a;
	if (ay > ax) r = M_PI_2 - r;
	if (x < 0) r = M_PI - r;
	return y < 0 ? -r : r;
}

}  // namespace tagmap
