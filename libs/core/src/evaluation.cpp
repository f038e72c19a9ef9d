#include "tagmap/evaluation.h"

#include <algorithm>
#include <cmath>

#include "tagmap/tag_family.h"
#include "tagmap/yaml_text.h"

namespace tagmap
{
int Evaluation::found() const
{
	return static_cast<int>(std::count_if(perTruth.begin(), perTruth.end(), [](const TagError& e) { return e.found; }));
}

int Evaluation::missed() const
{
	return static_cast<int>(
		std::count_if(perTruth.begin(), perTruth.end(), [](const TagError& e) { return e.required && !e.found; }));
}

int Evaluation::falseOf(FalseKind kind) const
{
	return static_cast<int>(std::count(falseKinds.begin(), falseKinds.end(), kind));
}

const char* falseKindName(FalseKind kind)
{
	switch (kind)
	{
		case FalseKind::WrongId: return "wrong family/id";
		case FalseKind::Duplicate: return "duplicate";
		default: return "false tag";
	}
}

Evaluation evaluateDetections(const std::vector<TagDetection>& found, const std::vector<TagDetection>& truth,
							  const std::vector<bool>& required)
{
	Evaluation ev;
	std::vector<bool> used(found.size(), false);
	for (size_t ti = 0; ti < truth.size(); ti++)
	{
		const TagDetection& t = truth[ti];
		TagError e;
		e.family = t.family;
		e.id = t.id;
		e.required = ti >= required.size() || required[ti];
		for (size_t k = 0; k < found.size() && !e.found; k++)
		{
			const auto& d = found[k];
			if (used[k] || !sameMarker(d.family, d.id, t.family, t.id)) continue;
			if ((d.position() - t.position()).norm() > 0.5 * t.size) continue;
			used[k] = true;
			e.found = true;
			e.foundIndex = static_cast<int>(k);
			e.positionError = (d.position() - t.position()).cwiseAbs();
			e.rotationErrorDeg = (rollPitchYaw(t.pose.linear().transpose() * d.pose.linear()) * 180.0 / M_PI).cwiseAbs();
			e.vertexOrderCorrect = true;
			for (int c = 0; c < 4; c++)
			{
				e.maxCornerError = std::max(e.maxCornerError, (d.corners[c] - t.corners[c]).norm());
				for (int o = 0; o < 4; o++)
					if (o != c && (d.corners[c] - t.corners[o]).norm() < (d.corners[c] - t.corners[c]).norm())
						e.vertexOrderCorrect = false;
			}
		}
		ev.perTruth.push_back(e);
	}
	for (size_t k = 0; k < found.size(); k++)
	{
		if (used[k]) continue;
		const TagDetection& d = found[k];
		FalseKind kind = FalseKind::Elsewhere;
		for (const TagDetection& t : truth)
			if ((d.position() - t.position()).norm() <= 0.5 * std::max(t.size, d.size))
				kind = sameMarker(d.family, d.id, t.family, t.id) ? FalseKind::Duplicate : FalseKind::WrongId;
		ev.falseDetections.push_back(d);
		ev.falseKinds.push_back(kind);
	}
	return ev;
}

namespace
{
/** One value per tag of a truth file's list (none when it has no such list). */
template <typename T, typename PerTag>
std::vector<T> perTruthTag(const std::string& path, const std::string& listKey, PerTag perTag)
{
	const mrpt::containers::yaml doc = readYamlFile(path);
	std::vector<T> out;
	if (!doc.isMap() || !doc.has(listKey) || !doc[listKey].isSequence()) return out;
	for (const auto& node : doc[listKey].asSequence()) out.push_back(perTag(mrpt::containers::yaml(node)));
	return out;
}
}  // namespace

std::vector<bool> readRequiredFlags(const std::string& path, const std::string& listKey)
{
	return perTruthTag<bool>(path, listKey, [](const mrpt::containers::yaml& t) {
		return !(t.isMap() && t.has("expected")) || yamlScalarAs<bool>(t["expected"]);
	});
}

std::vector<double> readTruthNumbers(const std::string& path, const std::string& key, const std::string& listKey)
{
	return perTruthTag<double>(path, listKey, [&](const mrpt::containers::yaml& t) {
		return t.isMap() && t.has(key) ? yamlScalarAs<double>(t[key]) : std::nan("");
	});
}

}  // namespace tagmap
