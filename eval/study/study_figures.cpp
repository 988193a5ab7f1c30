#include "eval/study/study_figures.h"

#include <fmt/format.h>

#include <algorithm>
#include <map>
#include <optional>
#include <sstream>

#include "eval/study/job_graph.h"
#include "src/figures/gnuplot.h"
#include "src/figures/style.h"
#include "src/statistics.h"

namespace colav {
namespace {

// The metrics the figures show, in panel order (the paper's table).
const char* const kFigureMetrics[] = {"progress", "cross_track_error", "duration", "collision"};
constexpr double kDefaultBeta = 1.0;  // train_vae's vae.beta

// The study's model of several seeds named `name` (study_spec.h), if there is one.
std::optional<SeededModel> FindSeeded(const StudySpec& spec, const std::string& name) {
  for (const SeededModel& model : spec.SeededModels()) {
    if (model.name == name) return model;
  }
  return std::nullopt;
}

// The mean of `metric` of each seed of the configuration or ensemble kind `name` (in the
// report's unit).
std::vector<double> SeedMeans(const ScenarioSetReport& report, const ScenarioSetResults& results,
                              const std::string& name, const std::string& metric) {
  const int seeds = SummaryOf(report, name).seeds;
  std::vector<double> means;
  means.reserve(static_cast<std::size_t>(seeds));
  for (int k = 0; k < seeds; ++k) {
    means.push_back(Mean(results.models.at(SeedModelName(name, k)).at(metric)));
  }
  return means;
}

std::string Estimates(const ScenarioSetReport& report, const std::vector<std::string>& names,
                      const std::string& metric, const std::map<std::string, double>& position) {
  std::ostringstream block;
  for (const std::string& name : names) {
    const MetricEstimate& e = SummaryOf(report, name).metrics.at(metric);
    block << position.at(name) << ' ' << e.mean << ' ' << e.ci.low << ' ' << e.ci.high << '\n';
  }
  return block.str();
}

std::string DataBlock(const std::string& name, const std::string& rows) {
  return "$" + name + " << EOD\n" + (rows.empty() ? "nan nan nan nan\n" : rows) + "EOD\n";
}

// The report's models in its order, split into ours (configurations and ensemble kinds) and the
// reference agents.
std::pair<std::vector<std::string>, std::vector<std::string>> OursAndReferences(
    const StudySpec& spec, const ScenarioSetReport& report) {
  std::pair<std::vector<std::string>, std::vector<std::string>> split;
  for (const ModelSummary& model : report.models) {
    (FindSeeded(spec, model.name) ? split.first : split.second).push_back(model.name);
  }
  return split;
}

// Rows "collisions metric collisions-low collisions-high metric-low metric-high name".
std::string TradeOffRows(const ScenarioSetReport& report, const std::vector<std::string>& names,
                         const std::string& metric) {
  std::ostringstream rows;
  for (const std::string& name : names) {
    const ModelSummary& model = SummaryOf(report, name);
    const MetricEstimate& x = model.metrics.at("collision");
    const MetricEstimate& y = model.metrics.at(metric);
    rows << x.mean << ' ' << y.mean << ' ' << x.ci.low << ' ' << x.ci.high << ' ' << y.ci.low << ' '
         << y.ci.high << " \"" << name << "\"\n";
  }
  return rows.str();
}

}  // namespace

void DrawModelsFigure(const StudySpec& spec, const ScenarioSetResults& results,
                      const ScenarioSetReport& report, const std::string& title,
                      const std::filesystem::path& png) {
  const auto [ours, references] = OursAndReferences(spec, report);
  std::map<std::string, double> row;  // first model on top
  for (std::size_t m = 0; m < report.models.size(); ++m) {
    row[report.models[m].name] = static_cast<double>(report.models.size() - m);
  }
  std::ostringstream script;
  std::string ytics;
  for (const auto& [name, y] : row) {
    ytics += (ytics.empty() ? "" : ", ") + GnuplotQuote(GnuplotEnhancedText(name)) +
             fmt::format(" {}", y);
  }
  script << MultiplotLayout(2, 2, GnuplotEnhancedText(title)) << LightGrid()
         << fmt::format("set yrange [0.5:{}]\nset ytics ({})\nset key below horizontal\n",
                        report.models.size() + 0.5, ytics);
  for (const char* metric : kFigureMetrics) {
    std::ostringstream seeds;
    for (const std::string& config : ours) {
      for (const double mean : SeedMeans(report, results, config, metric)) {
        seeds << mean << ' ' << row.at(config) << '\n';
      }
    }
    script << DataBlock(std::string("ours_") + metric, Estimates(report, ours, metric, row))
           << DataBlock(std::string("refs_") + metric, Estimates(report, references, metric, row))
           << DataBlock(std::string("seeds_") + metric, seeds.str()) << "set title "
           << GnuplotQuote(FindStudyMetric(metric)->label) << "\n"
           << "plot $seeds_" << metric << " using 1:2 with points pt 6 ps 0.7 "
           << LineColour("#999999") << " title 'training seeds', $ours_" << metric
           << " using 2:1:3:4 with xerrorbars pt 7 ps 1.2 lw 2 " << LineColour(FigureColour(0))
           << " title 'configuration, 95 % CI', $refs_" << metric
           << " using 2:1:3:4 with xerrorbars pt 9 ps 1.4 lw 2 " << LineColour(FigureColour(1))
           << " title 'reference agent, 95 % CI'\n";
  }
  script << "unset multiplot\n";
  RenderGnuplotPng(script.str(), png, 1100,
                   std::max(500, 160 + 2 * 26 * static_cast<int>(report.models.size())));
}

void DrawTradeOffFigure(const StudySpec& spec, const ScenarioSetReport& report,
                        const std::string& title, const std::filesystem::path& png) {
  const auto [ours, references] = OursAndReferences(spec, report);
  struct Group {
    std::string name;
    const std::vector<std::string>& models;
    std::string style;
    std::string title;
  };
  const Group groups[] = {
      {"ours", ours, "pt 7 ps 1.2 " + LineColour(FigureColour(0)), "configuration, 95 % CI"},
      {"refs", references, "pt 9 ps 1.4 " + LineColour(FigureColour(1)),
       "reference agent, 95 % CI"}};
  std::ostringstream script;
  script << MultiplotLayout(1, 2, GnuplotEnhancedText(title)) << LightGrid()
         << "set key below horizontal\nset offsets graph 0.05, graph 0.25, graph 0.05, graph "
            "0.05\nset xlabel "
         << GnuplotQuote(FindStudyMetric("collision")->label) << "\n";
  for (const char* metric : {"progress", "cross_track_error"}) {
    std::string points;
    std::string labels;
    for (const Group& group : groups) {
      if (group.models.empty()) continue;  // a study without reference agents
      const std::string block = group.name + "_" + metric;
      script << DataBlock(block, TradeOffRows(report, group.models, metric));
      points +=
          fmt::format("{}${} using 1:2:3:4:5:6 with xyerrorbars {} title {}",
                      points.empty() ? "" : ", ", block, group.style, GnuplotQuote(group.title));
      labels += fmt::format(
          ", ${} using 1:2:7 with labels offset 0.6,0.6 left noenhanced font ',9' notitle", block);
    }
    script << "set ylabel " << GnuplotQuote(FindStudyMetric(metric)->label) << "\nplot " << points
           << labels << "\n";
  }
  script << "unset multiplot\n";
  RenderGnuplotPng(script.str(), png, 1200, 560);
}

std::vector<std::pair<double, std::string>> BetaSweep(const StudySpec& spec) {
  std::map<std::string, std::vector<std::pair<double, std::string>>> by_extractor;
  for (const PpoConfigSpec& config : spec.ppo_configs) {
    if (config.extractor == "baseline" || !config.locked || !config.overrides.empty()) continue;
    const auto vae = std::find_if(spec.vaes.begin(), spec.vaes.end(),
                                  [&](const VaeSpec& v) { return v.name == config.vae; });
    double beta = kDefaultBeta;
    for (const std::string& assignment : vae->overrides) {
      if (assignment.rfind("vae.beta=", 0) == 0) beta = std::stod(assignment.substr(9));
    }
    by_extractor[config.extractor].emplace_back(beta, config.name);
  }
  std::vector<std::pair<double, std::string>> sweep;
  for (auto& [extractor, points] : by_extractor) {
    if (points.size() > sweep.size()) sweep = points;
  }
  std::sort(sweep.begin(), sweep.end());
  const bool distinct = std::adjacent_find(sweep.begin(), sweep.end(), [](auto& a, auto& b) {
                          return a.first == b.first;
                        }) == sweep.end();
  if (sweep.size() < 3 || !distinct) return {};
  return sweep;
}

void DrawBetaSweepFigure(const ScenarioSetResults& results, const ScenarioSetReport& report,
                         const std::vector<std::pair<double, std::string>>& sweep,
                         const std::filesystem::path& png) {
  std::ostringstream script;
  script << MultiplotLayout(2, 2,
                            GnuplotEnhancedText("Beta sweep: " + sweep.front().second + " ... " +
                                                sweep.back().second))
         << LightGrid()
         << "set xlabel 'beta of the VAE'\nset key below horizontal\nset offsets graph 0.04, graph "
            "0.04, 0, 0\n";
  for (const char* metric : kFigureMetrics) {
    std::ostringstream estimates;
    std::ostringstream seeds;
    for (const auto& [beta, config] : sweep) {
      const MetricEstimate& e = SummaryOf(report, config).metrics.at(metric);
      estimates << beta << ' ' << e.mean << ' ' << e.ci.low << ' ' << e.ci.high << '\n';
      for (const double mean : SeedMeans(report, results, config, metric)) {
        seeds << beta << ' ' << mean << '\n';
      }
    }
    script << DataBlock(std::string("sweep_") + metric, estimates.str())
           << DataBlock(std::string("seeds_") + metric, seeds.str()) << "set title "
           << GnuplotQuote(FindStudyMetric(metric)->label) << "\nplot $seeds_" << metric
           << " using 1:2 with points pt 6 ps 0.7 " << LineColour("#999999")
           << " title 'training seeds', $sweep_" << metric
           << " using 1:2:3:4 with yerrorlines pt 7 lw 2 " << LineColour(FigureColour(0))
           << " title 'mean over seeds, 95 % CI'\n";
  }
  script << "unset multiplot\n";
  RenderGnuplotPng(script.str(), png, 1000, 800);
}

}  // namespace colav
