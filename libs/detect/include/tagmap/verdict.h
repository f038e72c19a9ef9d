// What happened to a candidate cluster, one value per outcome: the filter's
// rejections, the read checks', the 3D checks' and "decoded". Each has the
// name written in reports (HTML, candidate images, bench tables) and its
// meaning for people, in one table, so a misspelt verdict does not compile.
#pragma once

#include <array>
#include <ostream>
#include <string>

namespace tagmap
{
enum class Verdict
{
	Candidate,  // passed the filter (so far)
	Size,
	Squareness,
	NotFlat,
	SameBox,
	OnDecodedTag,
	NotPlanar,
	NoDecode,
	NoFamilyCanPass,
	TooFewPoints,
	NoCodeShown,
	ByChance,
	GridOffImage,
	NoBorder,
	NoQuietZone,
	SizeMismatch,
	PatternMismatch,
	CodeNotInPoints,
	WrongSide,
	TurnSymmetric,
	Decoded,
};

struct VerdictInfo
{
	Verdict verdict;
	const char* name;  // as written in reports: never rename
	const char* meaning;
};

inline constexpr std::array<VerdictInfo, 21> kVerdicts = {{
	{Verdict::Candidate, "candidate", "passed the filter, not processed"},
	{Verdict::Size, "size", "box edge outside the tag-size range (--tag-size, candidates.min/max_tag_size)"},
	{Verdict::Squareness, "squareness", "box too elongated for a square tag (candidates.max_aspect)"},
	{Verdict::NotFlat, "not_flat", "box too thick for a printed tag (candidates.max_flatness)"},
	{Verdict::SameBox, "same_box",
	 "the box of an earlier candidate, to within a point spacing: it gathers the same points, decoded once"},
	{Verdict::OnDecodedTag, "on_decoded_tag",
	 "not decoded: its box is centred (within half the tag's size) on a tag that a candidate of its group before "
	 "it decoded, or its image showed outlines or reads only on such a tag; it would read that tag again "
	 "(decode_schedule.h)"},
	{Verdict::NotPlanar, "not_planar", "the gathered points do not fit one plane"},
	{Verdict::NoDecode, "no_decode", "no decoder read a tag of the requested families on the image"},
	{Verdict::NoFamilyCanPass, "no_family_can_pass",
	 "not decoded: no family asked for could pass the chance budget even read exactly (weak families searched "
	 "with others; evidence.chance_budget)"},
	{Verdict::TooFewPoints, "too_few_points",
	 "fewer points gathered than the cells a read of any family searched must measure (its code cells and "
	 "black border ring): no read of it could be evidence"},
	{Verdict::NoCodeShown, "no_code_shown",
	 "no outline of a tag's size in the image shows code cells of both colours inside a dark ring in a light "
	 "margin (a window pane, a plain panel): no decoder's read there could pass"},
	{Verdict::ByChance, "by_chance",
	 "a code was read, but a random pattern would match some code that well too often (evidence.chance_budget)"},
	{Verdict::GridOffImage, "grid_off_image",
	 "a code was read, but its family's grid reaches past the candidate's image, and past the image of the box "
	 "the whole grid fits in too: its cells cannot be sampled (families with data cells outside their border)"},
	{Verdict::NoBorder, "no_border",
	 "a code was read, but the black border ring is not black (evidence.max_border_error_rate), and the code "
	 "is not strong enough to outweigh it"},
	{Verdict::NoQuietZone, "no_quiet_zone",
	 "a code was read, but the white margin around it is not white: a grid or a larger pattern "
	 "(evidence.max_quiet_error_rate)"},
	{Verdict::SizeMismatch, "size_mismatch",
	 "decoded, but the decoded square is not a tag size asked for (--tag-size, candidates.min/max_tag_size)"},
	{Verdict::PatternMismatch, "pattern_mismatch",
	 "decoded, but the points disagree with the bitmap (refinement.min_pattern_fit)"},
	{Verdict::CodeNotInPoints, "code_not_in_points",
	 "decoded on the image, but the tag's own points, read cell by cell at the fitted pose, do not show that "
	 "code beyond chance: the image's cells were interpolated (evidence.chance_budget)"},
	{Verdict::WrongSide, "wrong_side",
	 "decoded, but its printed face would look into the solid body behind it, with free space on its other "
	 "side: the mirror image of a tag (front_side)"},
	{Verdict::TurnSymmetric, "turn_symmetric",
	 "decoded, but the code is its own image under a half turn (aruco_original #1023): which corner is its "
	 "first, so its vertex order and its turn about the normal, cannot be read"},
	{Verdict::Decoded, "decoded", "a tag was read and its points match the tag's bitmap"},
}};

constexpr bool verdictTableInEnumOrder()
{
	for (size_t k = 0; k < kVerdicts.size(); k++)
		if (static_cast<size_t>(kVerdicts[k].verdict) != k) return false;
	return static_cast<size_t>(Verdict::Decoded) + 1 == kVerdicts.size();
}
static_assert(verdictTableInEnumOrder(), "kVerdicts: one row per Verdict, in enum order");

inline const VerdictInfo& verdictInfo(Verdict v) { return kVerdicts[static_cast<size_t>(v)]; }
inline const char* verdictName(Verdict v) { return verdictInfo(v).name; }
inline const char* verdictMeaning(Verdict v) { return verdictInfo(v).meaning; }
inline std::ostream& operator<<(std::ostream& os, Verdict v) { return os << verdictName(v); }

}  // namespace tagmap
