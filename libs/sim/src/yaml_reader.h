// Checked access to a parsed YAML tree: every read knows its key path
// ("tags[2].size") and source file, so every mistake in a scene becomes one
// InputError "<file>: <key path>: <what is wrong>" instead of an MRPT
// assertion or a silent default. Unknown keys are errors too (typos).
#pragma once

#include <mrpt/containers/yaml.h>

#include <Eigen/Core>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "tagmap/yaml_text.h"

namespace tagmap::sim
{
using tagmap::parseYamlText;

class YamlReader
{
   public:
	using Node = mrpt::containers::yaml::node_t;

	YamlReader(const Node& node, std::string path, const std::string& file,
			   const std::map<std::string, double>& params);

	[[noreturn]] void fail(const std::string& what) const;
	const std::string& path() const { return path_; }

	bool isMap() const { return node_->isMap(); }
	bool isSequence() const { return node_->isSequence(); }
	bool has(const std::string& key) const;
	YamlReader child(const std::string& key) const;  // must exist
	std::vector<YamlReader> items(const std::string& key) const;  // sequence (absent = empty)
	std::vector<YamlReader> elements() const;  // this node as a sequence

	/** This node as a scalar number / string. "$name" refers to a parameter. */
	double number() const;
	std::string text() const;

	double number(const std::string& key) const { return child(key).number(); }
	double number(const std::string& key, double def) const { return has(key) ? number(key) : def; }
	/** Like number() but must be > 0 (or >= 0 with allowZero). */
	double positive(const std::string& key, double def, bool allowZero = false) const;
	int integer(const std::string& key, int def) const;
	std::string text(const std::string& key) const { return child(key).text(); }
	std::string text(const std::string& key, const std::string& def) const { return has(key) ? text(key) : def; }
	std::vector<double> numbers(const std::string& key, size_t expected = 0) const;
	Eigen::Vector3d vec3(const std::string& key) const;
	Eigen::Vector3d vec3(const std::string& key, const Eigen::Vector3d& def) const
	{
		return has(key) ? vec3(key) : def;
	}

	/** Keys of this map node, in file order as MRPT keeps them. */
	std::vector<std::string> keys() const;

	/** Fails naming the first key not in `allowed`. */
	void allowKeys(const std::set<std::string>& allowed) const;

   private:
	const Node* node_;
	std::string path_;
	const std::string* file_;
	const std::map<std::string, double>* params_;
};

}  // namespace tagmap::sim
