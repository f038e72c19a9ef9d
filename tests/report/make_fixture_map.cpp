// tagmap_report_fixture OUT.pcd: writes the report tests' synthetic map.
#include <iostream>

#include "fixture_map.h"
#include "tagmap/io/point_cloud_io.h"

int main(int argc, char** argv)
{
	if (argc != 2)
	{
		std::cerr << "usage: tagmap_report_fixture OUT.pcd\n";
		return 2;
	}
	tagmap::io::savePcdBinary(argv[1], tagmap::testing::makeReportFixtureMap());
	return 0;
}
