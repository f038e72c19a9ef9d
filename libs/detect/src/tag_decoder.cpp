#include "tagmap/tag_decoder.h"

#include <apriltag/apriltag.h>

#include <algorithm>

#include <opencv2/aruco.hpp>
#include <opencv2/imgproc.hpp>

#include "tagmap/apriltag_families.h"
#include "tagmap/tag_family.h"

namespace tagmap
{
namespace
{
// OpenCV's default DetectorParameters::errorCorrectionRate.
constexpr double kErrorCorrectionRate = 0.6;

/** Which of the 4 rotations (of the given side) puts the identified code's
 *  bitmap on the sampled cells: the one that disagrees on fewest cells. */
int bestOrder(const std::string& family, int id, const std::vector<float>& sample, float threshold, bool mirrored)
{
	const TagBitmap bm = renderTagBitmap(family, id);
	int best = 0, fewest = bm.cells * bm.cells + 1;
	for (int order = mirrored ? 4 : 0; order < (mirrored ? 8 : 4); order++)
	{
		const std::vector<int>& perm = cellPermutation(bm.cells, order);
		int wrong = 0;
		for (size_t k = 0; k < perm.size(); k++)
			wrong += (sample[static_cast<size_t>(perm[k])] > threshold) != (bm.pixels[k] != 0);
		if (wrong < fewest) fewest = wrong, best = order;
	}
	return best;
}

/** Sub-pixel corners, as OpenCV's CORNER_REFINE_SUBPIX does for ArUco. */
void refineCorners(const cv::Mat& img, Quad& corners)
{
	std::vector<cv::Point2f> pts;
	for (const auto& c : corners) pts.emplace_back(static_cast<float>(c.x() - 0.5), static_cast<float>(c.y() - 0.5));
	cv::cornerSubPix(img, pts, cv::Size(5, 5), cv::Size(-1, -1),
					 cv::TermCriteria(cv::TermCriteria::MAX_ITER | cv::TermCriteria::EPS, 30, 0.1));
	for (size_t k = 0; k < 4; k++) corners[k] = Eigen::Vector2d(pts[k].x + 0.5, pts[k].y + 0.5);
}
}  // namespace

struct TagDecoder::Impl
{
	TagDecoderParams params;
	apriltag_detector_t* detector = nullptr;
	std::vector<std::shared_ptr<apriltag_family>> aprilFamilies;  // tables shared by all decoders
	std::vector<std::string> requested;  // as asked, for naming nested ArUco ids
	struct ArucoFamily
	{
		std::string name;
		cv::Ptr<cv::aruco::Dictionary> dictionary;
		int cells = 0, borderStart = 0, borderCells = 0;  // the rendered bitmap's grid
		double errorCorrectionRate = 0;  // 0 for weak families: exact codes only
	};
	std::vector<ArucoFamily> aruco;

