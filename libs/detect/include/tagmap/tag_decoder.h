// Stage 5: decoding an intensity image with the real fiducial decoders,
// as rendered and mirrored: the box a candidate was rendered from has no
// preferred side, so the tag may be seen from "behind".
//  - AprilTag families: libapriltag, each family also read in the mirror
//    (its bits sampled at their mirror positions, the same codes and decode
//    table), so the image's quads are found once for both sides.
//  - ArUco dictionaries: OpenCV's Dictionary::identify on the bits sampled
//    inside each tag-shaped quad (tag_quads.h), and on their mirror image.
//    The quads are found once per image: running cv::aruco::detectMarkers
//    per dictionary and per side repeated the same thresholding and contour
//    search ten times and was half of the decode stage's time.
#pragma once

#include <Eigen/Core>
#include <array>
#include <memory>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "tagmap/tag_quads.h"

namespace tagmap
{
struct DecodedTag2D
{
	std::string family;
	int id = -1;
	/** Pixel coordinates, x right, y down, with pixel (c, r) covering
	 *  [c, c+1) x [r, r+1); vertex-index order (TL, TR, BR, BL of the
	 *  upright pattern), already mapped back to the unmirrored image. */
	std::array<Eigen::Vector2d, 4> corners;
	double margin = 0;  // libapriltag decision margin; for ArUco a fixed 100
	int hamming = 0;  // bits the decoder corrected; -1 for the soft decoder (no bit decision)
	bool mirrored = false;  // found on the mirrored image
};

struct TagDecoderParams
{
	bool tryMirrored = true;
	/** Bits an AprilTag decode may correct. Fewer where the family's decode
	 *  table would not fit its budget (affordableBitsCorrected), none for
	 *  weak families (TagFamilyInfo::weak). */
	int maxBitsCorrected = 2;
	/** Reject AprilTag decodes below this decision margin (libapriltag's
	 *  contrast measure; the image is contrast-normalised, so it is scale free). */
	double minDecisionMargin = 25;
	/** Largest tag-shaped quads tried per image (ArUco and soft decoder). */
	int maxQuads = 8;
	/** Border cells an ArUco decode may find white, as a fraction (OpenCV's
	 *  maxErroneousBitsInBorderRate). */
	double maxBorderErrorRate = 0.2;
	/** libapriltag's quad_decimate: quads are searched on an image this
	 *  many times smaller, then fitted at full resolution. */
	float quadDecimate = 1.0f;
};

/** Removes reads of the same tag (family, id, side) from nearly the same
 *  square, found through two quads of one outline: the first is kept. */
void dropRepeatedReads(std::vector<DecodedTag2D>& reads);

class TagDecoder
{
   public:
	/** `families`: names from supportedFamilies(). Not thread-safe: use one
	 *  decoder per thread (libapriltag keeps scratch state in the detector). */
	explicit TagDecoder(const std::vector<std::string>& families, TagDecoderParams params = {});
	~TagDecoder();
	TagDecoder(const TagDecoder&) = delete;
	TagDecoder& operator=(const TagDecoder&) = delete;

	/** All tags in an 8-bit grey image (black ink dark), raw then mirrored.
	 *  `quads`: the image's findTagQuads() when the caller has them already. */
	std::vector<DecodedTag2D> decode(const cv::Mat& gray8, const std::vector<Quad>* quads = nullptr) const;
	const TagDecoderParams& params() const;

   private:
	struct Impl;
	std::unique_ptr<Impl> impl_;
};

}  // namespace tagmap
