#include "yaml_reader.h"

#include <cmath>
#include <cstdlib>

#include "tagmap/errors.h"
#include "tagmap/yaml_text.h"

namespace tagmap::sim
{
namespace
{
std::string scalarText(const YamlReader::Node& n) { return yamlScalarText(n); }
}  // namespace

YamlReader::YamlReader(const Node& node, std::string path, const std::string& file,
					   const std::map<std::string, double>& params)
	: node_(&node), path_(std::move(path)), file_(&file), params_(&params)
{
}

void YamlReader::fail(const std::string& what) const { throw InputError(*file_, path_, what); }

bool YamlReader::has(const std::string& key) const
{
	if (!node_->isMap()) return false;
	for (const auto& kv : node_->asMap())
		if (kv.first.isScalar() && scalarText(kv.first) == key) return !kv.second.isNullNode();
	return false;
}

YamlReader YamlReader::child(const std::string& key) const
{
	const std::string childPath = path_.empty() ? key : path_ + "." + key;
	if (!node_->isMap()) fail("expected a map with key '" + key + "'");
	for (const auto& kv : node_->asMap())
		if (kv.first.isScalar() && scalarText(kv.first) == key)
		{
			if (kv.second.isNullNode()) YamlReader(kv.second, childPath, *file_, *params_).fail("value is missing");
			return YamlReader(kv.second, childPath, *file_, *params_);
		}
	fail("missing required key '" + key + "'");
}

std::vector<YamlReader> YamlReader::elements() const
{
	if (!node_->isSequence()) fail("expected a list, got " + node_->typeName());
	std::vector<YamlReader> out;
	const auto& seq = node_->asSequence();
	for (size_t i = 0; i < seq.size(); i++)
		out.emplace_back(seq[i], path_ + "[" + std::to_string(i) + "]", *file_, *params_);
	return out;
}

std::vector<YamlReader> YamlReader::items(const std::string& key) const
{
	if (!has(key)) return {};
	return child(key).elements();
}

std::string YamlReader::text() const
{
	if (!node_->isScalar()) fail("expected a single value, got " + node_->typeName());
	return scalarText(*node_);
}

double YamlReader::number() const
{
	std::string s = text();
	if (!s.empty() && s[0] == '$')
	{
		auto it = params_->find(s.substr(1));
		if (it == params_->end()) fail("unknown parameter '" + s + "' (declare it under 'parameters:')");
		return it->second;
	}
	try
	{
		return parseFiniteNumber(s);
	}
	catch (const std::invalid_argument& e)
	{
		fail(e.what());
	}
}

double YamlReader::positive(const std::string& key, double def, bool allowZero) const
{
	const double v = number(key, def);
	if (v < 0 || (!allowZero && v == 0))
		child(key).fail("must be " + std::string(allowZero ? ">= 0" : "> 0") + ", got " + std::to_string(v));
	return v;
}

int YamlReader::integer(const std::string& key, int def) const
{
	if (!has(key)) return def;
	const double v = number(key);
	if (v != std::floor(v) || std::abs(v) > 2e9) child(key).fail("must be an integer");
	return static_cast<int>(v);
}

std::vector<double> YamlReader::numbers(const std::string& key, size_t expected) const
{
	const YamlReader c = child(key);
	std::vector<double> out;
	for (const auto& e : c.elements()) out.push_back(e.number());
	if (expected && out.size() != expected)
		c.fail("expected " + std::to_string(expected) + " numbers, got " + std::to_string(out.size()));
	return out;
}

Eigen::Vector3d YamlReader::vec3(const std::string& key) const
{
	const auto v = numbers(key, 3);
	return {v[0], v[1], v[2]};
}

std::vector<std::string> YamlReader::keys() const
{
	if (!node_->isMap()) fail("expected a map, got " + node_->typeName());
	std::vector<std::string> out;
	for (const auto& kv : node_->asMap()) out.push_back(kv.first.isScalar() ? scalarText(kv.first) : "?");
	return out;
}

void YamlReader::allowKeys(const std::set<std::string>& allowed) const
{
	if (!node_->isMap()) fail("expected a map, got " + node_->typeName());
	try
	{
		requireKnownKeys(*node_, allowed);
	}
	catch (const std::invalid_argument& e)
	{
		fail(e.what());
	}
}

}  // namespace tagmap::sim
