// `tagmap detect --report DIR`: a static HTML page people open in a browser,
//   DIR/index.html          summary, tables, configuration
//   DIR/map.png             the map coloured by intensity, tags outlined
//   DIR/candidates/*.png    each candidate's intermediate-plane image
// The folder is built aside and swapped into place, so DIR is never partial.
#pragma once

#include <string>

#include "tagmap/report/report_input.h"

namespace tagmap::report
{
/** Throws InputError when DIR cannot be written or replaced (an existing
 *  non-empty folder is replaced only when an earlier report wrote it). */
void checkReportDir(const std::string& dir);

void writeReport(const std::string& dir, const ReportInput& in, const ReportParams& p = {});

}  // namespace tagmap::report
