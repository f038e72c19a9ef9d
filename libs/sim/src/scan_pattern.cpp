#include "tagmap/sim/scan_pattern.h"

namespace tagmap::sim
{
std::unique_ptr<ScanPattern> makeScanPattern(const SensorSpec& spec)
{
	switch (spec.kind)
	{
		case SensorKind::Rosette:
			return std::make_unique<RosettePattern>(spec.rosette);
		case SensorKind::Spinning:
			return std::make_unique<SpinningPattern>(spec.spinning);
		case SensorKind::Grid:
			break;
	}
	return std::make_unique<GridPattern>(spec.grid);
}

}  // namespace tagmap::sim
