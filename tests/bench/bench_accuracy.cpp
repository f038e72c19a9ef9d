// Accuracy benchmark in the layout of the paper's Table 2: one tag36h11 of
// 0.164 m on a wall, a stationary Livox-like 2 s scan with 1 cm range noise
// from 2, 3 and 4 m, many seeds per distance. Prints mean absolute errors
// per axis, detection counts and vertex-order checks. Not a timed test.
//
// --randomize draws the physics per seed instead (the same draw at every
// distance): range noise 0.5-3 cm, a circular (0.3-3 mrad) or elliptical
// (up to 0.52 x 5.2 mrad, the MID-40's 0.03 x 0.3 deg) beam, pointing jitter
// 0-1 mrad, range walk 0-5 mm, the intensity model (gain, incidence and
// range fall-off, noise, saturation, 8 or 16 bit), ink and paper albedo, and
// the sheet either on a board (3-20 mm standoff, tilted up to 5 deg) or
// stuck to the wall 0-2 mm proud. Each distance then also prints the worst
// error over the draws and the physics of the draw that made it.
//
//   build/bin/tagmap-bench-accuracy [--seeds 10] [--distances 2,3,4] [--unknown-size] [--randomize]
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

#include "tagmap/evaluation.h"
#include "tagmap/pipeline.h"
#include "tagmap/sim/rng.h"
#include "tagmap/sim/scene_loader.h"
#include "tagmap/sim/simulate.h"

namespace
{
/** One draw of the physics nobody tuned to, applied to the scene's only
 *  sensor and tag. */
struct PhysicsDraw
{
	double rangeNoise, beamH, beamV, jitter, walk;
	tagmap::sim::IntensityParams intensity;
	float black, white;
	bool onBoard;
	double standoff;

	explicit PhysicsDraw(uint64_t seed)
	{
		tagmap::sim::Rng rng(tagmap::sim::streamSeed(seed, 0xACC));
		auto u = [&](double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng); };
		rangeNoise = u(0.005, 0.03);
		const bool elliptical = u(0, 1) < 0.6;
		beamH = elliptical ? u(0.2, 0.52) : u(0.3, 3.0);
		beamV = elliptical ? u(0.5, 5.2) : beamH;
		jitter = u(0, 1.0);
		walk = u(0, 0.005);
		intensity.gain = u(0.5, 2.0);
		intensity.incidenceExponent = u(0.3, 2.0);
		intensity.rangeFalloffExponent = u(0, 2);
		intensity.noiseSigma = u(0.005, 0.05);
		intensity.saturation = u(0.4, 1.0);
		intensity.bits = u(0, 1) < 0.5 ? 8 : 16;
		black = static_cast<float>(u(0.02, 0.15));
		white = static_cast<float>(u(0.55, 0.95));
		onBoard = u(0, 1) < 0.5;
		standoff = onBoard ? u(0.003, 0.02) : u(0, 0.002);
	}

	void applyTo(tagmap::sim::Scene& scene) const
	{
		tagmap::sim::SensorSpec& s = scene.sensors.at(0);
		s.rangeNoiseSigma = rangeNoise;
		s.beam.divergenceMrad = beamH;
		s.beam.divergenceVerticalMrad = beamV;
		s.beam.pointingJitterMrad = jitter;
		s.rangeWalk = walk;
		s.intensity = intensity;
		tagmap::sim::TagSpec& t = scene.tags.at(0);
		t.black = black;
		t.white = white;
		if (onBoard)
			t.boardStandoff = standoff;
		else
		{
			// Stuck to the wall: no board, and only an in-plane turn.
			t.boardWidth = t.boardHeight = 0;
			t.paperOffset = standoff;
		}
	}

	std::string describe() const
	{
		char buf[256];
		std::snprintf(buf, sizeof buf,
					  "noise %.1f mm, beam %.2fx%.2f mrad, jitter %.2f mrad, walk %.1f mm, gain %.2f, incidence^%.2f, "
					  "range^%.2f, I-noise %.3f, sat %.2f, %d bit, ink %.2f, paper %.2f, %s %.1f mm",
					  1000 * rangeNoise, beamH, beamV, jitter, 1000 * walk, intensity.gain,
					  intensity.incidenceExponent, intensity.rangeFalloffExponent, intensity.noiseSigma,
					  intensity.saturation, intensity.bits, black, white, onBoard ? "board" : "on wall",
					  1000 * standoff);
		return buf;
	}
};
}  // namespace

