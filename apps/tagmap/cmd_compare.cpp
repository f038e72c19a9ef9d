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
int runCompare(int argc, char** argv)
{
	return cli::runCommand("compare", [&] {
		const cli::Args args = cli::parse(argc, argv, 1, {}, {"--help", "--in-map"});
		if (args.has("--help"))
		{
			std::cout << "Usage: tagmap compare RESULT.json TRUTH.json [--in-map]\n\n"
						 "Matches tags by family, id and position (within half a tag size) and prints,\n"
						 "per true tag, the position error per axis, the roll/pitch/yaw error, the\n"
						 "largest corner error and whether the vertex order is right; then the\n"
						 "numbers found, missed and falsely detected. Exit status 0 when every true\n"
						 "tag was found with the right vertex order and nothing else was reported.\n"
						 "\n"
						 "  --in-map   compare with the truth's `tags_in_map` list (the simulator's tags\n"
						 "             where the drifted map shows them), which separates the\n"
						 "             detector's error from the map's own drift\n";
			return 0;
		}
		if (args.positional.size() != 2) throw cli::UsageError("expected RESULT.json and TRUTH.json");
		const Evaluation ev = evaluateDetections(readTagsJson(args.positional[0]), readTagsJson(args.positional[1], args.has("--in-map") ? "tags_in_map" : "tags"));
		std::printf("%-16s %5s %6s %9s %9s %9s %8s %8s %8s %10s %6s\n", "family", "id", "found", "dx [m]", "dy [m]",
					"dz [m]", "droll", "dpitch", "dyaw", "corner [m]", "order");
		bool ok = true;
		for (const auto& e : ev.perTruth)
		{
			if (!e.found)
			{
				std::printf("%-16s %5d %6s\n", e.family.c_str(), e.id, "no");
				ok = false;
				continue;
			}
			ok = ok && e.vertexOrderCorrect;
			std::printf("%-16s %5d %6s %9.4f %9.4f %9.4f %8.3f %8.3f %8.3f %10.4f %6s\n", e.family.c_str(), e.id, "yes",
						e.positionError.x(), e.positionError.y(), e.positionError.z(), e.rotationErrorDeg.x(),
						e.rotationErrorDeg.y(), e.rotationErrorDeg.z(), e.maxCornerError,
						e.vertexOrderCorrect ? "ok" : "WRONG");
		}
		for (const auto& f : ev.falseDetections)
			std::printf("false detection: %s %d at (%.3f, %.3f, %.3f)\n", f.family.c_str(), f.id, f.position().x(),
						f.position().y(), f.position().z());
		std::printf("found %d of %zu, missed %d, false %d\n", ev.found(), ev.perTruth.size(), ev.missed(),
					ev.falsePositives());
		return ok && ev.falsePositives() == 0 ? 0 : 1;
	});
}
}  // namespace tagmap::app
