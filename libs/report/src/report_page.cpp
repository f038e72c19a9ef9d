#include "tagmap/report/report_page.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

#include "tagmap/report/html_table.h"

namespace tagmap::report
{
namespace
{
const char* kStyle = R"(<style>
body { font-family: system-ui, sans-serif; margin: 1.5em auto; max-width: 1200px; padding: 0 1em; color: #222; }
h1 { font-size: 1.5em; } h2 { font-size: 1.2em; margin-top: 2em; border-bottom: 1px solid #ccc; }
table { border-collapse: collapse; margin: .5em 0; font-size: .9em; }
th, td { border: 1px solid #ccc; padding: .2em .6em; text-align: left; }
th { background: #f2f2f2; } td.num { text-align: right; font-variant-numeric: tabular-nums; }
.map { max-width: 100%; border: 1px solid #999; }
.gallery { display: flex; flex-wrap: wrap; gap: 12px; }
figure { margin: 0; width: 250px; font-size: .8em; } figure img { width: 240px; image-rendering: pixelated; border: 1px solid #999; }
.decoded { color: #187818; } .rejected { color: #b35900; }
#image-check { font-weight: bold; } #image-check.failed { color: #c00; }
pre { background: #f6f6f6; padding: .6em; overflow-x: auto; }
</style>
)";

// Marks each image and summarises, after every image has loaded or failed.
const char* kImageCheck = R"(<script>
window.addEventListener('load', function () {
  var imgs = document.images, ok = 0;
  for (var i = 0; i < imgs.length; i++) {
    var good = imgs[i].complete && imgs[i].naturalWidth > 0;
    imgs[i].setAttribute('data-loaded', good ? 'yes' : 'no');
    if (good) ok++;
  }
  var el = document.getElementById('image-check');
  el.textContent = ok === imgs.length ? 'all ' + ok + ' images loaded'
                                      : (imgs.length - ok) + ' of ' + imgs.length + ' images failed to load';
  if (ok !== imgs.length) el.className = 'failed';
});
</script>
)";

std::string vec3(const Eigen::Vector3d& v, const char* fmt = "%.3f")
{
	return format(fmt, v.x()) + " " + format(fmt, v.y()) + " " + format(fmt, v.z());
}

std::string summarySection(const ReportInput& in)
{
	std::string h = "<p>Input <code>" + htmlEscape(in.inputPath) + "</code>: " +
					htmlEscape(format("%zu points", in.map.size())) +
					(in.inputSummary.empty() ? "" : " (" + htmlEscape(in.inputSummary) + ")") + ". Found <b>" +
					htmlEscape(format("%zu tag(s)", in.found.tags.size())) + "</b> in " +
					htmlEscape(format("%.2f s", in.found.totalSeconds)) + ".</p>\n";
	if (!in.commandLine.empty()) h += "<p>Command: <code>" + htmlEscape(in.commandLine) + "</code></p>\n";
	return h + "<p id=\"image-check\">checking images&hellip;</p>\n";
}

std::string detectionsSection(const Detections& found)
{
	HtmlTable t({"family", "id", "size [m]", "position x y z [m]", "roll pitch yaw [deg]", "points", "pattern fit",
				 "decode margin", "mirrored"});
	for (const auto& d : found.tags)
		t.addRow({d.family, std::to_string(d.id), format("%.3f", d.size), vec3(d.position()),
				  vec3(rollPitchYaw(d.pose.linear()) * 180.0 / M_PI, "%.1f"), std::to_string(d.pointsUsed),
				  format("%.2f", d.patternFit), format("%.1f", d.decodeMargin), d.mirrored ? "yes" : "no"});
	return "<h2>Detections</h2>\n" + (found.tags.empty() ? std::string("<p>No tags found.</p>\n") : t.html());
}

std::string stagesSection(const Detections& found)
{
	HtmlTable t({"stage", "seconds", "in", "out"});
	for (const auto& s : found.stages)
		t.addRow({s.name, format("%.3f", s.seconds), std::to_string(s.itemsIn), std::to_string(s.itemsOut)});
	t.addRow({"total", format("%.3f", found.totalSeconds), "", ""});
	return "<h2>Stages</h2>\n<p>Counts are points, voxels, clusters or tags, as fits each stage.</p>\n" + t.html();
}

std::string verdictsTable(const Detections& found)
{
	std::map<std::string, std::pair<size_t, const char*>> rows;  // by name: count, meaning
	for (const auto& c : found.candidates)
	{
		auto& row = rows[verdictName(c.verdict)];
		row.first++;
		row.second = verdictMeaning(c.verdict);
	}
	HtmlTable t({"verdict", "clusters", "meaning"});
	for (const auto& [name, row] : rows) t.addRow({name, std::to_string(row.first), row.second});
	return t.html();
}

std::string candidateCaption(size_t index, const CandidateReport& c)
{
	std::string what = verdictName(c.verdict);
	for (const auto& l : c.decodedLabels) what += " " + l;
	// A rejected candidate's reads, each with its own reason.
	if (c.verdict != Verdict::Decoded)
		for (size_t k = 0; k < c.decoded.size() && k < c.readVerdicts.size(); k++)
			what += (k == 0 ? " (read " : ", ") + tagLabel(c.decoded[k].family, c.decoded[k].id) + " " +
					verdictName(c.readVerdicts[k]) + (k + 1 == c.decoded.size() ? ")" : "");
	const char* cls = c.verdict == Verdict::Decoded ? "decoded" : "rejected";
	return "<b class=\"" + std::string(cls) + "\">" + htmlEscape(format("#%zu ", index) + what) + "</b><br>" +
		   htmlEscape(format("%zu cluster / %zu gathered points; box %.2f x %.2f x %.2f m at (%.2f, %.2f, %.2f)",
							 c.clusterPoints, c.gatheredPoints, c.extent.x(), c.extent.y(), c.extent.z(), c.center.x(),
							 c.center.y(), c.center.z()));
}

std::string candidatesSection(const Detections& found, const PageImages& images)
{
	std::string h = "<h2>Candidates</h2>\n<p>Every cluster of high-gradient points, and what became of it.</p>\n" +
					verdictsTable(found);
	h += "<p>Intermediate-plane images of the candidates, as the decoders saw them; each decode is drawn with its "
		 "vertex indices 0&ndash;3 (green: became a tag, orange: rejected by the pattern check).</p>\n";
	h += "<div class=\"gallery\">\n";
	for (const auto& ci : images.candidates)
		h += "<figure><img src=\"" + htmlEscape(ci.path) + "\" alt=\"candidate " + std::to_string(ci.index) +
			 "\"><figcaption>" + candidateCaption(ci.index, found.candidates[ci.index]) + "</figcaption></figure>\n";
	h += "</div>\n";
	if (images.candidatesOmitted)
		h += "<p>" + htmlEscape(format("%zu more candidate image(s) not shown.", images.candidatesOmitted)) + "</p>\n";
	return h;
}

std::string rejectedSection(const Detections& found, size_t maxListed)
{
	std::vector<size_t> idx;
	for (size_t i = 0; i < found.candidates.size(); i++)
		if (found.candidates[i].image.empty() && found.candidates[i].verdict != Verdict::Decoded) idx.push_back(i);
	std::stable_sort(idx.begin(), idx.end(), [&](size_t a, size_t b) {
		return found.candidates[a].clusterPoints > found.candidates[b].clusterPoints;
	});
	const size_t shown = std::min(idx.size(), maxListed);
	HtmlTable t({"#", "verdict", "cluster points", "box l x w x h [m]", "centre x y z [m]"});
	for (size_t k = 0; k < shown; k++)
	{
		const CandidateReport& c = found.candidates[idx[k]];
		const std::string verdict = verdictName(c.verdict) +
									(c.sameBoxAs ? " as #" + std::to_string(*c.sameBoxAs) : std::string()) +
									(c.onTagOf ? " of #" + std::to_string(*c.onTagOf) : std::string());
		t.addRow({std::to_string(idx[k]), verdict, std::to_string(c.clusterPoints),
				  format("%.3f x %.3f x %.3f", c.extent.x(), c.extent.y(), c.extent.z()), vec3(c.center, "%.2f")});
	}
	std::string h = "<h2>Clusters without an image</h2>\n<p>Rejected by the candidate filter before any image was "
					"made (size, squareness, not_flat), with an earlier candidate's box and decoded there "
					"(same_box as #N), centred on a tag an earlier candidate decoded (on_decoded_tag of #N), or "
					"whose points are not planar; biggest first.</p>\n";
	if (idx.empty()) return h + "<p>None.</p>\n";
	h += t.html();
	if (idx.size() > shown) h += "<p>" + htmlEscape(format("%zu more not listed.", idx.size() - shown)) + "</p>\n";
	return h;
}

std::string configSection(const PipelineParams& params)
{
	std::ostringstream yaml;
	params.toYaml().printAsYAML(yaml);
	return "<h2>Configuration</h2>\n<details><summary>Effective parameters (load with <code>--config</code>)"
		   "</summary>\n<pre>" +
		   htmlEscape(yaml.str()) + "</pre></details>\n";
}
}  // namespace

std::string reportPage(const ReportInput& in, const PageImages& images, const ReportParams& p)
{
	std::string h = "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\n"
					"<meta name=\"generator\" content=\"tagmap report\">\n<title>tagmap report: " +
					htmlEscape(in.inputPath) + "</title>\n" + kStyle + "</head><body>\n<h1>tagmap report</h1>\n";
	h += summarySection(in);
	h += "<h2>Map</h2>\n<img class=\"map\" src=\"" + htmlEscape(images.topView) + "\" alt=\"map view\">\n<p>" +
		 htmlEscape(images.topViewCaption) + ". Found tags are outlined in magenta (dot: vertex 0).</p>\n";
	h += detectionsSection(in.found);
	h += stagesSection(in.found);
	h += candidatesSection(in.found, images);
	h += rejectedSection(in.found, p.maxRejectedListed);
	h += configSection(in.params);
	return h + kImageCheck + "</body></html>\n";
}

}  // namespace tagmap::report
