#include "train/ppo/checkpoint.h"

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include "models/policy_export.h"
#include "src/atomic_file.h"
#include "src/error.h"

namespace colav {
namespace {

constexpr char kModelPrefix[] = "model/";
constexpr char kConfigKey[] = "config";  // the resolved configuration's text, as bytes
constexpr char kOptimizerPrefix[] = "optimizer/";

torch::Tensor ReadTensor(torch::serialize::InputArchive& archive, const std::string& key) {
  torch::Tensor tensor;
  archive.read(key, tensor);
  return tensor;
}

constexpr char kRolloutStartPrefix[] = "rollout_start/";

torch::Tensor ActionsTensor(const std::vector<double>& actions) {
  return torch::tensor(actions, torch::kFloat64);
}

void WriteRolloutStart(torch::serialize::OutputArchive& archive, const RolloutStart& start) {
  const std::string prefix = kRolloutStartPrefix;
  archive.write(prefix + "global_step", torch::tensor(start.counters.global_step));
  archive.write(prefix + "episodes", torch::tensor(start.counters.episodes));
  archive.write(prefix + "generator_state", start.generator_state);
  std::vector<std::int64_t> episodes;
  for (std::size_t i = 0; i < start.worlds.size(); ++i) {
    episodes.push_back(static_cast<std::int64_t>(start.worlds[i].episode));
    archive.write(prefix + "world_actions_" + std::to_string(i),
                  ActionsTensor(start.worlds[i].actions));
  }
  archive.write(prefix + "world_episodes", torch::tensor(episodes, torch::kInt64));
  const RunningVariance& variance = start.reward_scaling.return_variance;
  archive.write(prefix + "reward_scaling_moments",
                torch::tensor({variance.mean, variance.variance, variance.count}, torch::kFloat64));
  archive.write(prefix + "reward_scaling_returns",
                torch::tensor(start.reward_scaling.returns, torch::kFloat64));
  std::vector<double> navigation;  // [kNavigationSize, 3]: mean, variance, count of each value
  for (const RunningVariance& moments : start.navigation_moments) {
    navigation.insert(navigation.end(), {moments.mean, moments.variance, moments.count});
  }
  archive.write(prefix + "navigation_moments",
                torch::tensor(navigation, torch::kFloat64).reshape({kNavigationSize, 3}));
  if (!start.policy_states.empty()) {  // memoryless runs' files stay as they were
    archive.write(prefix + "policy_states", torch::tensor(start.policy_states, torch::kFloat32));
  }
}

// Absent for memoryless policies: empty.
std::vector<float> ReadPolicyStates(torch::serialize::InputArchive& archive) {
  torch::Tensor stored;
  if (!archive.try_read(std::string(kRolloutStartPrefix) + "policy_states", stored)) return {};
  stored = stored.to(torch::kFloat32).contiguous();
  return {stored.data_ptr<float>(), stored.data_ptr<float>() + stored.numel()};
}

// Absent from state files written before navigation normalisation existed: then the initial
// moments, which such a run never used.
NavigationNormalizer::Moments ReadNavigationMoments(torch::serialize::InputArchive& archive) {
  NavigationNormalizer::Moments moments;
  torch::Tensor stored;
  if (!archive.try_read(std::string(kRolloutStartPrefix) + "navigation_moments", stored)) {
    return moments;
  }
  stored = stored.to(torch::kFloat64).contiguous();
  if (stored.numel() != kNavigationSize * 3) {
    throw UserError("navigation moments: " + std::to_string(kNavigationSize * 3) +
                    " values expected");
  }
  const double* values = stored.data_ptr<double>();
  for (int j = 0; j < kNavigationSize; ++j) {
    moments[j] = {values[3 * j], values[3 * j + 1], values[3 * j + 2]};
  }
  return moments;
}

// Absent from state files written before reward scaling existed: then it stays empty.
RewardScalingState ReadRewardScaling(torch::serialize::InputArchive& archive) {
  const std::string prefix = kRolloutStartPrefix;
  RewardScalingState state;
  torch::Tensor moments;
  if (!archive.try_read(prefix + "reward_scaling_moments", moments)) return state;
  moments = moments.to(torch::kFloat64).contiguous();
  if (moments.numel() != 3) throw UserError("reward scaling moments: 3 values expected");
  state.return_variance = {moments[0].item<double>(), moments[1].item<double>(),
                           moments[2].item<double>()};
  const torch::Tensor returns =
      ReadTensor(archive, prefix + "reward_scaling_returns").to(torch::kFloat64).contiguous();
  state.returns.assign(returns.data_ptr<double>(), returns.data_ptr<double>() + returns.numel());
  return state;
}

// The rollout start recorded in `archive`, whose own counters are `counters`.
RolloutStart ReadRolloutStart(torch::serialize::InputArchive& archive,
                              const TrainingCounters& counters, const std::string& file) {
  const std::string prefix = kRolloutStartPrefix;
  torch::Tensor probe;
  if (!archive.try_read(prefix + "world_episodes", probe)) {
    throw UserError(file + " records no world states (an older train_ppo's): it cannot resume " +
                    "exactly; start over with --overwrite");
  }
  RolloutStart start;
  start.counters = counters;
  start.counters.global_step = ReadTensor(archive, prefix + "global_step").item<std::int64_t>();
  start.counters.episodes = ReadTensor(archive, prefix + "episodes").item<std::int64_t>();
  start.generator_state = ReadTensor(archive, prefix + "generator_state");
  const torch::Tensor episodes = probe.to(torch::kInt64).contiguous();
  for (std::int64_t i = 0; i < episodes.numel(); ++i) {
    const torch::Tensor actions = ReadTensor(archive, prefix + "world_actions_" + std::to_string(i))
                                      .to(torch::kFloat64)
                                      .contiguous();
    start.worlds.push_back(
        {static_cast<std::uint64_t>(episodes[i].item<std::int64_t>()),
         {actions.data_ptr<double>(), actions.data_ptr<double>() + actions.numel()}});
  }
  start.reward_scaling = ReadRewardScaling(archive);
  start.navigation_moments = ReadNavigationMoments(archive);
  start.policy_states = ReadPolicyStates(archive);
  const bool navigation_consistent =
      std::all_of(start.navigation_moments.begin(), start.navigation_moments.end(),
                  [](const RunningVariance& m) { return m.variance >= 0.0 && m.count > 0.0; });
  const bool consistent =
      navigation_consistent && start.reward_scaling.return_variance.variance >= 0.0 &&
      start.reward_scaling.return_variance.count > 0.0 && start.counters.global_step >= 0 &&
      start.counters.global_step <= counters.global_step && start.counters.episodes >= 0 &&
      start.counters.episodes <= counters.episodes && (episodes >= 0).all().item<bool>();
  if (!consistent) throw UserError(file + ": inconsistent counters (damaged?)");
  return start;
}

}  // namespace

std::filesystem::path TrainingStatePath(const std::filesystem::path& run_dir) {
  return run_dir / "training_state.pt";
}

void SaveCheckpoint(const std::filesystem::path& run_dir, ActorCriticImpl& model,
                    const Adam& optimizer, torch::Generator& generator,
                    const TrainingCounters& counters, const RolloutStart& rollout_start,
                    const ObservationSettings& settings,
                    const std::optional<NavigationNormalization>& navigation,
                    const std::string& resolved_config, bool keep_policy_copy) {
  ExportPolicy(model, counters.global_step, settings, run_dir / "policy.pt", navigation);
  if (keep_policy_copy) {
    ExportPolicy(
        model, counters.global_step, settings,
        run_dir / "checkpoints" / ("policy_" + std::to_string(counters.global_step) + ".pt"),
        navigation);
  }
  torch::serialize::OutputArchive archive;
  for (const auto& parameter : model.named_parameters()) {
    archive.write(kModelPrefix + parameter.key(), parameter.value().detach());
  }
  torch::serialize::OutputArchive optimizer_archive;
  optimizer.Save(optimizer_archive);
  archive.write("optimizer", optimizer_archive);
  archive.write("generator_state", generator.get_state());
  archive.write("global_step", torch::tensor(counters.global_step));
  archive.write("n_updates", torch::tensor(counters.n_updates));
  archive.write("rollouts", torch::tensor(counters.rollouts));
  archive.write("episodes", torch::tensor(counters.episodes));
  archive.write("wall_s", torch::tensor(counters.wall_s, torch::kFloat64));
  WriteRolloutStart(archive, rollout_start);
  const std::vector<std::uint8_t> config_bytes(resolved_config.begin(), resolved_config.end());
  archive.write(kConfigKey, torch::tensor(config_bytes, torch::kUInt8));
  WriteFileAtomically(TrainingStatePath(run_dir), [&](const std::filesystem::path& temporary) {
    archive.save_to(temporary.string());
  });
}

RolloutStart LoadCheckpoint(const std::filesystem::path& run_dir, ActorCriticImpl& model,
                            Adam& optimizer) {
  const std::filesystem::path path = TrainingStatePath(run_dir);
  const std::string file = "training state '" + path.string() + "'";
  if (!std::filesystem::is_regular_file(path)) throw UserError(file + " does not exist");
  RolloutStart start;
  try {
    torch::serialize::InputArchive archive;
    archive.load_from(path.string());
    torch::NoGradGuard no_grad;
    for (const auto& parameter : model.named_parameters()) {
      const torch::Tensor stored = ReadTensor(archive, kModelPrefix + parameter.key());
      if (stored.sizes() != parameter.value().sizes()) {
        throw UserError(file + ": parameter '" + parameter.key() +
                        "' does not fit the configured model");
      }
      parameter.value().copy_(stored);  // in place: the fast path keeps pointing at it
    }
    torch::serialize::InputArchive optimizer_archive;
    archive.read("optimizer", optimizer_archive);
    optimizer.Load(optimizer_archive);
    TrainingCounters counters;
    counters.global_step = ReadTensor(archive, "global_step").item<std::int64_t>();
    counters.n_updates = ReadTensor(archive, "n_updates").item<std::int64_t>();
    counters.rollouts = ReadTensor(archive, "rollouts").item<std::int64_t>();
    counters.episodes = ReadTensor(archive, "episodes").item<std::int64_t>();
    counters.wall_s = ReadTensor(archive, "wall_s").item<double>();
    start = ReadRolloutStart(archive, counters, file);
  } catch (const UserError&) {
    throw;
  } catch (const std::exception& error) {
    const std::string reason = error.what();
    throw UserError(file + " cannot be read: " + reason.substr(0, reason.find('\n')));
  }
  return start;
}

std::optional<std::string> RecordedConfig(const std::filesystem::path& run_dir) {
  const std::filesystem::path path = TrainingStatePath(run_dir);
  const std::string file = "training state '" + path.string() + "'";
  if (!std::filesystem::is_regular_file(path)) throw UserError(file + " does not exist");
  torch::Tensor bytes;
  try {
    torch::serialize::InputArchive archive;
    archive.load_from(path.string());
    if (!archive.try_read(kConfigKey, bytes)) return std::nullopt;
    bytes = bytes.to(torch::kUInt8).contiguous();
  } catch (const std::exception& error) {
    const std::string reason = error.what();
    throw UserError(file + " cannot be read: " + reason.substr(0, reason.find('\n')));
  }
  const auto* begin = bytes.data_ptr<std::uint8_t>();
  return std::string(begin, begin + bytes.numel());
}

}  // namespace colav
