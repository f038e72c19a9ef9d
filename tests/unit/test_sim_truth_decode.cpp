// THE convention test: points simulated on a tag, projected onto the TRUE
// tag plane (tag x -> image right, tag y -> image up), rendered and decoded
// by the project's decoder, must give the right id and corners that map
// back onto the ground-truth corners in vertex-index order.
#include <gtest/gtest.h>

#include <iostream>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "tagmap/sim/scene_loader.h"
#include "tagmap/sim/simulate.h"
#include "tagmap/tag_decoder.h"
#include "tagmap/tag_family.h"

using namespace tagmap;

namespace
{
// A wall facing the sensor at ~2.3 m, turned 25 deg about z; the tag, on a
// board, is rolled in its plane (so a wrong vertex order cannot pass by
// symmetry) and tilted a few random degrees.
std::string sceneText(const std::string& family, int id, double size, double rollDeg)
{
	return "name: truth_decode\n"
		   "objects:\n"
		   "  - {name: wall, type: plane, position: [2.3, 0.3, 1.2], normal: [-0.906, -0.423, 0], size: [4, 3], "
		   "reflectivity: 0.5}\n"
		   "tags:\n"
		   "  - {family: " +
		   family + ", id: " + std::to_string(id) + ", size: " + std::to_string(size) +
		   ", position: [2.3, 0.3, 1.2], normal: [-0.906, -0.423, 0], roll_deg: " + std::to_string(rollDeg) +
		   ", margin: 0.03, jitter_deg: 6, board: {size: [0.5, 0.5]}}\n"
		   "sensors:\n"
		   "  - {name: livox, type: livox_mid40, range_noise: 0.01}\n"
		   "runs:\n"
		   "  - {name: still, sensor: livox, duration: 3.0, waypoints: [{position: [0, 0, 1.1], look_at: [2.3, 0.3, "
		   "1.2]}]}\n";
}

struct Rendered
{
	cv::Mat gray;
	double half = 0, px = 0;  // image covers tag-frame [-half, half]^2, px metres per pixel
};

// Average intensity per pixel on the true tag plane, holes filled from neighbours.
Rendered render(const mrpt::maps::CPointsMapXYZI& map, const Eigen::Isometry3d& T_G_tag, double half, double px)
{
	const int n = static_cast<int>(std::ceil(2 * half / px));
	cv::Mat sum(n, n, CV_64F, cv::Scalar(0)), cnt(n, n, CV_64F, cv::Scalar(0));
	const Eigen::Isometry3d inv = T_G_tag.inverse();
	for (size_t i = 0; i < map.size(); i++)
	{
		float x, y, z;
		map.getPointFast(i, x, y, z);
		const Eigen::Vector3d q = inv * Eigen::Vector3d(x, y, z);
		if (std::abs(q.z()) > 0.05) continue;
		const int c = static_cast<int>(std::floor((q.x() + half) / px));
		const int r = static_cast<int>(std::floor((half - q.y()) / px));  // tag y up -> row decreases
		if (c < 0 || r < 0 || c >= n || r >= n) continue;
		sum.at<double>(r, c) += map.getPointIntensity(i);
		cnt.at<double>(r, c) += 1;
	}
	cv::Mat img(n, n, CV_64F, cv::Scalar(-1));
	for (int r = 0; r < n; r++)
		for (int c = 0; c < n; c++)
			if (cnt.at<double>(r, c) > 0) img.at<double>(r, c) = sum.at<double>(r, c) / cnt.at<double>(r, c);
	for (bool holes = true; holes;)
	{
		holes = false;
		cv::Mat next = img.clone();
		for (int r = 0; r < n; r++)
			for (int c = 0; c < n; c++)
			{
				if (img.at<double>(r, c) >= 0) continue;
				double s = 0;
				int k = 0;
				for (int dr = -1; dr <= 1; dr++)
					for (int dc = -1; dc <= 1; dc++)
					{
						const int rr = r + dr, cc = c + dc;
						if (rr >= 0 && cc >= 0 && rr < n && cc < n && img.at<double>(rr, cc) >= 0)
						{
							s += img.at<double>(rr, cc);
							k++;
						}
					}
				if (k)
					next.at<double>(r, c) = s / k;
				else
					holes = true;
			}
		img = next;
	}
	Rendered out;
	cv::normalize(img, img, 0, 255, cv::NORM_MINMAX);
	img.convertTo(out.gray, CV_8U);
	out.half = half;
	out.px = px;
	return out;
}

// Renders the points around one true tag and decodes them; the decoded
// corners, mapped back to 3D, must be the true corners in vertex order.
void checkTag(const mrpt::maps::CPointsMapXYZI& map, const TagDetection& truth, size_t pointsOnTag, double tolerance)
{
	SCOPED_TRACE(truth.family + ":" + std::to_string(truth.id));
	const TagBitmap bm = renderTagBitmap(truth.family, truth.id);
	const double cell = truth.size / bm.borderCells;
	const double half = 0.5 * bm.cells * cell + 0.02;  // pattern with its quiet zone, plus paper
	const Rendered img = render(map, truth.pose, half, cell / 7);  // 7 px per bit cell

	if (getenv("TAGMAP_DUMP")) cv::imwrite("/tmp/truth_" + truth.family + ".png", img.gray);
	TagDecoder decoder({truth.family});
	const auto found = decoder.decode(img.gray);
	ASSERT_FALSE(found.empty()) << "nothing decoded; " << pointsOnTag << " points on the tag";
	const DecodedTag2D& d = found[0];
	EXPECT_EQ(d.family, truth.family);
	EXPECT_EQ(d.id, truth.id);
	EXPECT_FALSE(d.mirrored);
	double worst = 0;
	for (int v = 0; v < 4; v++)
	{
		const Eigen::Vector3d local(-img.half + d.corners[v].x() * img.px, img.half - d.corners[v].y() * img.px, 0);
		const Eigen::Vector3d g = truth.pose * local;
		worst = std::max(worst, (g - truth.corners[v]).norm());
		EXPECT_LT((g - truth.corners[v]).norm(), tolerance)
			<< "vertex " << v << " at " << g.transpose() << ", truth " << truth.corners[v].transpose();
	}
	std::cout << truth.family << ": id " << d.id << ", " << pointsOnTag << " points on the paper, worst corner error "
			  << worst * 1000 << " mm\n";
}

void checkFamily(const std::string& family, int id, double size, double rollDeg, double tolerance = 0.004)
{
	const auto scene = sim::parseScene(sceneText(family, id, size, rollDeg), "truth_decode.yaml");
	sim::SimOptions opt;
	opt.seed = 11;
	const auto out = sim::simulate(scene, opt);
	ASSERT_EQ(out.truth.size(), 1u);
	checkTag(out.map, out.truth[0], out.tagSightings[0].points, tolerance);
}
}  // namespace

