// share/config/default.yaml is the parameters' documentation: these tests
// keep it equal to the built-in defaults and complete, so it cannot drift.
#include <gtest/gtest.h>

#include <fstream>
#include <regex>
#include <sstream>

#include "tagmap/errors.h"
#include "tagmap/pipeline_params.h"

using tagmap::PipelineParams;

namespace
{
const std::string kDefaultYaml = TAGMAP_SOURCE_DIR "/share/config/default.yaml";

std::string yamlText(const PipelineParams& p)
{
	std::ostringstream s;
	p.toYaml().printAsYAML(s);
	return s.str();
}

// The message of the std::invalid_argument that loading `text` throws.
std::string loadError(const std::string& text)
{
	try
	{
		PipelineParams::fromYaml(mrpt::containers::yaml::FromText(text));
	}
	catch (const std::invalid_argument& e)
	{
		return e.what();
	}
	return "(no error)";
}
}  // namespace

TEST(Config, DefaultYamlEqualsBuiltInDefaults)
{
	EXPECT_EQ(yamlText(PipelineParams::fromYamlFile(kDefaultYaml)), yamlText(PipelineParams{}));
}

// `tagmap config --dump > my.yaml` must load back as it is (every family:
// MRPT printed an empty list as nothing, which its parser rejected).
TEST(Config, DumpLoadsBackAsItIs)
{
	PipelineParams some;
	some.families = {"tag36h11", "aruco_4x4_50"};
	for (const PipelineParams& p : {PipelineParams{}, some})
	{
		const std::string text = yamlText(p);
		PipelineParams back;
		ASSERT_NO_THROW(back = PipelineParams::fromYaml(mrpt::containers::yaml::FromText(text))) << text;
		EXPECT_EQ(yamlText(back), text);
		EXPECT_EQ(back.families, p.families);
	}
}

TEST(Config, DefaultYamlHasEveryParameterWithAComment)
{
	const auto file = mrpt::containers::yaml::FromFile(kDefaultYaml);
	const auto defaults = PipelineParams{}.toYaml();
	for (const auto& [k, v] : defaults.asMap())
	{
		const std::string key = k.as<std::string>();
		ASSERT_TRUE(file.has(key)) << key << " missing from default.yaml";
		if (!v.isMap()) continue;
		for (const auto& [k2, v2] : v.asMap())
			EXPECT_TRUE(file[key].has(k2.as<std::string>())) << key << "." << k2.as<std::string>() << " missing";
	}
	// Every "key: value" line follows a comment line that explains it.
	std::ifstream in(kDefaultYaml);
	std::string line, previous;
	const std::regex keyValue(R"(^\s*[a-z_]+:\s*\S.*$)"), comment(R"(^\s*#.*$)");
	while (std::getline(in, line))
	{
		if (std::regex_match(line, keyValue))
		{
			EXPECT_TRUE(std::regex_match(previous, comment)) << "no comment above: " << line;
		}
		previous = line;
	}
}

TEST(Config, UnknownKeyIsNamed)
{
	// The scene files' wording (one helper, yaml_text.h): the key as written
	// and what would have been accepted there.
	const std::string inSection = loadError("gradient:\n  treshold: 0.2\n");
	EXPECT_EQ(inSection.rfind("unknown key 'gradient.treshold' (allowed: ", 0), 0u) << inSection;
	EXPECT_NE(inSection.find("threshold"), std::string::npos) << inSection;
	const std::string topLevel = loadError("tag_sise: 0.2\n");
	EXPECT_EQ(topLevel.rfind("unknown key 'tag_sise' (allowed: ", 0), 0u) << topLevel;
	EXPECT_NE(topLevel.find("tag_size"), std::string::npos) << topLevel;
	EXPECT_NE(topLevel.find("families"), std::string::npos) << topLevel;
}

TEST(Config, BadValueIsNamed)
{
	EXPECT_EQ(loadError("clustering:\n  min_points: many\n"),
			  "parameter 'clustering.min_points' has an invalid value: 'many' is not an integer");
	// MRPT's as<double>() runs into undefined behaviour on this (fuzz_config).
	EXPECT_EQ(loadError("tag_size: 1e999\n"), "parameter 'tag_size' has an invalid value: '1e999' is not a finite number");
	EXPECT_EQ(loadError("clustering:\n  min_points: 1.5\n"),
			  "parameter 'clustering.min_points' has an invalid value: '1.5' is not an integer");
	EXPECT_NE(loadError("candidates:\n  max_aspect: 0.5\n").find("candidates.max_aspect"), std::string::npos);
	EXPECT_NE(loadError("families: [tag99h99]\n").find("tag99h99"), std::string::npos);
}

TEST(Config, DeeplyNestedTextIsRefusedBeforeTheParser)
{
	// libfyaml crashed in its error report on the fuzzer's input
	// (tests/fuzz/regressions/config/libfyaml-crashes-on-deep-nesting.yaml).
	const std::string path = ::testing::TempDir() + "/tagmap_nested_config.yaml";
	std::ofstream(path) << std::string(1600, '{') << "'x\n";
	try
	{
		PipelineParams::fromYamlFile(path);
		FAIL() << "no error";
	}
	catch (const tagmap::InputError& e)
	{
		EXPECT_NE(std::string(e.what()).find("nested deeper than 64 levels"), std::string::npos) << e.what();
	}
	// Real files nest a few levels: unchanged.
	std::ofstream(path) << "candidates: {min_tag_size: 0.2, max_tag_size: 0.8}\nfamilies: [tag36h11]\n";
	EXPECT_EQ(PipelineParams::fromYamlFile(path).candidates.maxTagSize, 0.8);
}

TEST(Config, FileErrorsNameTheFile)
{
	const std::string path = ::testing::TempDir() + "/tagmap_bad_config.yaml";
	std::ofstream(path) << "decoder:\n  max_bits_corrected: 7\n";
	try
	{
		PipelineParams::fromYamlFile(path);
		FAIL() << "no error";
	}
	catch (const tagmap::InputError& e)
	{
		const std::string msg = e.what();
		EXPECT_EQ(msg.rfind(path, 0), 0u) << msg;
		EXPECT_NE(msg.find("decoder.max_bits_corrected"), std::string::npos) << msg;
	}
}