int main(int argc, char** argv)
{
	int seeds = 10;
	std::vector<double> distances = {2, 3, 4};
	bool unknownSize = false;
	bool randomize = false;
	std::string scenePath = std::string(TAGMAP_SOURCE_DIR) + "/share/scenes/accuracy.yaml";
	for (int i = 1; i < argc; i++)
	{
		const std::string a = argv[i];
		if (a == "--seeds" && i + 1 < argc)
			seeds = std::atoi(argv[++i]);
		else if (a == "--distances" && i + 1 < argc)
		{
			distances.clear();
			std::stringstream ss(argv[++i]);
			for (std::string d; std::getline(ss, d, ',');) distances.push_back(std::atof(d.c_str()));
		}
		else if (a == "--unknown-size")
			unknownSize = true;
		else if (a == "--randomize")
			randomize = true;
		else if (a == "--scene" && i + 1 < argc)
			scenePath = argv[++i];
		else
		{
			std::fprintf(stderr, "usage: %s [--seeds N] [--distances 2,3,4] [--unknown-size] [--randomize] [--scene FILE]\n", argv[0]);
			return 2;
		}
	}

	std::printf("tagmap accuracy benchmark: %s, %d seeds per distance, tag size %s, physics %s\n",
				scenePath.c_str(), seeds, unknownSize ? "estimated" : "given (0.164 m)",
				randomize ? "drawn per seed" : "the scene's");
	std::printf("%-8s | %-6s | %9s %9s %9s | %9s %9s %9s | %6s %6s %4s | %8s\n", "Distance", "Found", "X err(m)",
				"Y err(m)", "Z err(m)", "Roll(deg)", "Pitch(deg)", "Yaw(deg)", "maxXYZ", "maxRot", "FP", "order");
	int failures = 0;
	std::vector<std::string> worstDraws;
	for (double dist : distances)
	{
		const tagmap::sim::Scene sceneAsWritten = tagmap::sim::loadScene(scenePath, {{"tag_distance", dist}});
		double worstRot = -1;
		std::string worstDraw;
		Eigen::Vector3d sumPos = Eigen::Vector3d::Zero(), sumRot = Eigen::Vector3d::Zero();
		double maxPos = 0, maxRot = 0;
		int found = 0, truths = 0, falsePos = 0, orderOk = 0;
		for (int seed = 1; seed <= seeds; seed++)
		{
			tagmap::sim::SimOptions opt;
			opt.seed = static_cast<uint64_t>(seed);
			tagmap::sim::Scene scene = sceneAsWritten;
			const PhysicsDraw draw(opt.seed);
			if (randomize) draw.applyTo(scene);
			const tagmap::sim::SimulationOutput sim = tagmap::sim::simulate(scene, opt);
			tagmap::PipelineParams params;
			if (!unknownSize && !sim.truth.empty()) params.tagSize = sim.truth[0].size;
			const tagmap::Detections det = tagmap::Pipeline(params).detect(sim.map);
			const tagmap::Evaluation ev = tagmap::evaluateDetections(det.tags, sim.truth);
			truths += static_cast<int>(ev.perTruth.size());
			falsePos += ev.falsePositives();
			for (const auto& e : ev.perTruth)
			{
				if (!e.found) continue;
				found++;
				orderOk += e.vertexOrderCorrect;
				sumPos += e.positionError;
				sumRot += e.rotationErrorDeg;
				maxPos = std::max(maxPos, e.positionError.maxCoeff());
				maxRot = std::max(maxRot, e.rotationErrorDeg.maxCoeff());
				if (e.rotationErrorDeg.maxCoeff() > worstRot)
				{
					worstRot = e.rotationErrorDeg.maxCoeff();
					char buf[128];
					std::snprintf(buf, sizeof buf, "seed %d, %.3f deg, %.1f mm: ", seed, worstRot,
								  1000 * e.positionError.maxCoeff());
					worstDraw = buf + (randomize ? draw.describe() : std::string("the scene's physics"));
				}
			}
			for (const auto& e : ev.perTruth)
				if (!e.found && randomize)
					worstDraws.push_back(std::to_string(static_cast<int>(dist)) + " m: missed at seed " +
										 std::to_string(seed) + ": " + draw.describe());
		}
		const Eigen::Vector3d mp = found ? Eigen::Vector3d(sumPos / found) : Eigen::Vector3d::Zero();
		const Eigen::Vector3d mr = found ? Eigen::Vector3d(sumRot / found) : Eigen::Vector3d::Zero();
		std::printf("%-8s | %2d/%-3d | %9.4f %9.4f %9.4f | %9.3f %9.3f %9.3f | %6.4f %6.3f %4d | %3d/%-4d\n",
					(std::to_string(static_cast<int>(dist)) + " m").c_str(), found, truths, mp.x(), mp.y(), mp.z(),
					mr.x(), mr.y(), mr.z(), maxPos, maxRot, falsePos, orderOk, found);
		if (worstRot >= 0) worstDraws.push_back(std::to_string(static_cast<int>(dist)) + " m: worst " + worstDraw);
		// The bar: every tag found, mean error <= 5 mm and <= 0.3 deg per axis, order always right.
		if (found != truths || mp.maxCoeff() > 0.005 || mr.maxCoeff() > 0.3 || orderOk != found || falsePos) failures++;
	}
	for (const std::string& w : worstDraws) std::printf("%s\n", w.c_str());
	std::printf("paper (Table 2, ours): 2 m: 0.002 0.005 0.011 m, 0.315 0.305 0.391 deg; 3 m: 0.006 0.009 0.015 m, "
				"0.343 0.322 0.455 deg; 4 m: 0.008 0.014 0.016 m, 0.302 0.389 0.478 deg\n");
	std::printf("%s\n", failures ? "RESULT: below the bar at some distance" : "RESULT: meets the bar at every distance");
	return failures ? 1 : 0;
}