	/** OpenCV's identify on the bits inside each quad, read as is and
	 *  mirrored. Bits are thresholded halfway between the black border ring
	 *  and the white quiet zone around it: both are known, so the threshold
	 *  needs no global statistics and no intensity scale. */
	void decodeAruco(const cv::Mat& img, const std::vector<Quad>& quads, std::vector<DecodedTag2D>& out) const
	{
		for (const Quad& q : quads)
			for (const ArucoFamily& f : aruco)
			{
				const int m = f.dictionary->markerSize, b0 = f.borderStart, b1 = f.borderStart + f.borderCells - 1;
				const std::vector<float> sample = sampleCells(img, q, f.cells, b0, b1 + 1);
				if (sample.empty()) continue;
				double ring = 0, quiet = 0;
				int nr = 0, nq = 0;
				for (int r = 0; r < f.cells; r++)
					for (int c = 0; c < f.cells; c++)
					{
						const float v = sample[static_cast<size_t>(r * f.cells + c)];
						const bool inside = r >= b0 && r <= b1 && c >= b0 && c <= b1;
						if (!inside) quiet += v, nq++;
						else if (r == b0 || r == b1 || c == b0 || c == b1) ring += v, nr++;
					}
				ring /= std::max(nr, 1);
				quiet /= std::max(nq, 1);
				if (quiet - ring < 20) continue;  // no dark square on a light ground
				const float threshold = static_cast<float>(0.5 * (ring + quiet));
				int borderErrors = 0;
				for (int r = b0; r <= b1; r++)
					for (int c = b0; c <= b1; c++)
						if ((r == b0 || r == b1 || c == b0 || c == b1) && sample[static_cast<size_t>(r * f.cells + c)] > threshold)
							borderErrors++;
				if (borderErrors > params.maxBorderErrorRate * nr) continue;
				cv::Mat bits(m, m, CV_8UC1);
				for (int r = 0; r < m; r++)
					for (int c = 0; c < m; c++)
						bits.at<uint8_t>(r, c) = sample[static_cast<size_t>((r + b0 + 1) * f.cells + c + b0 + 1)] > threshold;
				for (bool mirrored : {false, true})
				{
					if (mirrored && !params.tryMirrored) break;
					cv::Mat read = bits;
					if (mirrored) cv::flip(bits, read, 1);
					int id = -1, rotation = 0;
					if (!f.dictionary->identify(read, id, rotation, f.errorCorrectionRate)) continue;
					DecodedTag2D d;
					d.family = reportedFamily(requested, f.name, id);
					if (d.family.empty()) continue;
					d.id = id;
					d.hamming = f.dictionary->getDistanceToId(read, id, true);
					d.margin = 100;
					d.mirrored = mirrored;
					d.corners = orderedCorners(q, bestOrder(f.name, id, sample, threshold, mirrored));
					refineCorners(img, d.corners);
					out.push_back(d);
				}
			}
	}

	/** A family read in the mirror: the same codes and decode table, each
	 *  bit sampled at its mirror position across the tag's vertical axis. */
	struct MirroredFamily
	{
		apriltag_family_t family{};
		std::vector<uint32_t> bitX, bitY;
	};
	std::vector<std::unique_ptr<MirroredFamily>> mirrored;

	/** `plain` as read in the mirror, added to the detector. libapriltag
	 *  then finds the image's quads once and decodes each as read and
	 *  mirrored: decoding the flipped image repeated the thresholding,
	 *  segmentation and quad fitting, half of its time. */
	void addMirrored(const apriltag_family_t& plain, int bitsCorrected)
	{
		auto m = std::make_unique<MirroredFamily>();
		m->family = plain;  // codes, name and the shared decode table (impl) are the plain family's
		for (uint32_t k = 0; k < plain.nbits; k++)
		{
			// Bit cells are numbered 0 .. width_at_border-1 across the border
			// (outside it, reversed-border families, as wrapped negatives).
			m->bitX.push_back(static_cast<uint32_t>(plain.width_at_border - 1 - static_cast<int32_t>(plain.bit_x[k])));
			m->bitY.push_back(plain.bit_y[k]);
		}
		m->family.bit_x = m->bitX.data();
		m->family.bit_y = m->bitY.data();
		apriltag_detector_add_family_bits(detector, &m->family, bitsCorrected);  // impl set: builds no table
		mirrored.push_back(std::move(m));
	}

	bool isMirrored(const apriltag_family_t* f) const
	{
		return std::any_of(mirrored.begin(), mirrored.end(), [f](const auto& m) { return &m->family == f; });
	}

