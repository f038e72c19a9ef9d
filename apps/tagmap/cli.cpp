#include "cli.h"

#include <cmath>
#include <cstdlib>
#include <iostream>

namespace tagmap::cli
{
std::string Args::get(const std::string& opt, const std::string& def) const
{
	auto it = options.find(opt);
	return it == options.end() ? def : it->second;
}

std::vector<std::string> Args::getAll(const std::string& opt) const
{
	auto it = every.find(opt);
	return it == every.end() ? std::vector<std::string>{} : it->second;
}

double Args::getDouble(const std::string& opt, double def) const
{
	auto it = options.find(opt);
	if (it == options.end()) return def;
	char* end = nullptr;
	const double v = std::strtod(it->second.c_str(), &end);
	if (it->second.empty() || *end != '\0' || !std::isfinite(v))
		throw UsageError(opt + ": '" + it->second + "' is not a number");
	return v;
}

Eigen::Vector3d Args::getVector3(const std::string& opt, const Eigen::Vector3d& def) const
{
	auto it = options.find(opt);
	if (it == options.end()) return def;
	Eigen::Vector3d v;
	const char* s = it->second.c_str();
	for (int a = 0; a < 3; a++)
	{
		char* end = nullptr;
		v[a] = std::strtod(s, &end);
		if (end == s || !std::isfinite(v[a]) || *end != (a < 2 ? ',' : '\0'))
			throw UsageError(opt + ": expected x,y,z (three numbers), got '" + it->second + "'");
		s = end + 1;
	}
	return v;
}

long Args::getInt(const std::string& opt, long def) const
{
	auto it = options.find(opt);
	if (it == options.end()) return def;
	char* end = nullptr;
	const long v = std::strtol(it->second.c_str(), &end, 10);
	if (it->second.empty() || *end != '\0') throw UsageError(opt + ": '" + it->second + "' is not an integer");
	return v;
}

Args parse(int argc, char** argv, int first, const std::set<std::string>& valueOptions,
		   const std::set<std::string>& switchOptions)
{
	Args a;
	for (int i = first; i < argc; i++)
	{
		std::string s = argv[i];
		if (s.size() > 2 && s.rfind("--", 0) == 0)
		{
			std::string value;
			const auto eq = s.find('=');
			const bool inlineValue = eq != std::string::npos;
			if (inlineValue)
			{
				value = s.substr(eq + 1);
				s = s.substr(0, eq);
			}
			if (valueOptions.count(s))
			{
				if (!inlineValue)
				{
					if (i + 1 >= argc) throw UsageError(s + " needs a value");
					value = argv[++i];
				}
				a.options[s] = value;
				a.every[s].push_back(value);
			}
			else if (switchOptions.count(s) && !inlineValue)
				a.switches.insert(s);
			else
				throw UsageError("unknown option " + s);
		}
		else
			a.positional.push_back(s);
	}
	return a;
}

int runCommand(const char* name, const std::function<int()>& body)
{
	try
	{
		return body();
	}
	catch (const UsageError& e)
	{
		std::cerr << "tagmap " << name << ": " << e.what() << " (see tagmap " << name << " --help)\n";
		return 2;
	}
	catch (const std::exception& e)
	{
		std::cerr << "tagmap " << name << ": " << e.what() << "\n";
		return 1;
	}
}

}  // namespace tagmap::cli
