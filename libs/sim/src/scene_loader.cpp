#include "tagmap/sim/scene_loader.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include "scene_yaml_parts.h"
#include "tagmap/errors.h"
#include "tagmap/sim/distractor.h"
#include "tagmap/tag_family.h"

namespace tagmap::sim
{
namespace
{
std::set<std::string> withPose(std::set<std::string> keys)
{
	keys.insert(kPoseKeys.begin(), kPoseKeys.end());
	return keys;
}

float reflectivity(const YamlReader& r, const std::string& key, double def)
{
	const double v = r.number(key, def);
	if (v < 0 || v > 1) r.child(key).fail("reflectivity must be within 0..1");
	return static_cast<float>(v);
}

Rect plainRect(const Eigen::Isometry3d& pose, double w, double h, float refl)
{
	Rect rect;
	rect.pose = pose;
	rect.halfW = 0.5 * w;
	rect.halfH = 0.5 * h;
	rect.texture.base = refl;
	return rect;
}

SceneObject parseObject(const YamlReader& r)
{
	r.allowKeys(withPose({"name", "type", "size", "reflectivity"}));
	SceneObject o;
	o.name = r.text("name", r.path());
	const std::string type = r.text("type");
	const Eigen::Isometry3d pose = parsePose(r);
	const float refl = reflectivity(r, "reflectivity", 0.5);
	if (type == "plane")
	{
		const auto sz = r.numbers("size", 2);
		if (sz[0] <= 0 || sz[1] <= 0) r.child("size").fail("width and height must be > 0");
		o.kind = ObjectKind::Plane;
		o.faces.push_back(plainRect(pose, sz[0], sz[1], refl));
	}
	else if (type == "box")
	{
		const Eigen::Vector3d sz = r.vec3("size");
		if (sz.minCoeff() <= 0) r.child("size").fail("all three edges must be > 0");
		o.kind = ObjectKind::Box;
		// Six outward faces: for axis a, normal +-a, face spanned by the other two.
		for (int a = 0; a < 3; a++)
			for (int sgn : {-1, 1})
			{
				const int b = (a + 1) % 3, c = (a + 2) % 3;
				Eigen::Matrix3d R;
				R.col(0) = Eigen::Vector3d::Unit(b) * sgn;
				R.col(1) = Eigen::Vector3d::Unit(c);
				R.col(2) = Eigen::Vector3d::Unit(a) * sgn;
				Eigen::Isometry3d local = Eigen::Isometry3d::Identity();
				local.linear() = R;
				local.translation() = Eigen::Vector3d::Unit(a) * (0.5 * sgn * sz[a]);
				o.faces.push_back(plainRect(pose * local, sz[b], sz[c], refl));
			}
	}
	else
		r.child("type").fail("unknown object type '" + type + "' (plane, box)");
	return o;
}

SceneObject parseDistractor(const YamlReader& r)
{
	r.allowKeys(withPose({"name", "type", "size", "cell", "fill", "seed", "dark", "light", "family", "id"}));
	DistractorSpec s;
	s.name = r.text("name", r.path());
	const std::string type = r.text("type");
	// Names as written in scenes ("poster" is an older name of random_blocks).
	static const std::vector<std::pair<std::string, DistractorKind>> kinds = {
		{"checkerboard", DistractorKind::Checkerboard}, {"random_blocks", DistractorKind::RandomBlocks},
		{"poster", DistractorKind::RandomBlocks},		{"text", DistractorKind::Text},
		{"stripes", DistractorKind::Stripes},			{"mirrored_tag", DistractorKind::MirroredTag},
		{"window_grid", DistractorKind::WindowGrid},	{"zebra", DistractorKind::Zebra},
		{"qr_like", DistractorKind::QrLike},			{"bordered_square", DistractorKind::BorderedSquare}};
	const auto kind = std::find_if(kinds.begin(), kinds.end(), [&](const auto& k) { return k.first == type; });
	if (kind == kinds.end())
	{
		std::string names;
		for (const auto& k : kinds)
			if (k.first != "poster") names += (names.empty() ? "" : ", ") + k.first;
		r.child("type").fail("unknown distractor type '" + type + "' (" + names + ")");
	}
	s.kind = kind->second;
	if (s.kind == DistractorKind::MirroredTag)
	{
		s.family = r.text("family");
		s.id = static_cast<int>(r.integer("id", 0));
		try
		{
			renderTagBitmap(s.family, s.id);  // validates family and id range
		}
		catch (const std::invalid_argument& e)
		{
			r.fail(e.what());
		}
	}
	else if (r.has("family") || r.has("id"))
		r.fail("'family' and 'id' are for type mirrored_tag only");
	s.pose = parsePose(r);
	const auto sz = r.numbers("size", 2);
	if (sz[0] <= 0 || sz[1] <= 0) r.child("size").fail("width and height must be > 0");
	s.width = sz[0];
	s.height = sz[1];
	s.cell = r.positive("cell", s.cell);
	if (cellsIn(std::min(s.width, s.height), s.cell) < minCellsAcross(s.kind))
		r.child("size").fail("a " + type + " needs at least " + std::to_string(minCellsAcross(s.kind)) +
							 " cells of " + std::to_string(s.cell) + " m across its shorter side");
	s.fill = r.number("fill", s.fill);
	if (s.fill < 0 || s.fill > 1) r.child("fill").fail("must be within 0..1");
	s.seed = static_cast<uint64_t>(r.integer("seed", 1));
	s.dark = reflectivity(r, "dark", s.dark);
	s.light = reflectivity(r, "light", s.light);
	return makeDistractor(s);
}

TagSpec parseTag(const YamlReader& r)
{
	r.allowKeys(withPose({"family", "id", "size", "margin", "jitter_deg", "paper_offset", "black", "white", "board"}));
	TagSpec t;
	t.family = r.text("family");
	t.id = r.integer("id", 0);
	if (!r.has("id")) r.fail("missing required key 'id'");
	try
	{
		renderTagBitmap(t.family, t.id);  // validates family and id range
	}
	catch (const std::invalid_argument& e)
	{
		r.fail(e.what());
	}
	t.size = r.positive("size", 0);
	t.pose = parsePose(r);
	t.margin = r.positive("margin", t.margin, true);
	t.jitterDeg = r.positive("jitter_deg", 0, true);
	t.paperOffset = r.positive("paper_offset", t.paperOffset, true);
	if (r.has("board"))
	{
		const YamlReader b = r.child("board");
		b.allowKeys({"size", "standoff", "reflectivity"});
		const auto sz = b.numbers("size", 2);
		t.boardWidth = sz[0];
		t.boardHeight = sz[1];
		if (std::min(sz[0], sz[1]) < t.size) b.child("size").fail("board is smaller than the tag");
		t.boardStandoff = b.positive("standoff", t.boardStandoff);
		t.boardReflectivity = reflectivity(b, "reflectivity", t.boardReflectivity);
	}
	t.black = reflectivity(r, "black", t.black);
	t.white = reflectivity(r, "white", t.white);
	return t;
}

ScanRun parseRun(const YamlReader& r, const std::vector<SensorSpec>& sensors)
{
	r.allowKeys({"name", "sensor", "waypoints", "duration", "drift_scale", "deskew_residual", "mount",
				 "odometry_scale_error", "odometry_heading_bias_deg_per_m"});
	ScanRun run;
	run.name = r.text("name", r.path());
	const std::string sensor = r.text("sensor");
	run.sensor = -1;
	for (size_t i = 0; i < sensors.size(); i++)
		if (sensors[i].name == sensor) run.sensor = static_cast<int>(i);
	if (run.sensor < 0) r.child("sensor").fail("no sensor named '" + sensor + "' in 'sensors:'");
	const auto wps = r.items("waypoints");
	if (wps.empty()) r.fail("needs at least one entry in 'waypoints'");
	for (size_t i = 0; i < wps.size(); i++)
	{
		wps[i].allowKeys(withPose({"t"}));
		Waypoint w;
		w.t = wps[i].number("t", static_cast<double>(i));
		w.pose = parsePose(wps[i]);
		if (i > 0 && !(w.t > run.waypoints.back().t)) wps[i].child("t").fail("waypoint times must increase");
		run.waypoints.push_back(w);
	}
	run.duration = r.positive("duration", 0, true);
	if (sensors[run.sensor].kind != SensorKind::Grid && run.waypoints.size() == 1 && run.duration <= 0)
		r.fail("a single waypoint needs 'duration' > 0 (seconds of integration)");
	run.driftScale = r.positive("drift_scale", 1, true);
	run.deskewResidual = r.number("deskew_residual", 0);
	if (run.deskewResidual < 0 || run.deskewResidual > 1) r.child("deskew_residual").fail("must be within 0..1");
	run.odometryScaleError = r.number("odometry_scale_error", 0);
	if (std::abs(run.odometryScaleError) >= 0.5) r.child("odometry_scale_error").fail("must be within -0.5..0.5");
	run.odometryHeadingBiasDegPerM = r.number("odometry_heading_bias_deg_per_m", 0);
	if (std::abs(run.odometryHeadingBiasDegPerM) > 90)
		r.child("odometry_heading_bias_deg_per_m").fail("must be within -90..90");
	if (r.has("mount"))
	{
		const YamlReader m = r.child("mount");
		m.allowKeys({"position", "rpy_deg", "quaternion"});
		run.mount = parsePose(m);
	}
	return run;
}

DriftParams parseDrift(const YamlReader& r)
{
	r.allowKeys({"translation_per_sqrt_m", "rotation_deg_per_sqrt_m", "translation_per_sqrt_s",
				 "rotation_deg_per_sqrt_s"});
	DriftParams d;
	d.translationPerSqrtM = r.positive("translation_per_sqrt_m", d.translationPerSqrtM, true);
	d.rotationDegPerSqrtM = r.positive("rotation_deg_per_sqrt_m", d.rotationDegPerSqrtM, true);
	d.translationPerSqrtS = r.positive("translation_per_sqrt_s", d.translationPerSqrtS, true);
	d.rotationDegPerSqrtS = r.positive("rotation_deg_per_sqrt_s", d.rotationDegPerSqrtS, true);
	return d;
}

Scene parseTree(const mrpt::containers::yaml& doc, const std::string& file, const SceneParameters& overrides)
{
	const auto& rootNode = doc.node();
	std::map<std::string, double> params;
	const std::map<std::string, double> none;
	YamlReader root(rootNode, "", file, none);
	if (!rootNode.isMap()) root.fail("a scene must be a YAML map (name, objects, tags, sensors, runs, ...)");
	root.allowKeys({"name", "parameters", "drift", "objects", "distractors", "tags", "sensors", "runs"});
	if (root.has("parameters"))
	{
		const YamlReader p = root.child("parameters");
		for (const std::string& name : p.keys()) params[name] = p.number(name);
	}
	for (const auto& [name, value] : overrides)
	{
		if (!params.count(name)) root.fail("unknown parameter '" + name + "' (the scene declares none by that name)");
		params[name] = value;
	}

	const YamlReader r(rootNode, "", file, params);
	Scene s;
	s.file = file;
	s.name = r.text("name", "scene");
	if (r.has("drift")) s.drift = parseDrift(r.child("drift"));
	for (const auto& o : r.items("objects")) s.objects.push_back(parseObject(o));
	for (const auto& d : r.items("distractors")) s.objects.push_back(parseDistractor(d));
	for (const auto& t : r.items("tags")) s.tags.push_back(parseTag(t));
	for (const auto& se : r.items("sensors"))
	{
		s.sensors.push_back(parseSensor(se));
		for (size_t i = 0; i + 1 < s.sensors.size(); i++)
			if (s.sensors[i].name == s.sensors.back().name) se.child("name").fail("duplicate sensor name");
	}
	for (const auto& ru : r.items("runs")) s.runs.push_back(parseRun(ru, s.sensors));
	if (s.runs.empty()) r.fail("needs at least one entry in 'runs' (what scans the scene)");
	return s;
}

}  // namespace

Scene parseScene(const std::string& yamlText, const std::string& sourceName, const SceneParameters& overrides)
{
	return parseTree(parseYamlText(yamlText, sourceName), sourceName, overrides);
}

Scene loadScene(const std::string& path, const SceneParameters& overrides)
{
	std::ifstream in(path, std::ios::binary);
	if (!in) throw InputError(path, "", "cannot open scene file");
	std::stringstream ss;
	ss << in.rdbuf();
	return parseScene(ss.str(), path, overrides);
}

}  // namespace tagmap::sim
