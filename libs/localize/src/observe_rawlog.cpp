#include "tagmap/localize/observe_rawlog.h"

#include <mrpt/obs/CSensoryFrame.h>

#include <algorithm>
#include <chrono>
#include <deque>
#if defined(__GLIBC__)
#include <malloc.h>
#endif

#include "tagmap/errors.h"
#include "tagmap/localize/rawlog_odometry.h"
#include "tagmap/localize/rawlog_visit.h"
#include "tagmap/localize/scan_tags.h"
#include "tagmap/localize/window_disagreement.h"
#include "tagmap/obs/CObservationTagPoses.h"
#include "tagmap/quantile.h"

namespace tagmap::localize
{
namespace
{
bool isLidar(const mrpt::obs::CObservation& o)
{
	// Our own outputs carry no points; everything else is tried as a scan.
	return !dynamic_cast<const obs::CObservationTagPoses*>(&o) &&
		   !dynamic_cast<const mrpt::obs::CObservationBeaconRanges*>(&o);
}

class Observer
{
   public:
	Observer(const Pipeline& pipeline, const ObserveParams& params, ObserveReport& report, size_t total,
			 OdometrySource odometry, const CountProgressFn& progress)
		: pipeline_(pipeline),
		  params_(params),
		  report_(report),
		  total_(total),
		  odometry_(odometry),
		  progress_(progress)
	{
	}

	void addActions(const mrpt::obs::CActionCollection& a) { odometry_.addActions(a); }

	/** The tag observations of one scan (empty if it is not a LiDAR scan). */
	std::vector<mrpt::obs::CObservation::Ptr> observe(const mrpt::obs::CObservation& scanObs)
	{
		odometry_.addObservation(scanObs);
		if (!isLidar(scanObs)) return {};
		auto scan = scanInSensorFrame(scanObs);
		if (!scan) return {};
		mrpt::poses::CPose3D sensorPose;
		scanObs.getSensorPose(sensorPose);
		const mrpt::poses::CPose3D sensorNow = mrpt::poses::CPose3D(odometry_.pose()) + sensorPose;

		auto tags = obs::CObservationTagPoses::Create();
		tags->sensorLabel = scanObs.sensorLabel + params_.tagsLabelSuffix;
		tags->timestamp = scanObs.timestamp;
		tags->sensorPose = sensorPose;
		WindowDetection detection = detectWindow(*scan, sensorNow, params_.window);
		// No tag in the short window: the frames between tags try the long one.
		const size_t longest = std::min(params_.maxWindow, window_.size() + 1);
		if (detection.found.tags.empty() && longest > params_.window)
		{
			const double shortSeconds = detection.found.totalSeconds;
			detection = detectWindow(*scan, sensorNow, longest);
			detection.found.totalSeconds += shortSeconds;
		}
		auto& [found, points, scansMerged] = detection;
		window_.push_back({sensorNow, std::move(*scan)});
		if (window_.size() >= std::max(params_.window, params_.maxWindow)) window_.pop_front();
		pointsDetected_ += points;
		report_.perScan.push_back(
			{points, scansMerged, found.totalSeconds, std::move(found.stages), std::move(found.candidates)});
		tags->tags = std::move(found.tags);

		auto ranges = makeBeaconRanges(tags->tags, sensorPose, params_.ranges);
		ranges->sensorLabel = scanObs.sensorLabel + params_.rangesLabelSuffix;
		ranges->timestamp = scanObs.timestamp;

		report_.scans++;
		report_.scansWithTags += !tags->tags.empty();
		report_.scansWithTagsInLongWindow += !tags->tags.empty() && scansMerged > params_.window;
		report_.tagsSeen += tags->tags.size();
		for (const TagDetection& t : tags->tags) report_.scansPerTag[tagLabel(t.family, t.id)]++;
		report_.meanPointsDetected = pointsDetected_ / report_.scans;
		if (progress_) progress_(report_.scans, total_);
		return {ranges, tags};
	}

   private:
	struct PastScan
	{
		mrpt::poses::CPose3D sensorInOdometry;  // the sensor's pose in the odometry frame
		mrpt::maps::CPointsMapXYZI points;  // in its sensor frame
	};

