#include "tagmap/tags_json.h"

#include <mrpt/containers/yaml.h>

#include <cstdio>
#include <sstream>

#include "tagmap/atomic_file.h"
#include "tagmap/errors.h"
#include "tagmap/yaml_text.h"

namespace tagmap
{
namespace
{
std::string num(double v, int decimals)
{
	if (v == 0) v = 0;  // no "-0.000000"
	char buf[64];
	std::snprintf(buf, sizeof(buf), "%.*f", decimals, v);
	std::string s(buf);
	if (s == "-0." + std::string(decimals, '0')) s = s.substr(1);
	return s;
}

std::string vec(const Eigen::Vector3d& v) { return "[" + num(v.x(), 6) + ", " + num(v.y(), 6) + ", " + num(v.z(), 6) + "]"; }
}  // namespace

std::string jsonQuote(const std::string& s)
{
	std::string out = "\"";
	for (char c : s)
	{
		switch (c)
		{
			case '"': out += "\\\""; break;
			case '\\': out += "\\\\"; break;
			case '\n': out += "\\n"; break;
			case '\t': out += "\\t"; break;
			default:
				if (static_cast<unsigned char>(c) < 0x20)
				{
					char buf[8];
					std::snprintf(buf, sizeof(buf), "\\u%04x", c);
					out += buf;
				}
				else
					out += c;
		}
	}
	return out + "\"";
}

std::string tagsToJson(const std::vector<TagDetection>& tags, const std::string& extraFields,
					   const std::vector<std::string>& tagFields)
{
	std::ostringstream o;
	o << "{\n  \"tags\": [";
	for (size_t i = 0; i < tags.size(); i++)
	{
		const auto& t = tags[i];
		Eigen::Quaterniond q = t.quaternion().normalized();
		if (q.w() < 0) q.coeffs() *= -1;  // one canonical sign, for diffable files
		o << (i ? "," : "") << "\n    {\n";
		o << "      \"family\": " << jsonQuote(t.family) << ",\n";
		o << "      \"id\": " << t.id << ",\n";
		o << "      \"size\": " << num(t.size, 6) << ",\n";
		o << "      \"corners\": [" << vec(t.corners[0]) << ", " << vec(t.corners[1]) << ", " << vec(t.corners[2]) << ", "
		  << vec(t.corners[3]) << "],\n";
		o << "      \"position\": " << vec(t.position()) << ",\n";
		o << "      \"quaternion\": [" << num(q.w(), 9) << ", " << num(q.x(), 9) << ", " << num(q.y(), 9) << ", "
		  << num(q.z(), 9) << "]";
		if (t.pointsUsed > 0)
		{
			o << ",\n      \"points_used\": " << t.pointsUsed;
			o << ",\n      \"decode_margin\": " << num(t.decodeMargin, 3);
			o << ",\n      \"pattern_fit\": " << num(t.patternFit, 4);
			o << ",\n      \"covariance\": [";
			for (int r = 0; r < 6; r++)
				for (int c = 0; c < 6; c++) o << (r || c ? ", " : "") << num(t.covariance(r, c), 12);
			o << "]";
		}
		if (i < tagFields.size() && !tagFields[i].empty()) o << ",\n      " << tagFields[i];
		o << "\n    }";
	}
	o << (tags.empty() ? "]" : "\n  ]");
	if (!extraFields.empty()) o << ",\n  " << extraFields;
	o << "\n}\n";
	return o.str();
}

void writeTagsJson(const std::string& path, const std::vector<TagDetection>& tags, const std::string& extraFields,
				   const std::vector<std::string>& tagFields)
{
	const std::string text = tagsToJson(tags, extraFields, tagFields);
	writeFileAtomically(path, [&](std::ostream& out) { out << text; });
}

std::vector<TagDetection> readTagsJson(const std::string& path, const std::string& listKey)
{
	// readYamlFile, not yaml::FromFile: MRPT lets libfyaml print its parse
	// errors on stderr (several lines for a binary file given as the map).
	const mrpt::containers::yaml doc = readYamlFile(path);
	if (!doc.isMap() || !doc.has(listKey) || !doc[listKey].isSequence())
		throw InputError(path, "", "no \"" + listKey + "\" list");
	std::vector<TagDetection> out;
	const auto& seq = doc[listKey].asSequence();
	for (size_t i = 0; i < seq.size(); i++)
	{
		const std::string where = listKey + "[" + std::to_string(i) + "]";
		try
		{
			mrpt::containers::yaml t = seq[i];
			TagDetection d;
			d.family = yamlScalarAs<std::string>(t["family"]);
			d.id = yamlScalarAs<int>(t["id"]);
			for (int k = 0; k < 4; k++)
				for (int j = 0; j < 3; j++) d.corners[k][j] = yamlScalarAs<double>(t["corners"](k)(j));
			// Corners are the one required geometry (surveyed truth often has
			// only them); size and pose follow from them when absent.
			d.pose = poseFromCorners(d.corners);
			d.size = 0;
			for (int k = 0; k < 4; k++) d.size += 0.25 * (d.corners[(k + 1) % 4] - d.corners[k]).norm();
			if (t.has("size")) d.size = yamlScalarAs<double>(t["size"]);
			if (t.has("position") && t.has("quaternion"))
			{
				Eigen::Vector3d p;
				for (int j = 0; j < 3; j++) p[j] = yamlScalarAs<double>(t["position"](j));
				Eigen::Quaterniond q(yamlScalarAs<double>(t["quaternion"](0)), yamlScalarAs<double>(t["quaternion"](1)),
									 yamlScalarAs<double>(t["quaternion"](2)), yamlScalarAs<double>(t["quaternion"](3)));
				d.pose.linear() = q.normalized().toRotationMatrix();
				d.pose.translation() = p;
			}
			out.push_back(d);
		}
		catch (const std::exception& e)
		{
			throw InputError(path, where, "malformed tag: " + errorSummary(e.what()));
		}
	}
	return out;
}

}  // namespace tagmap
