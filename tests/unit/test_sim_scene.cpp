// Scene files: every shipped scene loads and simulates; every mistake is an
// InputError naming the file, the key path and the problem.
#include <gtest/gtest.h>

#include <filesystem>

#include "tagmap/errors.h"
#include "tagmap/sim/scene_loader.h"
#include "tagmap/sim/simulate.h"

using namespace tagmap::sim;

namespace
{
const std::string kMinimal =
	"name: t\n"
	"objects:\n"
	"  - {name: wall, type: plane, position: [5, 0, 0], normal: [-1, 0, 0], size: [4, 4]}\n"
	"tags:\n"
	"  - {family: tag36h11, id: 1, size: 0.2, position: [5, 0, 0], normal: [-1, 0, 0]}\n"
	"sensors:\n"
	"  - {name: l, type: livox_mid40}\n"
	"runs:\n"
	"  - {name: r, sensor: l, duration: 0.1, waypoints: [{position: [0, 0, 0]}]}\n";

std::string replaced(const std::string& from, const std::string& to)
{
	std::string s = kMinimal;
	const auto at = s.find(from);
	EXPECT_NE(at, std::string::npos) << from;
	return s.replace(at, from.size(), to);
}

// The error message must contain every one of `parts`.
void expectError(const std::string& yaml, const std::vector<std::string>& parts)
{
	try
	{
		parseScene(yaml, "bad.yaml");
		ADD_FAILURE() << "no error for:\n" << yaml;
	}
	catch (const tagmap::InputError& e)
	{
		const std::string msg = e.what();
		EXPECT_EQ(msg.rfind("bad.yaml: ", 0), 0u) << msg;
		for (const auto& p : parts) EXPECT_NE(msg.find(p), std::string::npos) << "'" << p << "' not in: " << msg;
	}
}
}  // namespace

TEST(SimScene, MinimalSceneLoads)
{
	const Scene s = parseScene(kMinimal, "ok.yaml");
	EXPECT_EQ(s.tags.size(), 1u);
	EXPECT_EQ(s.objects.size(), 1u);
	EXPECT_EQ(simulate(s, {}).truth.size(), 1u);
}

TEST(SimScene, ErrorsNameFileKeyAndProblem)
{
	expectError(replaced("size: 0.2", "size: big"), {"tags[0].size", "not a finite number"});
	expectError(replaced("size: 0.2", "size: -0.2"), {"tags[0].size", "> 0"});
	expectError(replaced("family: tag36h11", "family: tag36h10"), {"tags[0]", "unknown tag family 'tag36h10'"});
	expectError(replaced("id: 1", "id: 5000"), {"tags[0]", "out of range"});
	expectError(replaced("sensor: l", "sensor: nope"), {"runs[0].sensor", "no sensor named 'nope'"});
	expectError(replaced("type: plane", "type: sphere"), {"objects[0].type", "unknown object type"});
	expectError(replaced("size: [4, 4]", "size: [4]"), {"objects[0].size", "expected 2 numbers"});
	expectError(replaced("size: [4, 4]", "size: [4, 4], colour: red"), {"objects[0]", "unknown key 'colour'"});
	expectError(replaced("type: livox_mid40", "type: velodyne"), {"sensors[0].type", "unknown sensor type"});
	expectError(replaced("duration: 0.1, ", ""), {"runs[0]", "duration"});
	expectError(replaced("normal: [-1, 0, 0]}\nsensors", "normal: [0, 0, 0]}\nsensors"), {"tags[0].normal", "zero"});
	expectError(replaced("size: 0.2", "size: $s"), {"tags[0].size", "unknown parameter '$s'"});
	expectError(replaced("runs:\n", "runz:\n"), {"unknown key 'runz'"});
	expectError("name: [unclosed\n", {"not valid YAML"});
	expectError("- just\n- a list\n", {"must be a YAML map"});
}

TEST(SimScene, ParametersAndOverrides)
{
	const std::string yaml = "parameters: {d: 3}\n" + replaced("position: [5, 0, 0], normal: [-1, 0, 0]}\nsensors",
															   "position: [$d, 0, 0], normal: [-1, 0, 0]}\nsensors");
	EXPECT_DOUBLE_EQ(parseScene(yaml, "p.yaml").tags[0].pose.translation().x(), 3);
	EXPECT_DOUBLE_EQ(parseScene(yaml, "p.yaml", {{"d", 4}}).tags[0].pose.translation().x(), 4);
	EXPECT_THROW(parseScene(yaml, "p.yaml", {{"e", 4}}), tagmap::InputError);
}

TEST(SimScene, MissingFileIsInputError)
{
	EXPECT_THROW(loadScene("/nonexistent/scene.yaml"), tagmap::InputError);
}

TEST(SimScene, ShippedScenesLoad)
{
	const std::filesystem::path dir = std::filesystem::path(TAGMAP_SOURCE_DIR) / "share/scenes";
	size_t n = 0;
	for (const auto& e : std::filesystem::directory_iterator(dir))
		if (e.path().extension() == ".yaml")
		{
			SCOPED_TRACE(e.path().string());
			const Scene s = loadScene(e.path().string());
			EXPECT_FALSE(s.runs.empty());
			n++;
		}
	EXPECT_GE(n, 1u);
}
