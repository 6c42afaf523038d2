#pragma once
// report.html of a pipeline run, beside report.md: the street network, each route (one feature
// per SUMO edge driven, with a slider along the drive), the streets coloured by their weight,
// times driven, measured drift, the trajectory error along the drive, map error and the tables,
// and a fleet's routes in one colour per vehicle with its merged map (HtmlFleet.hpp); pan and
// zoom. One self-contained file (HtmlPage.hpp).
#include <string>

#include "Report.hpp"

namespace slamroute::cli {

/// Writes in.out/report.html. Returns "" or a one-line note why it could not (the JavaScript
/// library was not vendored by the build). `geo_origin` ("LAT,LON" or "") places a net without
/// geo-reference; without one such a net is drawn in its own x/y metres.
std::string writeHtmlReport(const ReportInputs& in, const std::string& geo_origin);

}  // namespace slamroute::cli
