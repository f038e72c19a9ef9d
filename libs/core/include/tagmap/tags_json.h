// The result file of docs/RESULT_FORMAT.md: {"tags": [...]} plus optional
// extra top-level fields (scene metadata for ground truth, a report summary).
#pragma once

#include <string>
#include <vector>

#include "tagmap/tag_detection.h"

namespace tagmap
{
/** Serialises tags to the result JSON. `extraFields` is inserted as
 *  further top-level members, e.g. "\"scene\": \"parking\"" (may be empty);
 *  `tagFields[k]`, when given, as further members of tag k (the simulator's
 *  per-tag sighting conditions). Output is deterministic: fixed key order
 *  and number formatting. */
std::string tagsToJson(const std::vector<TagDetection>& tags, const std::string& extraFields = {},
					   const std::vector<std::string>& tagFields = {});

/** Writes tagsToJson() atomically (temp file + rename). */
void writeTagsJson(const std::string& path, const std::vector<TagDetection>& tags, const std::string& extraFields = {},
				   const std::vector<std::string>& tagFields = {});

/** Reads the `tags` list (or another list of the same schema, such as the
 *  simulator's `tags_in_map`) of a result or ground-truth file. Throws InputError. */
std::vector<TagDetection> readTagsJson(const std::string& path, const std::string& listKey = "tags");

/** JSON string literal with escapes, including the quotes. */
std::string jsonQuote(const std::string& s);

}  // namespace tagmap
