#pragma once
// crux stances' output: the share of the stances kinematic climbs reach that the static
// model holds, on four holds and on three, with intervals over walls and the reasons of
// the failures (docs/OUTPUTS.md, "crux stances").

#include <string>

#include <nlohmann/json.hpp>

#include "experiments/stance_survey.hpp"

namespace crux {

nlohmann::ordered_json stance_survey_json(const StanceSurvey& survey, const StanceSurveyParameters& parameters);
std::string stance_survey_text(const StanceSurvey& survey, const StanceSurveyParameters& parameters);

}  // namespace crux
