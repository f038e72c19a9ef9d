#include "scene_yaml_parts.h"

namespace tagmap::sim
{
namespace
{
// Pairs like `range: [min, max]`, checked min < max.
void readInterval(const YamlReader& r, const std::string& key, double& lo, double& hi)
{
	if (!r.has(key)) return;
	const auto v = r.numbers(key, 2);
	if (!(v[0] < v[1])) r.child(key).fail("needs [min, max] with min < max");
	lo = v[0];
	hi = v[1];
}

void setCircularBeam(BeamParams& b, double mrad) { b.divergenceMrad = b.divergenceVerticalMrad = mrad; }

// `divergence_mrad: 1.6` (circular) or `[horizontal, vertical]` (elliptical).
void readDivergence(const YamlReader& b, BeamParams& beam)
{
	if (!b.has("divergence_mrad")) return;
	if (!b.child("divergence_mrad").isSequence())
	{
		setCircularBeam(beam, b.positive("divergence_mrad", 0, true));
		return;
	}
	const auto v = b.numbers("divergence_mrad", 2);
	if (v[0] < 0 || v[1] < 0) b.child("divergence_mrad").fail("divergences must be >= 0");
	beam.divergenceMrad = v[0];
	beam.divergenceVerticalMrad = v[1];
}

// Defaults that make each type a plausible real device without any options.
SensorSpec defaultsFor(SensorKind kind)
{
	SensorSpec s;
	s.kind = kind;
	switch (kind)
	{
		case SensorKind::Rosette:  // Livox MID-40: 2 cm range noise, 0.28 x 0.03 deg beam
			s.rangeNoiseSigma = 0.02;
			// The datasheet's 4.9 x 0.5 mrad ellipse as the circle of equal
			// area (the shipped scenes' maps were made so);
			// `divergence_mrad: [0.5, 4.9]` gives the real ellipse.
			setCircularBeam(s.beam, 1.6);
			s.minRange = 1.0;
			s.maxRange = 260;
			break;
		case SensorKind::Spinning:  // 32-beam Ouster/Velodyne-like
			s.rangeNoiseSigma = 0.015;
			setCircularBeam(s.beam, 3.0);
			s.minRange = 0.5;
			s.maxRange = 120;
			for (int i = 0; i < 32; i++) s.spinning.beamElevationsDeg.push_back(-22.5 + 45.0 * i / 31);
			break;
		case SensorKind::Grid:  // phase/pulse terrestrial scanner
			s.rangeNoiseSigma = 0.003;
			setCircularBeam(s.beam, 0.5);
			s.minRange = 0.6;
			s.maxRange = 150;
			break;
	}
	return s;
}
}  // namespace

SensorSpec parseSensor(const YamlReader& r)
{
	r.allowKeys({"name", "type", "range_noise", "range_walk", "range", "frame_period", "beam", "intensity", "fov_deg",
				 "points_per_second", "prism_rpm", "beams", "vertical_fov_deg", "elevations_deg", "columns",
				 "rev_per_second", "azimuth_deg", "elevation_deg", "step_deg"});
	const std::string type = r.text("type");
	SensorKind kind;
	if (type == "rosette" || type == "livox_mid40")
		kind = SensorKind::Rosette;
	else if (type == "spinning")
		kind = SensorKind::Spinning;
	else if (type == "grid" || type == "terrestrial")
		kind = SensorKind::Grid;
	else
		r.child("type").fail("unknown sensor type '" + type + "' (rosette, livox_mid40, spinning, grid, terrestrial)");

	SensorSpec s = defaultsFor(kind);
	s.name = r.text("name");
	s.rangeNoiseSigma = r.positive("range_noise", s.rangeNoiseSigma, true);
	s.rangeWalk = r.positive("range_walk", s.rangeWalk, true);
	readInterval(r, "range", s.minRange, s.maxRange);
	s.framePeriod = r.positive("frame_period", s.framePeriod);

	if (r.has("beam"))
	{
		const YamlReader b = r.child("beam");
		b.allowKeys({"divergence_mrad", "sub_rays", "mixing_window", "pointing_jitter_mrad"});
		readDivergence(b, s.beam);
		s.beam.subRays = b.integer("sub_rays", s.beam.subRays);
		if (s.beam.subRays < 0 || s.beam.subRays > 32) b.child("sub_rays").fail("must be 0..32");
		s.beam.mixingWindow = b.positive("mixing_window", s.beam.mixingWindow, true);
		s.beam.pointingJitterMrad = b.positive("pointing_jitter_mrad", s.beam.pointingJitterMrad, true);
	}
	if (r.has("intensity"))
	{
		const YamlReader i = r.child("intensity");
		i.allowKeys({"gain", "incidence_exponent", "range_reference", "range_falloff_exponent", "noise",
					 "detection_threshold", "detection_range_10pct", "saturation", "bits"});
		IntensityParams& p = s.intensity;
		p.gain = i.positive("gain", p.gain);
		p.incidenceExponent = i.positive("incidence_exponent", p.incidenceExponent, true);
		p.rangeReference = i.positive("range_reference", p.rangeReference);
		p.rangeFalloffExponent = i.positive("range_falloff_exponent", p.rangeFalloffExponent, true);
		p.noiseSigma = i.positive("noise", p.noiseSigma, true);
		p.detectionThreshold = i.positive("detection_threshold", p.detectionThreshold, true);
		p.detectionRange10 = i.positive("detection_range_10pct", p.detectionRange10, true);
		p.saturation = i.positive("saturation", p.saturation);
		if (p.saturation > 1) i.child("saturation").fail("must be within (0, 1]: the received level that reads full scale");
		p.bits = i.integer("bits", p.bits);
		if (p.bits != 0 && p.bits != 8 && p.bits != 16) i.child("bits").fail("must be 8 or 16 (0: continuous)");
	}

	switch (kind)
	{
		case SensorKind::Rosette:
		{
			s.rosette.fovDeg = r.positive("fov_deg", s.rosette.fovDeg);
			if (s.rosette.fovDeg >= 180) r.child("fov_deg").fail("must be < 180");
			s.rosette.pointsPerSecond = r.positive("points_per_second", s.rosette.pointsPerSecond);
			if (r.has("prism_rpm"))
			{
				const auto rpm = r.numbers("prism_rpm", 2);
				if (rpm[0] == 0 || rpm[1] == 0) r.child("prism_rpm").fail("prism speeds must be non-zero");
				s.rosette.prism1Rpm = rpm[0];
				s.rosette.prism2Rpm = rpm[1];
			}
			break;
		}
		case SensorKind::Spinning:
		{
			if (r.has("elevations_deg"))
			{
				s.spinning.beamElevationsDeg = r.numbers("elevations_deg");
				if (s.spinning.beamElevationsDeg.empty()) r.child("elevations_deg").fail("needs at least one beam");
			}
			else if (r.has("beams") || r.has("vertical_fov_deg"))
			{
				const int n = r.integer("beams", 32);
				if (n < 1 || n > 1024) r.child("beams").fail("must be 1..1024");
				double lo = -22.5, hi = 22.5;
				readInterval(r, "vertical_fov_deg", lo, hi);
				s.spinning.beamElevationsDeg.clear();
				for (int i = 0; i < n; i++) s.spinning.beamElevationsDeg.push_back(n == 1 ? lo : lo + (hi - lo) * i / (n - 1));
			}
			s.spinning.columns = r.integer("columns", s.spinning.columns);
			if (s.spinning.columns < 1) r.child("columns").fail("must be >= 1");
			s.spinning.revPerSecond = r.positive("rev_per_second", s.spinning.revPerSecond);
			break;
		}
		case SensorKind::Grid:
		{
			GridParams& g = s.grid;
			readInterval(r, "azimuth_deg", g.azMinDeg, g.azMaxDeg);
			readInterval(r, "elevation_deg", g.elMinDeg, g.elMaxDeg);
			if (g.elMinDeg < -90 || g.elMaxDeg > 90) r.child("elevation_deg").fail("must lie within [-90, 90]");
			if (r.has("step_deg"))
			{
				const auto st = r.numbers("step_deg", 2);
				if (st[0] <= 0 || st[1] <= 0) r.child("step_deg").fail("steps must be > 0");
				// Counted in double: an absurd step must not overflow the size_t count.
				const double rays = ((g.azMaxDeg - g.azMinDeg) / st[0] + 1) * ((g.elMaxDeg - g.elMinDeg) / st[1] + 1);
				if (rays > 2e9) r.child("step_deg").fail("steps this small give " + std::to_string(rays) + " rays per scan (more than 2e9)");
				g.azStepDeg = st[0];
				g.elStepDeg = st[1];
			}
			break;
		}
	}
	return s;
}

}  // namespace tagmap::sim
