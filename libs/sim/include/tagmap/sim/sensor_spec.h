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

/** The finite beam: a cone sampled by a centre ray and a ring of sub-rays. */
struct BeamParams
{
	double divergenceMrad = 3.0;  // full angle
	int subRays = 4;  // ring samples besides the centre ray (0 = ideal thin beam)
	/** Returns whose ranges lie within this window merge into one echo
	 *  (range = energy-weighted mean -> mixed pixels); farther ones split
	 *  and the strongest echo wins. */
	double mixingWindow = 1.5;
};

struct IntensityParams
{
	double gain = 1.0;
	double incidenceExponent = 1.0;  // Lambertian: cos^1
	double rangeReference = 1.0;  // metres; no falloff closer than this
	double rangeFalloffExponent = 0.5;  // residual falloff after the sensor's own calibration
	double noiseSigma = 0.015;  // additive, in 0..1 units
	double detectionThreshold = 0.003;  // weaker echoes are lost
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
	double minRange = 0.5, maxRange = 200;
	double framePeriod = 0.1;  // seconds per frame (Rosette); Spinning uses one revolution
};

}  // namespace tagmap::sim