TEST(SimTruthDecode, Tag36h11) { checkFamily("tag36h11", 5, 0.20, 30); }
TEST(SimTruthDecode, TagStandard41h12) { checkFamily("tagStandard41h12", 12, 0.16, -60); }
// OpenCV's ArUco corners sit up to ~1 px (here ~4 mm) inside the true border
// where libapriltag's are within ~0.3 px, hence the looser bound.
TEST(SimTruthDecode, ArucoDict) { checkFamily("aruco_6x6_250", 4, 0.20, 100, 0.006); }
TEST(SimTruthDecode, ArucoOriginal) { checkFamily("aruco_original", 1, 0.20, 0, 0.006); }

// Every family, rolled, on the ceiling and on a tilted board (families.yaml).
TEST(SimTruthDecode, FamiliesSceneEveryTag)
{
	const auto scene = sim::loadScene(std::string(TAGMAP_SOURCE_DIR) + "/share/scenes/families.yaml");
	const auto out = sim::simulate(scene, {});
	ASSERT_EQ(out.truth.size(), scene.tags.size());
	for (size_t i = 0; i < out.truth.size(); i++) checkTag(out.map, out.truth[i], out.tagSightings[i].points, 0.005);
}

// The paper's parking lot: the most slowly and closely scanned tag (id 4)
// decodes where the drifted map shows it (truthInMap). Tag 0 (fast, blurred,
// extra drift) is the paper's failure case; tag 1 is marginal (it depends on
// the drift draw), so neither is asserted here.
TEST(SimTruthDecode, ParkingSlowPassTag)
{
	const auto scene = sim::loadScene(std::string(TAGMAP_SOURCE_DIR) + "/share/scenes/parking.yaml");
	const auto out = sim::simulate(scene, {});
	ASSERT_EQ(out.truthInMap.size(), 3u);
	// 3 cm: the map is a blend of frames with different drift; truthInMap
	// follows only the frame that saw the tag most.
	checkTag(out.map, out.truthInMap[2], out.tagSightings[2].points, 0.03);
}
