#include "tagmap/pipeline_params.h"

#include <cmath>
#include <functional>
#include <map>
#include <set>
#include <stdexcept>

#include "tagmap/errors.h"
#include "tagmap/tag_family.h"
#include "tagmap/yaml_text.h"

namespace tagmap
{
namespace
{
// One table of (section, key) -> field binding serves loading, dumping and
// unknown-key detection, so the three can never disagree.
struct Binding
{
	std::function<void(const mrpt::containers::yaml&)> load;
	// Writes map[key]: MRPT's yaml only accepts a scalar through a map proxy.
	std::function<void(mrpt::containers::yaml& map, const std::string& key)> dump;
};

template <typename T>
Binding bind(T& field)
{
	return {[&field](const mrpt::containers::yaml& v) { field = yamlScalarAs<T>(v); },
			[&field](mrpt::containers::yaml& map, const std::string& key) { map[key] = field; }};
}

// Lists (families, image variants, clustering scales) load from a YAML
// sequence and dump as one.
template <typename T>
Binding bind(std::vector<T>& field)
{
	return {[&field](const mrpt::containers::yaml& v) {
				if (!v.isSequence()) throw std::invalid_argument("expected a list");
				field.clear();
				for (const auto& e : v.asSequence()) field.push_back(yamlScalarAs<T>(e));
			},
			[&field](mrpt::containers::yaml& map, const std::string& key) {
				mrpt::containers::yaml seq = mrpt::containers::yaml::Sequence();
				for (const auto& e : field) seq.push_back(e);
				map[key] = seq;
			}};
}

std::map<std::string, std::map<std::string, Binding>> bindings(PipelineParams& p)
{
	return {
		{"",
		 {{"tag_size", bind(p.tagSize)},
		  {"threads", bind(p.threads)},
		  {"gradient_radius_spacings", bind(p.gradientRadiusSpacings)},
		  {"image_variants", bind(p.imageVariants)}}},
		{"gradient", {{"threshold", bind(p.gradient.threshold)}, {"min_neighbours", bind(p.gradient.minNeighbours)},
		  {"min_explained", bind(p.gradient.minExplained)},
		  {"density_levels", bind(p.gradient.densityLevels)}}},
		{"clustering",
		 {{"tolerance_spacings", bind(p.clustering.toleranceSpacings)},
		  {"min_points", bind(p.clustering.minPoints)},
		  {"scales", bind(p.clustering.scales)}}},
		{"candidates",
		 {{"min_tag_size", bind(p.candidates.minTagSize)},
		  {"max_tag_size", bind(p.candidates.maxTagSize)},
		  {"max_aspect", bind(p.candidates.maxAspect)},
		  {"max_oversize", bind(p.candidates.maxOversize)},
		  {"shortfall", bind(p.candidates.shortfall)},
		  {"max_flatness", bind(p.candidates.maxFlatness)},
		  {"split_aspect", bind(p.candidates.splitAspect)}}},
		{"gather",
		 {{"enlarge", bind(p.gather.enlarge)},
		  {"slab_spacings", bind(p.gather.slabSpacings)},
		  {"octree_cells_per_leaf", bind(p.gather.octreeCellsPerLeaf)}}},
		{"plane",
		 {{"pixel_spacings", bind(p.plane.pixelSpacings)},
		  {"splat_spacings", bind(p.plane.splatSpacings)},
		  {"max_image_pixels", bind(p.plane.maxImagePixels)},
		  {"pixels_per_cell", bind(p.plane.pixelsPerCell)},
		  {"inlier_sigmas", bind(p.plane.inlierSigmas)}}},
		{"decoder",
		 {{"try_mirrored", bind(p.decoder.tryMirrored)},
		  {"max_bits_corrected", bind(p.decoder.maxBitsCorrected)},
		  {"min_decision_margin", bind(p.decoder.minDecisionMargin)},
		  {"max_quads", bind(p.decoder.maxQuads)},
		  {"max_border_error_rate", bind(p.decoder.maxBorderErrorRate)}}},
		{"soft_decoder",
		 {{"enabled", bind(p.softDecoder.enabled)},
		  {"min_correlation", bind(p.softDecoder.minCorrelation)},
		  {"min_gap", bind(p.softDecoder.minGap)}}},
		{"evidence",
		 {{"chance_budget", bind(p.evidence.chanceBudget)},
		  {"erasure_band", bind(p.evidence.erasureBand)},
		  {"max_border_error_rate", bind(p.evidence.maxBorderErrorRate)},
		  {"max_quiet_error_rate", bind(p.evidence.maxQuietErrorRate)}}},
		{"support_plane",
		 {{"enabled", bind(p.supportPlane.enabled)},
		  {"reach_sizes", bind(p.supportPlane.reachSizes)},
		  {"step_sigmas", bind(p.supportPlane.stepSigmas)}}},
		{"front_side",
		 {{"enabled", bind(p.frontSide.enabled)},
		  {"depth_sizes", bind(p.frontSide.depthSizes)},
		  {"columns", bind(p.frontSide.columns)},
		  {"blocked_fraction", bind(p.frontSide.blockedFraction)},
		  {"free_fraction", bind(p.frontSide.freeFraction)}}},
		{"merge", {{"conflict_sigmas", bind(p.merge.conflictSigmas)}}},
		{"sensor_view",
		 {{"enabled", bind(p.sensorView.enabled)},
		  {"pixel_spacings", bind(p.sensorView.pixelSpacings)},
		  {"splat_spacings", bind(p.sensorView.splatSpacings)},
		  {"fill_spacings", bind(p.sensorView.fillSpacings)},
		  {"seam_overlap_deg", bind(p.sensorView.seamOverlapDeg)},
		  {"max_image_pixels", bind(p.sensorView.maxImagePixels)},
		  {"quad_decimate", bind(p.sensorView.quadDecimate)},
		  {"max_quads", bind(p.sensorView.maxQuads)},
		  {"near_sides", bind(p.sensorView.nearSides)}}},
		{"refinement",
		 {{"refine", bind(p.refinement.refine)},
		  {"min_pattern_fit", bind(p.refinement.minPatternFit)},
		  {"iterations", bind(p.refinement.iterations)}}},
	};
}

// MRPT's as<std::string>() on a map or list throws a many-line exception;
// the user must get one line naming the key instead.
std::string scalarText(const mrpt::containers::yaml& n, const std::string& where)
{
	if (!n.isScalar()) throw std::invalid_argument("'" + where + "' must be a single value, not a map or list");
	return yamlScalarText(n);
}

void loadSection(const mrpt::containers::yaml& node, const std::string& section, std::map<std::string, Binding>& keys,
				 const std::map<std::string, std::map<std::string, Binding>>& all)
{
	std::set<std::string> allowed;
	for (const auto& [key, binding] : keys) allowed.insert(key);
	if (section.empty())
	{
		for (const auto& [name, sectionKeys] : all)
			if (!name.empty()) allowed.insert(name);
		allowed.insert("families");
	}
	requireKnownKeys(node, allowed, section.empty() ? "" : section + ".");
	for (const auto& [k, v] : node.asMap())
	{
		const std::string key = yamlScalarText(k);
		const std::string where = section.empty() ? key : section + "." + key;
		auto it = keys.find(key);
		if (it == keys.end()) continue;  // a section or `families`, loaded by the caller
		try
		{
			it->second.load(v);
		}
		catch (const std::exception& e)
		{
			throw std::invalid_argument("parameter '" + where + "' has an invalid value: " + errorSummary(e.what()));
		}
	}
}
}  // namespace

PipelineParams PipelineParams::fromYaml(const mrpt::containers::yaml& y)
{
	PipelineParams p;
	if (y.isNullNode()) return p;
	if (!y.isMap()) throw std::invalid_argument("configuration must be a map of parameters");
	auto all = bindings(p);
	loadSection(y, "", all[""], all);
	for (auto& [section, keys] : all)
	{
		if (section.empty() || !y.has(section)) continue;
		if (!y[section].isMap()) throw std::invalid_argument("section '" + section + "' must be a map");
		loadSection(y[section], section, keys, all);
	}
	if (y.has("families"))
	{
		const auto& f = y["families"];
		std::string list;
		if (f.isSequence())
			for (const auto& e : f.asSequence()) list += scalarText(e, "families: an entry") + ",";
		else if (!f.isNullNode())
			list = scalarText(f, "families");
		p.families = list.empty() ? std::vector<std::string>{} : parseFamilyList(list);
	}
	p.validate();
	return p;
}

PipelineParams PipelineParams::fromYamlFile(const std::string& path)
{
	// Not yaml::FromFile: it prints syntax errors over several stderr lines.
	const mrpt::containers::yaml y = readYamlFile(path);
	try
	{
		return fromYaml(y);
	}
	catch (const std::invalid_argument& e)
	{
		throw InputError(path, "", e.what());
	}
}

mrpt::containers::yaml PipelineParams::toYaml() const
{
	PipelineParams copy = *this;
	auto all = bindings(copy);
	mrpt::containers::yaml y = mrpt::containers::yaml::Map();
	// Every family is '' (a comma list), not []: MRPT prints an empty
	// sequence as nothing at all, which its own parser then rejects.
	if (families.empty())
		y["families"] = std::string();
	else
	{
		mrpt::containers::yaml fams = mrpt::containers::yaml::Sequence();
		for (const auto& f : families) fams.push_back(f);
		y["families"] = fams;
	}
	for (auto& [section, keys] : all)
	{
		mrpt::containers::yaml sub = mrpt::containers::yaml::Map();
		for (auto& [k, b] : keys) b.dump(section.empty() ? y : sub, k);
		if (!section.empty()) y[section] = sub;
	}
	return y;
}

void PipelineParams::validate() const
{
	auto positive = [](double v, const char* name) {
		if (!(v > 0) || !std::isfinite(v))
			throw std::invalid_argument(std::string(name) + " must be positive (got " + std::to_string(v) + ")");
	};
	if (!(tagSize >= 0 && tagSize <= kMaxTagSize))
		throw std::invalid_argument("tag_size must be a length in metres up to 10, or 0 for unknown (got " +
									std::to_string(tagSize) + ")");
	positive(gradientRadiusSpacings, "gradient_radius_spacings");
	positive(gradient.threshold, "gradient.threshold");
	if (gradient.densityLevels < 1 || gradient.densityLevels > 6)
		throw std::invalid_argument("gradient.density_levels must be 1..6");
	if (!(gradient.minExplained >= 0 && gradient.minExplained < 1))
		throw std::invalid_argument("gradient.min_explained must be in [0, 1)");
	positive(clustering.toleranceSpacings, "clustering.tolerance_spacings");
	if (clustering.scales.empty()) throw std::invalid_argument("clustering.scales must not be empty");
	for (double sc : clustering.scales) positive(sc, "clustering.scales entries");
	positive(candidates.minTagSize, "candidates.min_tag_size");
	positive(candidates.maxTagSize, "candidates.max_tag_size");
	if (candidates.maxTagSize > kMaxTagSize) throw std::invalid_argument("candidates.max_tag_size must be at most 10 (metres)");
	if (candidates.maxTagSize < candidates.minTagSize)
		throw std::invalid_argument("candidates.max_tag_size must be at least candidates.min_tag_size");
	if (candidates.maxOversize < 1) throw std::invalid_argument("candidates.max_oversize must be at least 1");
	if (candidates.maxAspect < 1) throw std::invalid_argument("candidates.max_aspect must be at least 1");
	positive(gather.enlarge, "gather.enlarge");
	positive(plane.pixelSpacings, "plane.pixel_spacings");
	positive(plane.splatSpacings, "plane.splat_spacings");
	if (plane.maxImagePixels < 32) throw std::invalid_argument("plane.max_image_pixels must be at least 32");
	if (!(plane.pixelsPerCell == 0 || plane.pixelsPerCell >= 2))
		throw std::invalid_argument("plane.pixels_per_cell must be 0 (no cap) or at least 2");
	if (gather.octreeCellsPerLeaf < 1) throw std::invalid_argument("gather.octree_cells_per_leaf must be at least 1");
	for (const auto& v : imageVariants)
		if (v != "raw" && v != "otsu" && v != "half" && v != "half_smooth")
			throw std::invalid_argument("image_variants: unknown variant '" + v + "' (valid: raw, otsu, half, half_smooth)");
	if (!(evidence.chanceBudget > 0 && evidence.chanceBudget <= 1))
		throw std::invalid_argument("evidence.chance_budget must be in (0, 1]");
	if (!(evidence.maxBorderErrorRate >= 0 && evidence.maxBorderErrorRate <= 1) ||
		!(evidence.maxQuietErrorRate >= 0 && evidence.maxQuietErrorRate <= 1) ||
		!(evidence.erasureBand >= 0 && evidence.erasureBand < 0.5))
		throw std::invalid_argument("evidence.max_border_error_rate and max_quiet_error_rate must be in [0, 1], erasure_band in [0, 0.5)");
	if (!(supportPlane.reachSizes >= 0.5 && supportPlane.reachSizes <= 2.5))
		throw std::invalid_argument("support_plane.reach_sizes must be in [0.5, 2.5]");
	positive(supportPlane.stepSigmas, "support_plane.step_sigmas");
	positive(frontSide.depthSizes, "front_side.depth_sizes");
	positive(sensorView.pixelSpacings, "sensor_view.pixel_spacings");
	positive(sensorView.splatSpacings, "sensor_view.splat_spacings");
	positive(sensorView.fillSpacings, "sensor_view.fill_spacings");
	if (!(sensorView.quadDecimate >= 1 && sensorView.quadDecimate <= 8))
		throw std::invalid_argument("sensor_view.quad_decimate must be in [1, 8]");
	if (!(sensorView.seamOverlapDeg >= 0 && sensorView.seamOverlapDeg <= 90))
		throw std::invalid_argument("sensor_view.seam_overlap_deg must be in [0, 90]");
	if (sensorView.maxImagePixels < 64 || sensorView.maxImagePixels > 16384)
		throw std::invalid_argument("sensor_view.max_image_pixels must be in [64, 16384]");
	if (sensorView.maxQuads < 1 || sensorView.maxQuads > 1000) throw std::invalid_argument("sensor_view.max_quads must be 1..1000");
	if (!(sensorView.nearSides >= 1 && sensorView.nearSides <= 100))
		throw std::invalid_argument("sensor_view.near_sides must be in [1, 100]");
	if (!(merge.conflictSigmas >= 0)) throw std::invalid_argument("merge.conflict_sigmas must be at least 0");
	if (frontSide.columns < 1 || frontSide.columns > 64) throw std::invalid_argument("front_side.columns must be in [1, 64]");
	if (!(frontSide.freeFraction >= 0 && frontSide.freeFraction < frontSide.blockedFraction &&
		  frontSide.blockedFraction <= 1))
		throw std::invalid_argument("front_side: need 0 <= free_fraction < blocked_fraction <= 1");
	if (decoder.maxBitsCorrected < 0 || decoder.maxBitsCorrected > 3)
		throw std::invalid_argument("decoder.max_bits_corrected must be 0..3");
	// The rest, unchecked, would give silently empty results at best, and
	// unbounded loops, thread counts or allocations at worst.
	if (threads > 1024) throw std::invalid_argument("threads must be 0 (all cores) to 1024");
	if (gradient.minNeighbours < 0) throw std::invalid_argument("gradient.min_neighbours must be >= 0");
	if (clustering.minPoints < 1 || clustering.minPoints > (1u << 30))
		throw std::invalid_argument("clustering.min_points must be 1..2^30");
	if (!(candidates.shortfall >= 0 && candidates.shortfall < 1))
		throw std::invalid_argument("candidates.shortfall must be in [0, 1)");
	positive(candidates.maxFlatness, "candidates.max_flatness");
	if (!(candidates.splitAspect >= 0 && candidates.splitAspect <= 100))
		throw std::invalid_argument("candidates.split_aspect must be in [0, 100] (0: off)");
	positive(gather.slabSpacings, "gather.slab_spacings");
	positive(plane.inlierSigmas, "plane.inlier_sigmas");
	if (!(decoder.minDecisionMargin >= 0)) throw std::invalid_argument("decoder.min_decision_margin must be >= 0");
	if (decoder.maxQuads < 1 || decoder.maxQuads > 1000) throw std::invalid_argument("decoder.max_quads must be 1..1000");
	if (!(decoder.maxBorderErrorRate >= 0 && decoder.maxBorderErrorRate < 1))
		throw std::invalid_argument("decoder.max_border_error_rate must be in [0, 1)");
	if (!(refinement.minPatternFit >= 0 && refinement.minPatternFit <= 1))
		throw std::invalid_argument("refinement.min_pattern_fit must be in [0, 1]");
	if (refinement.iterations < 0 || refinement.iterations > 1000)
		throw std::invalid_argument("refinement.iterations must be 0..1000");
}

}  // namespace tagmap
