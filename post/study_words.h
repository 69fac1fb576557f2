// A study's columns in words for axis titles: an output selector ("base.displacement",
// "sum:wall*.impacts", solver/study/study_outputs.h) read as "peak base displacement" or "number of
// impacts (sum over walls)", an axis name ("angle") as "incidence angle"; units are the caller's
// ([cm]).
#pragma once

#include <string>

namespace isopound::post {

// The selector in words, lower case ("peak storey drift ratio (largest storey)"); "" when the
// selector is empty or does not parse.
std::string output_words(const std::string& selector);

// An axis title: the selector's words, else "peak <column>" (the study file is gone), with the
// unit in brackets unless it is "-" or empty: "peak base displacement [cm]".
std::string output_title(const std::string& selector, const std::string& column,
                         const std::string& unit);

// A swept axis in words ("angle": "incidence angle", "tb": "isolation period T_b"; others as
// named, '_' read as a space).
std::string axis_words(const std::string& axis);

// The first letter upper case (ASCII), for titles.
std::string capitalised(std::string text);

}  // namespace isopound::post
