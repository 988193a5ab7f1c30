// The study report's figures (gnuplot PNGs): every model's estimate with its interval and its
// training seeds, the way rliable draws results of deep RL, the trade-off between collisions and
// the other two metrics, and the beta sweep when the study has one.
#pragma once

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "eval/study/study_report.h"

namespace colav {

/// One panel per metric (progress, cross-track error, duration, collisions): each model a row with
/// its estimate and 95 % interval (ScenarioSetReport), our configurations' seed means as dots, the
/// reference agents in their own colour.
void DrawModelsFigure(const StudySpec& spec, const ScenarioSetResults& results,
                      const ScenarioSetReport& report, const std::string& title,
                      const std::filesystem::path& png);

/// Collisions against progress and against cross-track error, one panel each: every model at its
/// two estimates with their 95 % intervals, named, our configurations and the reference agents in
/// their own colours, so that the trade-off between caution and progress or path shows at a
/// glance.
void DrawTradeOffFigure(const StudySpec& spec, const ScenarioSetReport& report,
                        const std::string& title, const std::filesystem::path& png);

/// (beta, configuration) of the study's beta sweep, beta ascending: the locked configurations
/// without overrides of one extractor whose VAEs differ in vae.beta (1 when not set), when there
/// are at least three betas. Empty otherwise.
std::vector<std::pair<double, std::string>> BetaSweep(const StudySpec& spec);

/// Each metric's estimate with its interval and the seed means against the VAE's beta.
void DrawBetaSweepFigure(const ScenarioSetResults& results, const ScenarioSetReport& report,
                         const std::vector<std::pair<double, std::string>>& sweep,
                         const std::filesystem::path& png);

}  // namespace colav
