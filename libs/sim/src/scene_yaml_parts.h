// The pieces of the scene loader, one per YAML section kind.
#pragma once

#include <Eigen/Geometry>

#include "tagmap/sim/sensor_spec.h"
#include "yaml_reader.h"

namespace tagmap::sim
{
/** Keys a pose may use, for allowKeys(). */
extern const std::set<std::string> kPoseKeys;

/** `position` plus one orientation form: `rpy_deg: [r, p, y]` (R = Rz Ry Rx),
 *  `quaternion: [w, x, y, z]`, `normal: [..]` (+ optional `up`, `roll_deg`;
 *  the frame's z is the normal, y the up direction), or `look_at: [x, y, z]`
 *  (x towards the point, z up; for sensors). Default: identity rotation. */
Eigen::Isometry3d parsePose(const YamlReader& r);

SensorSpec parseSensor(const YamlReader& r);

}  // namespace tagmap::sim
