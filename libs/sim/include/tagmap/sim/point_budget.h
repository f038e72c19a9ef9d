// Sizing a map to a point budget (the large-map generator): every sensor's
// density is scaled by one factor, since a point count is proportional to
// rays fired times the fraction of rays that hit something.
#pragma once

#include "tagmap/sim/scene.h"

namespace tagmap::sim
{
/** Multiplies the rays a sensor fires per frame by about `factor`
 *  (grid: both angular steps / sqrt(factor); rosette: point rate;
 *  spinning: columns per revolution). */
void scaleSensorDensity(SensorSpec& sensor, double factor);

/** The same for every sensor of a scene. */
void scaleSceneDensity(Scene& scene, double factor);

}  // namespace tagmap::sim
