#include "tagmap/sim/trajectory.h"

#include <algorithm>
#include <cmath>

#include "tagmap/sim/scan_pattern.h"

namespace tagmap::sim
{
Eigen::Isometry3d interpolatePose(const std::vector<Waypoint>& w, double t)
{
	if (w.size() == 1 || t <= w.front().t) return w.front().pose;
	if (t >= w.back().t) return w.back().pose;
	size_t k = 1;
	while (w[k].t < t) k++;
	const Waypoint& a = w[k - 1];
	const Waypoint& b = w[k];
	const double s = (t - a.t) / (b.t - a.t);
	Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
	const Eigen::Quaterniond qa(a.pose.linear()), qb(b.pose.linear());
	T.linear() = qa.slerp(s, qb).toRotationMatrix();
	T.translation() = (1 - s) * a.pose.translation() + s * b.pose.translation();
	return T;
}

Eigen::Isometry3d sensorPoseAt(const ScanRun& run, double t) { return interpolatePose(run.waypoints, t) * run.mount; }

double framePeriod(const SensorSpec& s)
{
	return s.kind == SensorKind::Spinning ? 1.0 / s.spinning.revPerSecond : s.framePeriod;
}

std::vector<Frame> scheduleFrames(const Scene& scene)
{
	std::vector<Frame> frames;
	double clock = 0;
	for (size_t ri = 0; ri < scene.runs.size(); ri++)
	{
		const ScanRun& run = scene.runs[ri];
		const SensorSpec& sensor = scene.sensors[run.sensor];
		const auto pattern = makeScanPattern(sensor);
		Frame f;
		f.run = static_cast<int>(ri);
		f.sensor = run.sensor;
		if (sensor.kind == SensorKind::Grid)
		{
			for (const Waypoint& w : run.waypoints)
			{
				f.t0 = f.tRef = w.t;
				f.clock = clock;
				f.truePose = w.pose * run.mount;
				f.rays = pattern->rayCount(0);
				frames.push_back(f);
				clock += 1.0;  // a station sweep takes time; keeps frame stamps increasing
			}
			continue;
		}
		const double start = run.waypoints.front().t;
		const double length = run.waypoints.size() == 1 ? run.duration : run.waypoints.back().t - start;
		const double period = framePeriod(sensor);
		const int n = std::max(1, static_cast<int>(std::ceil(length / period - 1e-9)));
		for (int k = 0; k < n; k++)
		{
			f.t0 = start + k * period;
			f.duration = std::min(period, start + length - f.t0);
			f.clock = clock + k * period;
			f.tRef = f.t0 + 0.5 * f.duration;
			f.truePose = sensorPoseAt(run, f.tRef);
			const Eigen::Isometry3d a = sensorPoseAt(run, f.t0);
			const Eigen::Isometry3d b = sensorPoseAt(run, f.t0 + f.duration);
			f.moving = !a.isApprox(b, 1e-12);
			f.rays = pattern->rayCount(f.duration);
			frames.push_back(f);
		}
		clock += length;
	}
	return frames;
}

}  // namespace tagmap::sim
