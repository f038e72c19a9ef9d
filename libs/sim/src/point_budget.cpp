#include "tagmap/sim/point_budget.h"

#include <algorithm>
#include <cmath>

namespace tagmap::sim
{
void scaleSensorDensity(SensorSpec& s, double factor)
{
	switch (s.kind)
	{
		case SensorKind::Grid:
			s.grid.azStepDeg /= std::sqrt(factor);
			s.grid.elStepDeg /= std::sqrt(factor);
			break;
		case SensorKind::Rosette:
			s.rosette.pointsPerSecond *= factor;
			break;
		case SensorKind::Spinning:
			s.spinning.columns = std::max(1, static_cast<int>(std::lround(s.spinning.columns * factor)));
			break;
	}
}

void scaleSceneDensity(Scene& scene, double factor)
{
	for (auto& s : scene.sensors) scaleSensorDensity(s, factor);
}

}  // namespace tagmap::sim
