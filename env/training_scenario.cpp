#include "env/training_scenario.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>

#include "env/angles.h"
#include "env/path.h"
#include "env/vessel_model.h"
#include "src/random.h"

namespace colav {
namespace {

// Empirical speed distribution of the reference (resources/speed_*.txt): 100 speeds evenly
// spaced from kSlowest to kFastest with these probabilities.
constexpr double kSlowest = 5.973753401783561678e-02;
constexpr double kFastest = 1.987489866097870594e+00;
constexpr std::array<double, 100> kSpeedProbabilities = {
    1.206554933469061210e-02, 1.064313240747473237e-02, 8.748091325528974810e-03,
    7.702864829491747230e-03, 7.421108121864320763e-03, 7.262051915945612161e-03,
    7.734676070675489123e-03, 7.857376572384206989e-03, 7.666509125281756494e-03,
    8.970770013815167199e-03, 9.343415981967570505e-03, 1.056587653602850292e-02,
    1.082036646549843634e-02, 1.208827164982185717e-02, 1.391060132334763326e-02,
    1.582836472042463416e-02, 2.081364066021958864e-02, 2.681687631789427678e-02,
    3.473787537264597103e-02, 4.281793063331636867e-02, 5.079346324438304555e-02,
    5.776466952664872923e-02, 6.304988002617610554e-02, 6.288627935723115070e-02,
    5.821911582927360995e-02, 5.194321239002399476e-02, 4.778502872100632431e-02,
    4.459481567657965634e-02, 4.031847596887951773e-02, 3.600578055696938840e-02,
    3.023431251363338859e-02, 2.396295353741001791e-02, 1.735530429724423812e-02,
    1.446048134952374054e-02, 1.312440921980658794e-02, 1.228822802297680448e-02,
    1.062495455536973700e-02, 8.180033447247873901e-03, 5.457900094524830575e-03,
    4.276339707700137736e-03, 2.908456336799243678e-03, 2.144986548389442131e-03,
    1.617828837344579282e-03, 1.213371628008434516e-03, 7.589253253835527048e-04,
    7.543808623573038628e-04, 7.725587144622991223e-04, 6.544026757798298817e-04,
    6.998473060423180845e-04, 6.453137497273321978e-04, 4.908020068348724384e-04,
    7.362030102523086034e-04, 8.770813640660219453e-04, 9.407038464335054076e-04,
    1.090671126299716433e-03, 1.376972296953391959e-03, 2.013197120628226582e-03,
    2.231331345888169695e-03, 2.181342252599432867e-03, 1.831418599578273770e-03,
    1.636006689449574650e-03, 1.372427833927143117e-03, 1.231549480113429884e-03,
    7.998254926197920656e-04, 6.816694539373227167e-04, 7.225696211735621859e-04,
    4.953464698611211720e-04, 2.999345597324219975e-04, 2.635788555224314786e-04,
    2.317676143386897475e-04, 2.499454664436850070e-04, 2.590343924961826367e-04,
    2.772122446011779503e-04, 2.908456336799243678e-04, 4.226350614411401342e-04,
    4.635352286773794950e-04, 6.498582127535810398e-04, 9.497927724860030915e-04,
    1.090671126299716433e-03, 1.304260888533410922e-03, 1.581473133134588763e-03,
    1.785973969315785568e-03, 2.108630844179451829e-03, 2.040463898785719633e-03,
    2.490365738384352386e-03, 2.490365738384352386e-03, 2.331309532465643784e-03,
    2.031374972733221949e-03, 1.717807023922053372e-03, 1.395150149058387327e-03,
    9.452483094597542495e-04, 8.589035119610266859e-04, 4.726241547298771248e-04,
    2.953900967061732098e-04, 2.408565403911873772e-04, 1.408783538137133690e-04,
    1.090671126299716379e-04, 9.543372355122519335e-05, 5.453355631498581896e-05,
    4.090016723623936761e-05,
};

// Moving obstacles are advanced by 0.1 s at construction and 1 s before the first observation.
constexpr double kObstacleLeadTime = 1.1;

// Random curve through the origin (reference-simulator 4.1): n drawn per episode, of which only
// the k = n / 2 bends matter, unless `bends` (1 or 2) fixes k. The draw of n is made either way.
std::vector<Eigen::Vector2d> RandomWaypoints(Rng& rng, double length, int bends) {
  const int n = static_cast<int>(std::floor(4.0 * Uniform01(rng) + 2.0));
  const double alpha = 2.0 * kPi * (Uniform01(rng) - 0.5);
  const Eigen::Vector2d start = (length / 2.0) * Eigen::Vector2d(std::cos(alpha), std::sin(alpha));
  const Eigen::Vector2d end = -start;
  const int k = bends > 0 ? bends : n / 2;
  std::vector<Eigen::Vector2d> waypoints = {start, end};
  for (int w = 0; w < k; ++w) {
    const double scale = length / (k + 1);
    // The same scalar offset on both axes, as the reference.
    const Eigen::Vector2d p1 =
        (k - w) * start / (k + 1) + scale * (Uniform01(rng) - 0.5) * Eigen::Vector2d::Ones();
    const Eigen::Vector2d p2 =
        (k - w) * end / (k + 1) + scale * (Uniform01(rng) - 0.5) * Eigen::Vector2d::Ones();
    std::vector<Eigen::Vector2d> next(waypoints.begin(), waypoints.begin() + w + 1);
    next.insert(next.end(), {p1, Eigen::Vector2d::Zero(), p2});
    next.insert(next.end(), waypoints.end() - (w + 1), waypoints.end());
    waypoints = std::move(next);
  }
  return waypoints;
}

struct Placement {
  Eigen::Vector2d position;
  double size;
};

// generate_obstacle (reference-simulator 5.1): offset perpendicular to the middle 80 % of the
// path, size Poisson, kept away from the start and the goal.
Placement PlaceObstacle(Rng& rng, const Path& path, const Eigen::Vector2d& vessel_position,
                        double displacement_sd, double size_mean, double min_clearance) {
  while (true) {
    const double displacement = Normal(rng, 0.0, displacement_sd);
    const double s = (0.1 + 0.8 * Uniform01(rng)) * path.length();
    const double normal_angle = WrapAngle(path.Direction(s) - kPi / 2.0);
    const Eigen::Vector2d position =
        path.Point(s) +
        displacement * Eigen::Vector2d(std::cos(normal_angle), std::sin(normal_angle));
    const double size = std::max<double>(1.0, static_cast<double>(Poisson(rng, size_mean)));
    const double vessel_clearance =
        (position - vessel_position).norm() - CybershipModel::kRadius - size;
    const double goal_clearance = (position - path.end()).norm() - size;
    if (std::min(vessel_clearance, goal_clearance) > min_clearance) return {position, size};
  }
}

}  // namespace

double MovingObstacleSpeed(double u) {
  const double total = std::accumulate(kSpeedProbabilities.begin(), kSpeedProbabilities.end(), 0.0);
  double cumulative = 0.0;
  std::size_t k = 0;
  // searchsorted(cdf / cdf[-1], u, side='right')
  for (; k + 1 < kSpeedProbabilities.size(); ++k) {
    cumulative += kSpeedProbabilities[k];
    if (u < cumulative / total) break;
  }
  return kSlowest + static_cast<double>(k) * (kFastest - kSlowest) / 99.0;
}

Scenario TrainingScenarioGenerator::Make(std::uint64_t seed) const {
  Rng rng(seed);
  Scenario scenario;
  scenario.name = "training-" + std::to_string(seed);
  scenario.waypoints = RandomWaypoints(rng, config_.nominal_path_length, config_.path_bends);
  const Path path(scenario.waypoints);
  const double offset_x = 2.0 * config_.start_offset * (Uniform01(rng) - 0.5);
  const double offset_y = 2.0 * config_.start_offset * (Uniform01(rng) - 0.5);
  scenario.vessel_position = path.start() + Eigen::Vector2d(offset_x, offset_y);
  scenario.vessel_heading = WrapAngle(path.Direction(0.0) + 2.0 * kPi * (Uniform01(rng) - 0.5));
  for (int k = 0; k < config_.num_moving; ++k) {
    const Placement placement =
        PlaceObstacle(rng, path, scenario.vessel_position, config_.moving_displacement_sd,
                      config_.moving_width_mean, config_.min_clearance);
    VesselObstacleSpec obstacle;
    obstacle.width = placement.size;
    obstacle.course = 2.0 * kPi * Uniform01(rng);
    obstacle.speed = MovingObstacleSpeed(Uniform01(rng));
    obstacle.position = placement.position +
                        kObstacleLeadTime * obstacle.speed *
                            Eigen::Vector2d(std::cos(obstacle.course), std::sin(obstacle.course));
    scenario.dynamic_obstacles.push_back(obstacle);
  }
  for (int k = 0; k < config_.num_static; ++k) {
    const Placement placement =
        PlaceObstacle(rng, path, scenario.vessel_position, config_.static_displacement_sd,
                      config_.static_radius_mean, config_.min_clearance);
    scenario.static_obstacles.push_back({placement.position, placement.size});
  }
  return scenario;
}

}  // namespace colav
