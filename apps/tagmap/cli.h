// A tiny argument parser shared by the sub-commands: positional arguments,
// "--flag value" options and boolean switches, with one-line errors.
#pragma once

#include <Eigen/Core>
#include <functional>
#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace tagmap::cli
{
class UsageError : public std::runtime_error
{
   public:
	using std::runtime_error::runtime_error;
};

struct Args
{
	std::vector<std::string> positional;
	std::map<std::string, std::string> options;  // "--json" -> "out.json" (the last one given)
	std::map<std::string, std::vector<std::string>> every;  // each value given, in order (--param A=1 --param B=2)
	std::set<std::string> switches;  // "--quiet"

	bool has(const std::string& opt) const { return options.count(opt) || switches.count(opt); }
	std::string get(const std::string& opt, const std::string& def = {}) const;
	/** Every value of a repeatable option, in the order given. */
	std::vector<std::string> getAll(const std::string& opt) const;
	/** Parses a number; throws UsageError "--opt: 'x' is not a number". */
	double getDouble(const std::string& opt, double def) const;
	long getInt(const std::string& opt, long def) const;
	/** "x,y,z": three finite numbers; throws UsageError otherwise. */
	Eigen::Vector3d getVector3(const std::string& opt, const Eigen::Vector3d& def) const;
};

/** `valueOptions` take a value; `switchOptions` do not. Unknown options
 *  and missing values throw UsageError. */
Args parse(int argc, char** argv, int first, const std::set<std::string>& valueOptions,
		   const std::set<std::string>& switchOptions);

/** Runs a sub-command's `body` and turns its errors into the exit status:
 *  UsageError -> "tagmap NAME: what (see tagmap NAME --help)", 2; any other
 *  exception -> "tagmap NAME: what", 1. Every command reports errors alike. */
int runCommand(const char* name, const std::function<int()>& body);

}  // namespace tagmap::cli
