#pragma once
// The survey's and the graph's figures in report.md, written for a reader: a name, the value with
// its unit and one line of what it means. The raw keys stay in survey.json and graph.json.
#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace slamroute::cli {

struct Figure {
  const char* key;      ///< key in the JSON object
  const char* name;     ///< what a reader calls it
  const char* unit;     ///< appended to the value ("" for counts and ratios)
  int precision;        ///< decimals of a floating-point value
  const char* meaning;  ///< one line
};

/// The figures the report shows of survey.json and of graph.json's metadata sections.
const std::vector<Figure>& surveyFigures();
/// "validation", "stats", "weights" or "sumo_mapping"; empty for another section.
const std::vector<Figure>& graphFigures(const std::string& section);

/// A Markdown table | figure | value | meaning | of the figures of `obj` that `figures` lists, in
/// that order (lists by their length), ending with where the raw keys are (`source`).
std::string figureTable(const std::string& title, const nlohmann::json& obj,
                        const std::vector<Figure>& figures, const std::string& source);

}  // namespace slamroute::cli