	void decodeAprilTags(const cv::Mat& img, std::vector<DecodedTag2D>& out) const
	{
		image_u8_t im{img.cols, img.rows, static_cast<int32_t>(img.step), const_cast<uint8_t*>(img.data)};
		zarray_t* dets = apriltag_detector_detect(detector, &im);
		for (int i = 0; i < zarray_size(dets); i++)
		{
			apriltag_detection_t* det = nullptr;
			zarray_get(dets, i, &det);
			if (det->decision_margin < params.minDecisionMargin) continue;
			DecodedTag2D d;
			d.family = det->family->name;
			d.id = det->id;
			d.margin = det->decision_margin;
			d.hamming = det->hamming;
			d.mirrored = isMirrored(det->family);
			// libapriltag wraps p[] counter-clockwise from bottom-left.
			for (int k = 0; k < 4; k++) d.corners[k] = Eigen::Vector2d(det->p[3 - k][0], det->p[3 - k][1]);
			if (d.mirrored)
			{
				// libapriltag turns the corners by the rotation it decoded in,
				// one way; mirrored bits turn the other, so its order is right
				// only up to a half turn: the bitmap itself picks the order.
				const TagBitmap bm = renderTagBitmap(d.family, d.id);
				const std::vector<float> sample =
					sampleCells(img, d.corners, bm.cells, bm.borderStart, bm.borderStart + bm.borderCells);
				if (sample.empty()) continue;
				double mean = 0;
				for (float v : sample) mean += v / static_cast<double>(sample.size());
				d.corners = orderedCorners(d.corners, bestOrder(d.family, d.id, sample, static_cast<float>(mean), true));
			}
			out.push_back(d);
		}
		apriltag_detections_destroy(dets);
	}
};

TagDecoder::TagDecoder(const std::vector<std::string>& families, TagDecoderParams params) : impl_(new Impl)
{
	impl_->params = params;
	impl_->requested = families;
	for (const auto& name : searchFamilies(families))
	{
		const TagFamilyInfo* info = findFamily(name);
		if (!info) continue;
		if (info->system == TagSystem::AprilTag)
		{
			if (!impl_->detector)
			{
				impl_->detector = apriltag_detector_create();
				impl_->detector->quad_decimate = params.quadDecimate;
				impl_->detector->quad_sigma = 0.0f;
				impl_->detector->nthreads = 1;  // the pipeline parallelises across candidates
				impl_->detector->refine_edges = 1;
				impl_->detector->decode_sharpening = 0.25;
			}
			const int bits = info->weak() ? 0 : affordableBitsCorrected(name, params.maxBitsCorrected);
			impl_->aprilFamilies.push_back(sharedAprilTagFamily(name, bits));
			apriltag_detector_add_family_bits(impl_->detector, impl_->aprilFamilies.back().get(), bits);
			if (params.tryMirrored) impl_->addMirrored(*impl_->aprilFamilies.back(), bits);
		}
		else
		{
			const TagBitmap first = renderTagBitmap(name, 0);
			impl_->aruco.push_back({name, arucoDictionary(name), first.cells, first.borderStart, first.borderCells,
									info->weak() ? 0.0 : kErrorCorrectionRate});
		}
	}
}

TagDecoder::~TagDecoder()
{
	if (!impl_->detector) return;
	zarray_clear(impl_->detector->tag_families);  // the tables are shared: not the detector's to free
	apriltag_detector_destroy(impl_->detector);
}

std::vector<DecodedTag2D> TagDecoder::decode(const cv::Mat& gray8, const std::vector<Quad>* quads) const
{
	CV_Assert(gray8.type() == CV_8UC1 && gray8.isContinuous());
	std::vector<DecodedTag2D> out;
	if (impl_->detector) impl_->decodeAprilTags(gray8, out);
	if (!impl_->aruco.empty())
		impl_->decodeAruco(gray8, quads ? *quads : findTagQuads(gray8, impl_->params.maxQuads), out);
	dropRepeatedReads(out);
	return out;
}

void dropRepeatedReads(std::vector<DecodedTag2D>& reads)
{
	std::vector<DecodedTag2D> kept;
	for (const DecodedTag2D& d : reads)
	{
		const double side = (d.corners[1] - d.corners[0]).norm();
		const bool repeated = std::any_of(kept.begin(), kept.end(), [&](const DecodedTag2D& k) {
			if (k.family != d.family || k.id != d.id || k.mirrored != d.mirrored) return false;
			for (int c = 0; c < 4; c++)
				if ((k.corners[c] - d.corners[c]).norm() > 0.2 * side) return false;
			return true;
		});
		if (!repeated) kept.push_back(d);
	}
	reads = std::move(kept);
}

const TagDecoderParams& TagDecoder::params() const { return impl_->params; }

}  // namespace tagmap
