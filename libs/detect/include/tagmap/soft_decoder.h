// Stage 5c: maximum-likelihood decoding of blurred tags. The camera
// decoders threshold each bit cell; a tag blurred by map drift or a wide
// beam footprint loses bits that way although its pattern is still there.
// Here every tag-shaped quad (findTagQuads) is sampled on each family's
// cell grid and correlated with every code of the
// family, in all 8 corner orderings (4 rotations, seen from either side).
// The best code is kept when it correlates well and clearly beats the
// runner-up; the pattern check in 3D then confirms or rejects it.
#pragma once

#include <map>
#include <memory>
#include <opencv2/core.hpp>
#include <optional>
#include <string>
#include <vector>

#include "tagmap/tag_decoder.h"
#include "tagmap/tag_quads.h"

namespace tagmap
{
struct SoftDecoderParams
{
	bool enabled = true;
	/** Pearson correlation of the sampled data cells (those that differ
	 *  between codes) with the code's; chance level for the best of N codes
	 *  in 8 orientations is about 0.6 for the largest families. */
	double minCorrelation = 0.7;
	double minGap = 0.15;  // over the best other code
	/** With some cells erased: the fewest code cells (of those that differ
	 *  between codes) that must be measured to correlate at all. */
	double minMeasuredFraction = 0.5;
};

class SoftTagDecoder
{
   public:
	SoftTagDecoder(const std::vector<std::string>& families, SoftDecoderParams params = {});
	~SoftTagDecoder();
	SoftTagDecoder(const SoftTagDecoder&) = delete;
	SoftTagDecoder& operator=(const SoftTagDecoder&) = delete;

	/** Tags among `quads` (findTagQuads) of an 8-bit grey image; corners as
	 *  in TagDecoder. `measured` (optional, sampleMeasuredCells()): cells
	 *  nothing was scanned in are left out of the correlation (erasures), as
	 *  long as most of the code's cells were scanned; a tag partly in a
	 *  scan's gap then reads on the cells its points show.
	 *
	 *  A quad is an outline of a tag's border square, or, for a family whose
	 *  border ring is white (tagStandard*, tagCircle*, tagCustom48h12), of
	 *  the black ring around it or of the whole printed tag: dark-blob
	 *  outlines trace those, and the frame every code prints tells which
	 *  (the best one is read). `whiteBorders` false: those families are
	 *  not read at all, as before they had outlines of their own (a scan's
	 *  sensor view, whose many quads made the spinning bench with 8
	 *  families 14 -> 28 ms a scan). */
	std::vector<DecodedTag2D> decode(const cv::Mat& gray8, const std::vector<Quad>& quads,
									 const cv::Mat* measured = nullptr, bool whiteBorders = true) const;

   private:
	struct FamilyCodes;
	SoftDecoderParams params_;
	std::vector<std::string> requested_;
	std::vector<std::string> families_;  // searched: nested ArUco collapsed
	const FamilyCodes& codesOf(const std::string& family) const;
	struct BestCodes;
	/** The best and runner-up code over all 8 orientations of `sample`,
	 *  each compared on the measured cells only (erased cells are NaN). */
	static BestCodes correlate(const FamilyCodes& fc, const std::vector<float>& sample);
	/** Pearson correlation of the sample's frame cells (the same in every
	 *  code) with the family's frame. */
	static double frameCorrelation(const FamilyCodes& fc, const std::vector<float>& sample);
	/** The read of `family` on `q`, if its frame and code are clear. */
	std::optional<DecodedTag2D> read(const cv::Mat& gray8, const cv::Mat* measured, const Quad& q,
									 const std::string& family, const FamilyCodes& fc) const;
};

}  // namespace tagmap
