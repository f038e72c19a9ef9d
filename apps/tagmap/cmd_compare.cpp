// tagmap compare: score a result file against a ground-truth file (e.g. the
// simulator's, or surveyed tag positions) in the same `tags` schema.
#include <cmath>
#include <cstdio>
#include <iostream>

#include "cli.h"
#include "commands.h"
#include "tagmap/evaluation.h"
#include "tagmap/tags_json.h"

namespace tagmap::app
{
namespace
{
void printConditions(const Evaluation& ev, const std::string& truthPath, const std::string& list)
{
	const char* keys[] = {"points_per_cell", "range_min", "incidence_deg_min"};
	std::vector<std::vector<double>> columns;
	for (const char* key : keys) columns.push_back(readTruthNumbers(truthPath, key, list));
	std::printf("conditions: %-16s %5s %6s %16s %10s %18s\n", "family", "id", "found", keys[0], keys[1], keys[2]);
	for (size_t k = 0; k < ev.perTruth.size(); k++)
	{
		// A tag the truth does not require shows its result in brackets.
		const auto& e = ev.perTruth[k];
		std::printf("conditions: %-16s %5d %6s", e.family.c_str(), e.id,
					e.required ? (e.found ? "yes" : "no") : (e.found ? "(yes)" : "(no)"));
		const int widths[] = {16, 10, 18};
		for (size_t c = 0; c < columns.size(); c++)
		{
			const double v = k < columns[c].size() ? columns[c][k] : std::nan("");
			if (std::isnan(v))
				std::printf(" %*s", widths[c], "-");
			else
				std::printf(" %*.2f", widths[c], v);
		}
		std::printf("\n");
	}
}
}  // namespace

int runCompare(int argc, char** argv)
{
	return cli::runCommand("compare", [&] {
		const cli::Args args = cli::parse(argc, argv, 1, {}, {"--help", "--in-map", "--conditions"});
		if (args.has("--help"))
		{
			std::cout << "Usage: tagmap compare RESULT.json TRUTH.json [--in-map] [--conditions]\n\n"
						 "Matches tags by family, id and position (within half a tag size) and prints,\n"
						 "per true tag, the position error per axis, the roll/pitch/yaw error, the\n"
						 "largest corner error and whether the vertex order is right; then the\n"
						 "numbers found, missed and falsely detected (a false report on a true tag's\n"
						 "square is a wrong family/id, a second report of a found tag a duplicate).\n"
						 "A true tag marked \"expected\": false need not be found. Exit status 0 when\n"
						 "every required true tag was found with the right vertex order and nothing\n"
						 "else was reported.\n"
						 "\n"
						 "  --in-map   compare with the truth's `tags_in_map` list (the simulator's tags\n"
						 "             where the drifted map shows them), which separates the\n"
						 "             detector's error from the map's own drift\n"
						 "  --conditions  then print, per true tag, the conditions the truth file\n"
						 "             records (points_per_cell, range_min, incidence_deg_min; '-'\n"
						 "             where absent): which tags are missed, and why; a tag the\n"
						 "             truth does not require shows (yes) or (no)\n";
			return 0;
		}
		if (args.positional.size() != 2) throw cli::UsageError("expected RESULT.json and TRUTH.json");
		const std::string list = args.has("--in-map") ? "tags_in_map" : "tags";
		const Evaluation ev = evaluateDetections(readTagsJson(args.positional[0]), readTagsJson(args.positional[1], list),
												 readRequiredFlags(args.positional[1], list));
		std::printf("%-16s %5s %6s %9s %9s %9s %8s %8s %8s %10s %6s\n", "family", "id", "found", "dx [m]", "dy [m]",
					"dz [m]", "droll", "dpitch", "dyaw", "corner [m]", "order");
		bool ok = true;
		for (const auto& e : ev.perTruth)
		{
			if (!e.found)
			{
				std::printf("%-16s %5d %6s\n", e.family.c_str(), e.id, e.required ? "no" : "no (not required)");
				ok = ok && !e.required;
				continue;
			}
			ok = ok && e.vertexOrderCorrect;
			std::printf("%-16s %5d %6s %9.4f %9.4f %9.4f %8.3f %8.3f %8.3f %10.4f %6s\n", e.family.c_str(), e.id, "yes",
						e.positionError.x(), e.positionError.y(), e.positionError.z(), e.rotationErrorDeg.x(),
						e.rotationErrorDeg.y(), e.rotationErrorDeg.z(), e.maxCornerError,
						e.vertexOrderCorrect ? "ok" : "WRONG");
		}
		for (size_t k = 0; k < ev.falseDetections.size(); k++)
		{
			const TagDetection& f = ev.falseDetections[k];
			std::printf("false detection (%s): %s %d at (%.3f, %.3f, %.3f), %.3f m\n", falseKindName(ev.falseKinds[k]),
						f.family.c_str(), f.id, f.position().x(), f.position().y(), f.position().z(), f.size);
		}
		if (args.has("--conditions")) printConditions(ev, args.positional[1], list);
		std::printf("found %d of %zu, missed %d, false %d (wrong family/id %d, duplicate %d)\n", ev.found(),
					ev.perTruth.size(), ev.missed(), ev.falsePositives(), ev.falseOf(FalseKind::WrongId),
					ev.falseOf(FalseKind::Duplicate));
		return ok && ev.falsePositives() == 0 ? 0 : 1;
	});
}
}  // namespace tagmap::app
