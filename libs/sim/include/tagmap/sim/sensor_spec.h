// What a sensor is: its scan pattern and its measurement physics, as plain
// parameters (scene YAML `sensors:` entries).
#pragma once

#include <string>
#include <vector>

namespace tagmap::sim
{
enum class SensorKind
{
	Rosette,  // Livox MID-40-like non-repetitive (two Risley prisms)
	Spinning,  // Ouster/Velodyne-like multi-beam
	Grid  // terrestrial laser scanner, dense az/el grid
};

struct RosetteParams
{
	double fovDeg = 38.4;  // full circular field of view
	double pointsPerSecond = 100000;
	/** Counter-rotating prism speeds. Their non-integer ratio makes the
	 *  rosette precess so coverage keeps densifying with time. */
	double prism1Rpm = 7294;
	double prism2Rpm = -4664;
};

struct SpinningParams
{
	std::vector<double> beamElevationsDeg;  // one per beam
	int columns = 1024;  // firings per revolution
	double revPerSecond = 10;
};

struct GridParams
{
	double azMinDeg = -180, azMaxDeg = 180;
	double elMinDeg = -60, elMaxDeg = 90;
	double azStepDeg = 0.1, elStepDeg = 0.1;
};

/** The finite beam: a cone sampled by a centre ray and a ring of sub-rays.
 *  Laser diodes emit from a stripe, so real beams are elliptical (Livox
 *  MID-40: 0.03 x 0.28 deg); the ring is then an ellipse whose horizontal
 *  axis is perpendicular to the beam and to the sensor's up axis. */
struct BeamParams
{
	double divergenceMrad = 3.0;  // full angle, horizontal
	double divergenceVerticalMrad = 3.0;  // full angle, vertical (equal: circular beam)
	int subRays = 4;  // ring samples besides the centre ray (0 = ideal thin beam)
	/** Returns whose ranges lie within this window merge into one echo
	 *  (range = energy-weighted mean -> mixed pixels); farther ones split
	 *  and the strongest echo wins. */
	double mixingWindow = 1.5;
	/** Angular noise of each ray, mrad (sigma per axis): the beam leaves
	 *  slightly off the direction the encoder reports, so the point is
	 *  placed along the reported direction at the range of the real one. */
	double pointingJitterMrad = 0;
	bool circular() const { return divergenceMrad == divergenceVerticalMrad; }
};

struct IntensityParams
{
	double gain = 1.0;
	double incidenceExponent = 1.0;  // Lambertian: cos^1
	double rangeReference = 1.0;  // metres; no falloff closer than this
	double rangeFalloffExponent = 0.5;  // residual falloff after the sensor's own calibration
	double noiseSigma = 0.015;  // additive, in 0..1 units
	double detectionThreshold = 0.003;  // weaker echoes are lost (after the residual falloff above)
	/** > 0: whether an echo returns at all follows its received power
	 *  instead, reflectivity x cos^k / range^2, lost below what a 10 %
	 *  reflective surface returns at this range (metres; spec sheets give
	 *  it: a Livox MID-40 90 m, an Ouster OS1 ~40 m). The reported
	 *  intensity keeps its residual falloff: a sensor's calibration
	 *  flattens what it reports, not what its receiver gets.
	 *  `detectionThreshold` is then unused. */
	double detectionRange10 = 0;
	/** Received level (in the 0..1 units above, after gain) that fills the
	 *  receiver's full scale: stronger echoes clip there (retro-reflectors,
	 *  white paper close by). 1 = never before the 0..1 clamp. */
	double saturation = 1.0;
	/** Native bit depth of the reported intensity: 8 or 16 quantize to
	 *  2^bits - 1 integer levels before the output scale; 0 = continuous. */
	int bits = 0;
};

struct SensorSpec
{
	std::string name;
	SensorKind kind = SensorKind::Rosette;
	RosetteParams rosette;
	SpinningParams spinning;
	GridParams grid;
	BeamParams beam;
	IntensityParams intensity;
	double rangeNoiseSigma = 0.02;  // metres, Gaussian
	/** Range walk, metres: a weak echo's pulse crosses the receiver's
	 *  threshold later than a strong one's, so it reads farther. This is the
	 *  bias of the weakest echo relative to a full-scale one (dark ink reads
	 *  a few mm behind white paper). */
	double rangeWalk = 0;
	double minRange = 0.5, maxRange = 200;
	double framePeriod = 0.1;  // seconds per frame (Rosette); Spinning uses one revolution
};

}  // namespace tagmap::sim
