#include "tagmap/tag_decoder.h"

#include <apriltag/apriltag.h>

#include <opencv2/aruco.hpp>
#include <opencv2/imgproc.hpp>

#include "tagmap/apriltag_families.h"
#include "tagmap/tag_family.h"

namespace tagmap
{
namespace
{
}  // namespace

struct TagDecoder::Impl
{
	TagDecoderParams params;
	apriltag_detector_t* detector = nullptr;
	std::vector<std::shared_ptr<apriltag_family>> aprilFamilies;  // tables shared by all decoders
	std::vector<std::string> requested;  // as asked, for naming nested ArUco ids
	std::vector<std::string> arucoSearched;
	cv::Ptr<cv::aruco::DetectorParameters> arucoParams;

	void decodeOnce(const cv::Mat& img, bool mirrored, std::vector<DecodedTag2D>& out) const
	{
		if (detector)
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
				d.mirrored = mirrored;
				// libapriltag wraps p[] counter-clockwise from bottom-left.
				for (int k = 0; k < 4; k++) d.corners[k] = Eigen::Vector2d(det->p[3 - k][0], det->p[3 - k][1]);
				out.push_back(d);
			}
			apriltag_detections_destroy(dets);
		}
		for (const auto& searched : arucoSearched)
		{
			std::vector<std::vector<cv::Point2f>> corners;
			std::vector<int> ids;
			cv::aruco::detectMarkers(img, arucoDictionary(searched), corners, ids, arucoParams);
			for (size_t i = 0; i < ids.size(); i++)
			{
				const std::string family = reportedFamily(requested, searched, ids[i]);
				if (family.empty()) continue;
				DecodedTag2D d;
				d.family = family;
				d.id = ids[i];
				d.margin = 100;
				d.mirrored = mirrored;
				// OpenCV puts pixel centres on integers; ours are on half-integers.
				for (int k = 0; k < 4; k++) d.corners[k] = Eigen::Vector2d(corners[i][k].x + 0.5, corners[i][k].y + 0.5);
				out.push_back(d);
			}
		}
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
				impl_->detector->quad_decimate = 1.0f;  // our images are small and already at the right scale
				impl_->detector->quad_sigma = 0.0f;
				impl_->detector->nthreads = 1;  // the pipeline parallelises across candidates
				impl_->detector->refine_edges = 1;
				impl_->detector->decode_sharpening = 0.25;
			}
			const int bits = info->idCount > 10000 ? std::min(1, params.maxBitsCorrected) : params.maxBitsCorrected;
			impl_->aprilFamilies.push_back(sharedAprilTagFamily(name, bits));
			apriltag_detector_add_family_bits(impl_->detector, impl_->aprilFamilies.back().get(), bits);
		}
		else
			impl_->arucoSearched.push_back(name);
	}
	impl_->arucoParams = cv::aruco::DetectorParameters::create();
	impl_->arucoParams->cornerRefinementMethod = cv::aruco::CORNER_REFINE_SUBPIX;
	impl_->arucoParams->minMarkerPerimeterRate = 0.05;  // a candidate image is mostly tag
	impl_->arucoParams->maxErroneousBitsInBorderRate = 0.2;
}

TagDecoder::~TagDecoder()
{
	if (!impl_->detector) return;
	zarray_clear(impl_->detector->tag_families);  // the tables are shared: not the detector's to free
	apriltag_detector_destroy(impl_->detector);
}

std::vector<DecodedTag2D> TagDecoder::decode(const cv::Mat& gray8) const
{
	CV_Assert(gray8.type() == CV_8UC1 && gray8.isContinuous());
	std::vector<DecodedTag2D> out;
	impl_->decodeOnce(gray8, false, out);
	if (impl_->params.tryMirrored)
	{
		cv::Mat flipped;
		cv::flip(gray8, flipped, 1);
		std::vector<DecodedTag2D> mirroredFound;
		impl_->decodeOnce(flipped, true, mirroredFound);
		for (auto& d : mirroredFound)
		{
			for (auto& c : d.corners) c.x() = gray8.cols - c.x();
			out.push_back(d);
		}
	}
	return out;
}

}  // namespace tagmap
