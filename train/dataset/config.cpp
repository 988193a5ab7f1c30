#include "train/dataset/config.h"

#include "src/error.h"

namespace colav {
namespace {

void RequireOrdered(double low, double high, const std::string& low_key,
                    const std::string& high_key) {
  if (low > high) {
    throw UserError(low_key + " (" + std::to_string(low) + ") exceeds " + high_key + " (" +
                    std::to_string(high) + ")");
  }
}

}  // namespace

ConfigSchema DatasetGenerationSchema() {
  ConfigSchema schema;
  schema.AddInt("dataset.sim_scans", 10000, "scans recorded in the training environment", 0)
      .AddInt("dataset.synthetic_scans", 10000, "synthetic scans (three groups)", 0)
      .AddInt("dataset.seed", 0, "master seed of everything random", 0)
      .AddInt("dataset.threads", 2, "worker threads (the output does not depend on it)", 1, 256)
      .AddDouble("dataset.mixed_share", 0.5, "share of synthetic scans with 3 circles + 2 vessels",
                 0.0, 1.0)
      .AddDouble("dataset.vessels_share", 0.25,
                 "share of synthetic scans with 5 vessels (5 circles: "
                 "the rest)",
                 0.0, 1.0)
      .AddInt("augmentation.shifts_per_scan", 2, "random circular shifts added per scan", 0, 179)
      .AddDouble("augmentation.test_fraction", 0.3, "share of source scans in the test split", 0.0,
                 1.0)
      .AddDouble("augmentation.validation_fraction", 0.2,
                 "share of the non-test source scans held out for validation", 0.0, 1.0)
      .AddDouble("synthetic.radius_mean", 25.0, "Poisson mean of circle radii (m)", 0.0)
      .AddDouble("synthetic.width_mean", 10.0, "Poisson mean of vessel widths (m)", 0.0)
      .AddDouble("synthetic.extent", 150.0, "obstacle centres uniform in [-extent, extent]^2 (m)",
                 1.0)
      .AddDouble("synthetic.safe_zone_radius", 10.0, "obstacle-free disc around the sensor (m)",
                 0.0, 140.0)
      .AddDouble("pilot.heading_gain", 1.0, "yaw action per rad of line-of-sight heading error",
                 0.0)
      .AddDouble("pilot.yaw_rate_gain", 5.0, "yaw action per rad/s of yaw rate (damping)", 0.0)
      .AddDouble("pilot.steering_noise_sd", 0.2, "Gaussian noise on the yaw action", 0.0)
      .AddDouble("pilot.thrust_min", -0.2, "lowest thrust action level", -1.0, 1.0)
      .AddDouble("pilot.thrust_max", 1.0, "highest thrust action level", -1.0, 1.0)
      .AddDouble("pilot.thrust_change_probability", 0.02, "per step: draw a new thrust level", 0.0,
                 1.0)
      .AddDouble("pilot.evasive_turn_probability", 0.01, "per step: start a full-rudder turn", 0.0,
                 1.0)
      .AddInt("pilot.evasive_turn_min_steps", 10, "shortest evasive turn (steps)", 1)
      .AddInt("pilot.evasive_turn_max_steps", 40, "longest evasive turn (steps)", 1)
      .AddInt("recording.sample_interval_min", 5, "fewest steps between two recorded scans", 1)
      .AddInt("recording.sample_interval_max", 15, "most steps between two recorded scans", 1)
      .AddInt("recording.max_scans_per_episode", 50, "scans recorded per episode at most", 1);
  return schema;
}

DatasetGenerationOptions DatasetGenerationOptionsFrom(const Config& config) {
  DatasetGenerationOptions options;
  options.sim_scans = config.GetInt("dataset.sim_scans");
  options.synthetic_scans = config.GetInt("dataset.synthetic_scans");
  options.seed = static_cast<std::uint64_t>(config.GetInt("dataset.seed"));
  options.threads = static_cast<int>(config.GetInt("dataset.threads"));
  options.mixed_share = config.GetDouble("dataset.mixed_share");
  options.vessels_share = config.GetDouble("dataset.vessels_share");
  RequireOrdered(options.mixed_share + options.vessels_share, 1.0,
                 "dataset.mixed_share + dataset.vessels_share", "1");

  AugmentationOptions& augmentation = options.augmentation;
  augmentation.shifts_per_scan = static_cast<int>(config.GetInt("augmentation.shifts_per_scan"));
  augmentation.test_fraction = config.GetDouble("augmentation.test_fraction");
  augmentation.validation_fraction = config.GetDouble("augmentation.validation_fraction");

  SyntheticSceneOptions& synthetic = options.synthetic;
  synthetic.radius_mean = config.GetDouble("synthetic.radius_mean");
  synthetic.width_mean = config.GetDouble("synthetic.width_mean");
  synthetic.extent = config.GetDouble("synthetic.extent");
  synthetic.safe_zone_radius = config.GetDouble("synthetic.safe_zone_radius");

  ScriptedPilotOptions& pilot = options.simulator.pilot;
  pilot.heading_gain = config.GetDouble("pilot.heading_gain");
  pilot.yaw_rate_gain = config.GetDouble("pilot.yaw_rate_gain");
  pilot.steering_noise_sd = config.GetDouble("pilot.steering_noise_sd");
  pilot.thrust_min = config.GetDouble("pilot.thrust_min");
  pilot.thrust_max = config.GetDouble("pilot.thrust_max");
  RequireOrdered(pilot.thrust_min, pilot.thrust_max, "pilot.thrust_min", "pilot.thrust_max");
  pilot.thrust_change_probability = config.GetDouble("pilot.thrust_change_probability");
  pilot.evasive_turn_probability = config.GetDouble("pilot.evasive_turn_probability");
  pilot.evasive_turn_min_steps = static_cast<int>(config.GetInt("pilot.evasive_turn_min_steps"));
  pilot.evasive_turn_max_steps = static_cast<int>(config.GetInt("pilot.evasive_turn_max_steps"));
  RequireOrdered(pilot.evasive_turn_min_steps, pilot.evasive_turn_max_steps,
                 "pilot.evasive_turn_min_steps", "pilot.evasive_turn_max_steps");

  SimulatorRecordingOptions& recording = options.simulator;
  recording.sample_interval_min = static_cast<int>(config.GetInt("recording.sample_interval_min"));
  recording.sample_interval_max = static_cast<int>(config.GetInt("recording.sample_interval_max"));
  RequireOrdered(recording.sample_interval_min, recording.sample_interval_max,
                 "recording.sample_interval_min", "recording.sample_interval_max");
  recording.max_scans_per_episode =
      static_cast<int>(config.GetInt("recording.max_scans_per_episode"));
  return options;
}

}  // namespace colav