	struct WindowDetection
	{
		Detections found;
		size_t points = 0;  // the window's scans merged
		size_t scansMerged = 1;
	};
	/** Tags in `scan` merged with the `count` - 1 scans before it. Each
	 *  detection knows where the merged scans' sensors stood (a read whose
	 *  printed face none of them could see is a mirror image: front_side.h),
	 *  and its tags are as uncertain as those scans, placed by drifting
	 *  odometry, disagree about them (window_disagreement.h). */
	WindowDetection detectWindow(const mrpt::maps::CPointsMapXYZI& scan, const mrpt::poses::CPose3D& sensorNow,
								 size_t count)
	{
		std::vector<size_t> scanStarts = {0};
		std::vector<Eigen::Vector3d> viewpoints = {Eigen::Vector3d::Zero()};
		mrpt::maps::CPointsMapXYZI merged = scan;
		const size_t earlier = std::min(count - 1, window_.size());
		for (auto past = window_.end() - static_cast<std::ptrdiff_t>(earlier); past != window_.end(); ++past)
		{
			scanStarts.push_back(merged.size());
			const mrpt::poses::CPose3D inThisFrame = past->sensorInOdometry - sensorNow;
			merged.insertAnotherMap(&past->points, inThisFrame);
			viewpoints.emplace_back(inThisFrame.x(), inThisFrame.y(), inThisFrame.z());
		}
		Detections found = pipeline_.detect(merged, viewpoints);
		// A single scan has no other to disagree with (the fits would add 0).
		if (scanStarts.size() > 1)
			for (TagDetection& t : found.tags)
				addMisregistration(t, windowMisregistration(t, merged, scanStarts, found.surfaceNoise));
		return {std::move(found), merged.size(), scanStarts.size()};
	}

	const Pipeline& pipeline_;
	const ObserveParams& params_;
	ObserveReport& report_;
	size_t total_;
	OdometryIntegrator odometry_;
	std::deque<PastScan> window_;  // the longest window - 1 scans before the next one
	size_t pointsDetected_ = 0;
	const CountProgressFn& progress_;
};

size_t countObservations(const mrpt::obs::CRawlog& in)
{
	size_t n = 0;
	visitRawlog(in, {{}, [&](const mrpt::obs::CSensoryFrame& sf) { n += sf.size(); },
					 [&](const mrpt::obs::CObservation::Ptr&) { n++; }});
	return n;
}
}  // namespace

double ObserveReport::medianDetectSeconds() const
{
	if (perScan.empty()) return 0;
	std::vector<double> s;
	for (const ScanTiming& t : perScan) s.push_back(t.seconds);
	return medianInPlace(s);
}

mrpt::obs::CRawlog observeRawlog(const mrpt::obs::CRawlog& in, const Pipeline& pipeline, const ObserveParams& params,
								 ObserveReport* reportOut, const CountProgressFn& progress)
{
	const auto t0 = std::chrono::steady_clock::now();
	ObserveReport report;
	const OdometrySource odometry = findOdometry(in);
	const size_t longest = std::max(params.window, params.maxWindow);
	if (longest > 1 && odometry == OdometrySource::none)
		throw InputError("a window of " + std::to_string(longest) +
							 " scans needs odometry (CActionRobotMovement2D/3D or CObservationOdometry) to place "
							 "them; the rawlog has none");
	Observer observer(pipeline, params, report, countObservations(in), odometry, progress);
	mrpt::obs::CRawlog out;
	visitRawlog(in, {[&](const mrpt::obs::CActionCollection& a) {
						 observer.addActions(a);
						 mrpt::obs::CActionCollection copy = a;  // CRawlog::insert takes a non-const one
						 out.insert(copy);
					 },
					 [&](const mrpt::obs::CSensoryFrame& in_sf) {
						 mrpt::obs::CSensoryFrame sf;
						 for (const auto& o : in_sf)
						 {
							 sf.insert(o);
							 for (const auto& added : observer.observe(*o)) sf.insert(added);
						 }
						 out.insert(sf);
					 },
					 [&](const mrpt::obs::CObservation::Ptr& o) {
						 out.insert(o);
						 for (const auto& added : observer.observe(*o)) out.insert(added);
					 }});
	report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
	if (reportOut) *reportOut = report;
	return out;
}

void keepScanMemoryForReuse()
{
#if defined(__GLIBC__)
	// Setting either disables glibc's own adaptive thresholds: both are set.
	// 32 MB is glibc's largest mmap threshold on 64-bit systems.
	mallopt(M_MMAP_THRESHOLD, 32 << 20);
	mallopt(M_TRIM_THRESHOLD, 64 << 20);
#endif
}

}  // namespace tagmap::localize
