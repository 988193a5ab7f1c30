#include "train/dataset/config.h"

#include <string>

#include "src/error.h"

namespace colav {
namespace {

using Options = DatasetGenerationOptions;

// Scans of each kind at most: a million scans make 3 million rows, 2 GB in memory.
constexpr std::int64_t kMaxScans = 1'000'000;
// Steps of a pilot's turn or between recorded scans at most: half an episode (env.max_steps 2000).
constexpr std::int64_t kMaxSteps = 1'000;

void RequireOrdered(double low, double high, const std::string& low_key,
                    const std::string& high_key) {
  if (low > high) {
    throw UserError(low_key + " (" + std::to_string(low) + ") exceeds " + high_key + " (" +
                    std::to_string(high) + ")");
  }
}

void RequireConsistent(Options& options) {
  if (options.augmentation.fixed_shift_rays > 0 && options.augmentation.shifts_per_scan > 2) {
    throw UserError("augmentation.shifts_per_scan (" +
                    std::to_string(options.augmentation.shifts_per_scan) +
                    ") exceeds the 2 fixed shifts of augmentation.fixed_shift_rays");
  }
  if (options.synthetic_scans > 0) RequirePlaceableShapes(options.synthetic);
  RequireOrdered(options.mixed_share + options.vessels_share, 1.0,
                 "dataset.mixed_share + dataset.vessels_share", "1");
  const ScriptedPilotOptions& pilot = options.simulator.pilot;
  RequireOrdered(pilot.thrust_min, pilot.thrust_max, "pilot.thrust_min", "pilot.thrust_max");
  RequireOrdered(pilot.evasive_turn_min_steps, pilot.evasive_turn_max_steps,
                 "pilot.evasive_turn_min_steps", "pilot.evasive_turn_max_steps");
  const SimulatorRecordingOptions& recording = options.simulator;
  RequireOrdered(recording.sample_interval_min, recording.sample_interval_max,
                 "recording.sample_interval_min", "recording.sample_interval_max");
}

}  // namespace

OptionsBinding<DatasetGenerationOptions> DatasetGenerationBinding() {
  using Synthetic = SyntheticSceneOptions;
  using Recording = SimulatorRecordingOptions;
  using Pilot = ScriptedPilotOptions;
  // Accessors of the nested options' fields.
  const auto synthetic = [](auto field) {
    return [field](Options & options) -> auto& { return options.synthetic.*field; };
  };
  const auto augmentation = [](auto field) {
    return [field](Options & options) -> auto& { return options.augmentation.*field; };
  };
  const auto pilot = [](auto field) {
    return [field](Options & options) -> auto& { return options.simulator.pilot.*field; };
  };
  const auto recording = [](auto field) {
    return [field](Options & options) -> auto& { return options.simulator.*field; };
  };
  OptionsBinding<Options> binding;
  binding
      .Number("dataset.sim_scans", &Options::sim_scans,
              "scans recorded in the training environment (scripted pilot)", 0, kMaxScans)
      .Number("dataset.synthetic_scans", &Options::synthetic_scans,
              "synthetic scans (three groups)", 0, kMaxScans)
      .Number("dataset.seed", &Options::seed, "master seed of everything random", 0)
      .Number("dataset.threads", &Options::threads,
              "worker threads (the output does not depend on it)", 1, 256)
      .Number("dataset.mixed_share", &Options::mixed_share,
              "share of synthetic scans with 3 circles + 2 vessels", 0.0, 1.0)
      .Number("dataset.vessels_share", &Options::vessels_share,
              "share of synthetic scans with 5 vessels (5 circles: the rest)", 0.0, 1.0)
      .Number("augmentation.shifts_per_scan", augmentation(&AugmentationOptions::shifts_per_scan),
              "circular shifts added per scan, random unless fixed (2: 20,000 -> 60,000 rows)", 0,
              179)
      .Number("augmentation.fixed_shift_rays", augmentation(&AugmentationOptions::fixed_shift_rays),
              "0: random shifts; k: shifts of +k then -k rays instead (the reference: 10, +-20 "
              "degrees; shifts_per_scan at most 2)",
              0, kNumRays / 2 - 1)
      .Number("augmentation.test_fraction", augmentation(&AugmentationOptions::test_fraction),
              "share of source scans in the test split", 0.0, 1.0)
      .Number("augmentation.validation_fraction",
              augmentation(&AugmentationOptions::validation_fraction),
              "share of the non-test source scans held out for validation", 0.0, 1.0)
      .Number("synthetic.radius_mean", synthetic(&Synthetic::radius_mean),
              "Poisson mean of circle radii (m)", 1.0, 100.0)
      .Number("synthetic.width_mean", synthetic(&Synthetic::width_mean),
              "Poisson mean of vessel widths (m)", 1.0, 100.0)
      .Number("synthetic.extent", synthetic(&Synthetic::extent),
              "obstacle centres uniform in [-extent, extent]^2 (m)", 10.0, 1000.0)
      .Number("synthetic.safe_zone_radius", synthetic(&Synthetic::safe_zone_radius),
              "obstacle-free disc around the sensor (m)", 0.0, 140.0)
      .Number("pilot.heading_gain", pilot(&Pilot::heading_gain),
              "yaw action per rad of line-of-sight heading error: a1 = clip(k * heading_error - "
              "kd * r + noise)",
              0.0, 1000.0)
      .Number("pilot.yaw_rate_gain", pilot(&Pilot::yaw_rate_gain),
              "yaw action per rad/s of yaw rate (damping, kd)", 0.0, 1000.0)
      .Number("pilot.steering_noise_sd", pilot(&Pilot::steering_noise_sd),
              "Gaussian noise on the yaw action", 0.0, 10.0)
      .Number("pilot.thrust_min", pilot(&Pilot::thrust_min), "lowest thrust action level", -1.0,
              1.0)
      .Number("pilot.thrust_max", pilot(&Pilot::thrust_max), "highest thrust action level", -1.0,
              1.0)
      .Number("pilot.thrust_change_probability", pilot(&Pilot::thrust_change_probability),
              "per step: draw a new thrust level", 0.0, 1.0)
      .Number("pilot.evasive_turn_probability", pilot(&Pilot::evasive_turn_probability),
              "per step: start a full-rudder turn", 0.0, 1.0)
      .Number("pilot.evasive_turn_min_steps", pilot(&Pilot::evasive_turn_min_steps),
              "shortest evasive turn (steps)", 1, kMaxSteps)
      .Number("pilot.evasive_turn_max_steps", pilot(&Pilot::evasive_turn_max_steps),
              "longest evasive turn (steps)", 1, kMaxSteps)
      .Number("recording.sample_interval_min", recording(&Recording::sample_interval_min),
              "fewest steps between two recorded scans", 1, kMaxSteps)
      .Number("recording.sample_interval_max", recording(&Recording::sample_interval_max),
              "most steps between two recorded scans", 1, kMaxSteps)
      .Number("recording.max_scans_per_episode", recording(&Recording::max_scans_per_episode),
              "scans recorded per episode at most", 1, kMaxSteps)
      .Then(RequireConsistent);
  return binding;
}

}  // namespace colav
