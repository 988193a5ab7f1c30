#include "train/ppo/trainer.h"

#include <spdlog/spdlog.h>

#include <chrono>
#include <fstream>
#include <optional>
#include <vector>

#include "models/policy_export.h"
#include "models/policy_import.h"
#include "src/atomic_file.h"
#include "src/cli.h"
#include "src/error.h"
#include "src/progress.h"
#include "src/seeding.h"
#include "src/threads/thread_pool.h"
#include "train/ppo/critic_warmup.h"
#include "train/ppo/learning_rate_schedule.h"
#include "train/ppo/rollout.h"
#include "train/ppo/update.h"

namespace colav {
namespace {

using Clock = std::chrono::steady_clock;

ProgressMetrics ProgressMetricsOf(const RollingEpisodeStats& rolling) {
  if (rolling.count == 0) return {};
  return {{"reward", Fixed(rolling.reward, 0)},
          {"progress", Fixed(100.0 * rolling.progress, 1) + "%"},
          {"collisions", Fixed(100.0 * rolling.collision_rate, 0) + "%"}};
}

nlohmann::json SummaryJson(const nlohmann::json& resolved_config, const PpoRunSummary& summary) {
  const RollingEpisodeStats& r = summary.rolling;
  return {{"global_step", summary.counters.global_step},
          {"n_updates", summary.counters.n_updates},
          {"rollouts", summary.counters.rollouts},
          {"episodes", summary.counters.episodes},
          {"finished", summary.finished},
          {"steps_per_s", summary.steps_per_s},
          {"wall_s", summary.wall_s},
          {"total_wall_s", summary.counters.wall_s},
          {"session_steps", summary.session_steps},
          {"time_s",
           {{"rollout", summary.rollout_s},
            {"env_step", summary.env_s},
            {"update", summary.update_s},
            {"checkpoint", summary.checkpoint_s}}},
          {"last_100_episodes",
           {{"count", r.count},
            {"reward", r.reward},
            {"progress", r.progress},
            {"mean_cte", r.mean_cte},
            {"steps", r.steps},
            {"collision_rate", r.collision_rate},
            {"goal_rate", r.goal_rate}}},
          {"config", resolved_config}};
}

// RUN/summary.json if it records a finished run (train_ppo writes one when stopped, too).
std::optional<nlohmann::json> FinishedSummary(const std::filesystem::path& run_dir) {
  std::ifstream in(run_dir / "summary.json");
  nlohmann::json summary = nlohmann::json::parse(in, nullptr, /*allow_exceptions=*/false);
  if (summary.is_discarded() || !summary.is_object() || !summary.value("finished", false)) {
    return std::nullopt;
  }
  return summary;
}

class PpoTrainer {
 public:
  PpoTrainer(const PpoRunOptions& options, nlohmann::json resolved_config,
             std::filesystem::path run_dir, bool resume)
      : resolved_config_(std::move(resolved_config)),
        run_dir_(std::move(run_dir)),
        options_(options.ppo),
        observation_settings_(ObservationSettingsOf(options.env)),
        model_(StartingModel(options, resume)),
        updater_(model_, options_),
        generator_(at::make_generator<at::CPUGeneratorImpl>(DeriveSeed(options_.seed, "ppo"))),
        rollout_start_(resume ? LoadCheckpoint(run_dir_, *model_, updater_.optimizer())
                              : RolloutStart{}),
        counters_(rollout_start_.counters),
        second_worlds_from_step_(options.second_worlds_from_step),
        second_worlds_to_come_(SecondWorldsToCome(options, counters_.global_step)),
        collector_(options.env, WorldScenarios(options, counters_.global_step),
                   ThreadCountOrAllCores(options_.env_threads),
                   DeriveSeed(options_.seed, "worlds", 0),
                   {options_.timeouts_terminal, options_.normalize_reward, options_.gamma,
                    options_.normalize_navigation, options.model.critic_vessels}),
        logs_(run_dir_, resume ? std::optional<KeptLogRows>(KeptRows(rollout_start_.counters))
                               : std::nullopt),
        buffer_(options_.n_steps, options_.n_envs, ObservationSize(options.env),
                static_cast<int>(options.model.state_size()),
                static_cast<int>(options.model.critic_observation_size())),
        finished_summary_(resume && counters_.global_step >= options_.total_steps
                              ? FinishedSummary(run_dir_)
                              : std::nullopt) {
    updater_.set_n_updates(counters_.n_updates);
    if (resume) ContinueFromRolloutStart();
  }

  PpoRunSummary Run() {
    if (finished_summary_) return ExportFinishedRunAgain();
    const Clock::time_point start = Clock::now();
    const std::int64_t first_step = counters_.global_step;
    const double previous_wall_s = counters_.wall_s;
    ProgressOptions progress_options;
    progress_options.initial_done = first_step;
    ProgressBar progress("train_ppo", options_.total_steps, "steps", progress_options);
    std::int64_t next_checkpoint =
        (counters_.global_step / options_.checkpoint_interval + 1) * options_.checkpoint_interval;
    const auto checkpoint = [&](bool keep_policy_copy) {
      const Clock::time_point checkpoint_start = Clock::now();
      counters_.wall_s = previous_wall_s + SecondsSince(start);
      logs_.Flush();
      SaveCheckpoint(run_dir_, *model_, updater_.optimizer(), generator_, counters_, rollout_start_,
                     observation_settings_, collector_.navigation_normalization(),
                     resolved_config_.dump(), keep_policy_copy);
      summary_.checkpoint_s += SecondsSince(checkpoint_start);
    };
    const StopFlag stop_flag;
    bool stopped = false;
    bool within_rollout = false;
    while (counters_.global_step < options_.total_steps && !stopped) {
      MarkRolloutStart();
      within_rollout = true;
      const Clock::time_point rollout_start = Clock::now();
      const torch::Tensor noise =
          torch::randn({options_.n_steps, options_.n_envs, kActionSize}, generator_);
      const bool complete = collector_.Collect(
          updater_.policy(), noise, buffer_, [&](const std::vector<FinishedEpisode>& finished) {
            counters_.global_step += options_.n_envs;
            for (const FinishedEpisode& episode : finished) {
              logs_.AddEpisode(counters_.global_step, episode);
              ++counters_.episodes;
            }
            progress.Update(counters_.global_step, finished.empty()
                                                       ? ProgressMetrics{}
                                                       : ProgressMetricsOf(logs_.Rolling()));
            while (counters_.global_step >= next_checkpoint) {
              checkpoint(options_.keep_checkpoints);
              next_checkpoint += options_.checkpoint_interval;
            }
            return !StopFlag::StopRequested();
          });
      IterationTiming timing;
      timing.rollout_s = SecondsSince(rollout_start);
      summary_.rollout_s += timing.rollout_s;
      if (!complete) break;  // stopped in the middle of the rollout
      const Clock::time_point update_start = Clock::now();
      buffer_.ComputeReturnsAndAdvantages(options_.gamma, options_.gae_lambda);
      SetUpdatePhase();
      updater_.optimizer().set_learning_rate(
          ScheduledLearningRate(options_.learning_rate_schedule, options_.adam.learning_rate,
                                counters_.global_step, options_.total_steps));
      const UpdateStats stats = updater_.Update(buffer_, generator_);
      within_rollout = false;
      timing.update_s = SecondsSince(update_start);
      summary_.update_s += timing.update_s;
      ++counters_.rollouts;
      counters_.n_updates = updater_.n_updates();
      timing.fps = (counters_.global_step - first_step) / SecondsSince(start);
      logs_.AddUpdate(counters_.global_step, stats, timing);
      stopped = StopFlag::StopRequested();
    }
    if (!within_rollout) MarkRolloutStart();
    // A stopped run's checkpoint is only the resume point: the uninterrupted run has no copy of it.
    // A stop within the last rollout leaves global_step past total_steps without its update.
    const bool finished = !within_rollout && counters_.global_step >= options_.total_steps;
    checkpoint(options_.keep_checkpoints && finished);
    progress.Finish();

    summary_.counters = counters_;
    summary_.session_steps = counters_.global_step - first_step;
    summary_.wall_s = SecondsSince(start);
    summary_.steps_per_s = summary_.session_steps / summary_.wall_s;
    summary_.env_s = collector_.env_seconds();
    summary_.finished = finished;
    summary_.rolling = logs_.Rolling();
    WriteTextFileAtomically(run_dir_ / "summary.json",
                            SummaryJson(resolved_config_, summary_).dump(2) + "\n");
    return summary_;
  }

 private:
  // A finished run resumed trains no further and keeps its training files and figures. Only the
  // deterministic action may have changed (train_ppo lets nothing else), so policy.pt is
  // exported again and summary.json records the configuration it was exported with.
  PpoRunSummary ExportFinishedRunAgain() {
    ExportPolicy(*model_, counters_.global_step, observation_settings_, run_dir_ / "policy.pt",
                 collector_.navigation_normalization());
    (*finished_summary_)["config"] = resolved_config_;
    WriteTextFileAtomically(run_dir_ / "summary.json", finished_summary_->dump(2) + "\n");
    spdlog::info("the run had finished: policy.pt exported again, nothing trained");
    summary_.counters = counters_;
    summary_.finished = true;
    summary_.rolling = logs_.Rolling();
    return summary_;
  }

  // The critic warm-up's phase of the update that follows the rollout just collected.
  void SetUpdatePhase() {
    const UpdatePhase phase =
        UpdatePhaseAt(counters_.global_step, buffer_.size(), options_.critic_warmup_steps);
    updater_.set_actor_held(phase == UpdatePhase::kCriticOnly);
    if (phase != UpdatePhase::kActorJoins) return;
    updater_.RestartOptimizer();
    spdlog::info(
        "step {}: the critic's warm-up is over (ppo.critic_warmup_steps {}): the actor "
        "trains too, Adam restarted",
        counters_.global_step, options_.critic_warmup_steps);
  }

  static KeptLogRows KeptRows(const TrainingCounters& counters) {
    return {counters.episodes, counters.rollouts, counters.global_step};
  }

  // Resuming: the sampling generator, the worlds, the reward scaler and the navigation moments as
  // they were when the rollout in progress at the checkpoint started (LoadCheckpoint restored the
  // weights and the optimiser).
  void ContinueFromRolloutStart() {
    generator_.set_state(rollout_start_.generator_state);
    try {
      collector_.RestoreWorlds(rollout_start_.worlds);
      if (!rollout_start_.reward_scaling.returns.empty()) {
        collector_.RestoreRewardScaling(rollout_start_.reward_scaling);
      }
      collector_.RestoreNavigationMoments(rollout_start_.navigation_moments);
      const std::size_t states = rollout_start_.policy_states.size();
      if (states != 0 &&
          states != static_cast<std::size_t>(options_.n_envs) * updater_.policy().state_size()) {
        throw std::invalid_argument(std::to_string(states) + " policy state values");
      }
      collector_.RestorePolicyStates(rollout_start_.policy_states);
    } catch (const std::invalid_argument& error) {
      throw UserError("training state '" + TrainingStatePath(run_dir_).string() +
                      "' does not fit the configured worlds: " + error.what());
    }
  }

  // Everything a resumed run needs besides the weights and optimiser, which do not change until
  // the rollout's update. A curriculum's worlds change first, so that the worlds a checkpoint
  // records are those WorldScenarios gives at its step.
  void MarkRolloutStart() {
    StartSecondWorldsWhenDue();
    rollout_start_.counters = counters_;
    rollout_start_.generator_state = generator_.get_state();
    rollout_start_.worlds = collector_.world_histories();
    rollout_start_.reward_scaling = collector_.reward_scaling();
    rollout_start_.navigation_moments = collector_.navigation_moments();
    rollout_start_.policy_states = collector_.policy_states();
  }

  // A curriculum's second-stage worlds, while a run at `step` has them still to come.
  static std::optional<std::vector<TrainingScenarioConfig>> SecondWorldsToCome(
      const PpoRunOptions& options, std::int64_t step) {
    if (step >= options.second_worlds_from_step) return std::nullopt;
    return WorldScenarios(options, options.second_worlds_from_step);
  }

  void StartSecondWorldsWhenDue() {
    if (!second_worlds_to_come_ || counters_.global_step < second_worlds_from_step_) return;
    collector_.ReplaceWorlds(*second_worlds_to_come_);
    second_worlds_to_come_.reset();
    spdlog::info("step {}: the curriculum's second worlds (world2.*) start", counters_.global_step);
  }

  static ActorCritic StartingModel(const PpoRunOptions& options, bool resume) {
    if (!resume) return InitialPolicy(options);
    ActorCriticOptions model_options = options.model;
    model_options.extractor.encoder.clear();  // the weights come from the checkpoint
    return ActorCritic(model_options);
  }

  nlohmann::json resolved_config_;
  std::filesystem::path run_dir_;
  PpoOptions options_;
  ObservationSettings observation_settings_;  ///< recorded in every policy.pt
  ActorCritic model_;
  PpoUpdater updater_;
  torch::Generator generator_;
  RolloutStart rollout_start_;  ///< of the rollout in progress, or the next one between rollouts
  TrainingCounters counters_;
  std::int64_t second_worlds_from_step_;
  /// Until world2.from_step; never without a curriculum.
  std::optional<std::vector<TrainingScenarioConfig>> second_worlds_to_come_;
  RolloutCollector collector_;
  TrainingLogs logs_;
  RolloutBuffer buffer_;
  PpoRunSummary summary_;
  /// A resumed run's summary.json when the run had already finished.
  std::optional<nlohmann::json> finished_summary_;
};

}  // namespace

ActorCritic InitialPolicy(const PpoRunOptions& options) {
  ActorCritic model(options.model);
  if (!options.init_policy.empty()) {
    LoadPolicyWeights(options.init_policy, ObservationSettingsOf(options.env), *model);
    if (!options.init_keeps_log_std) {
      const torch::NoGradGuard no_grad;
      model->log_std().fill_(options.model.log_std_init);
    }
  }
  return model;
}

PpoRunSummary TrainPpo(const PpoRunOptions& options, const nlohmann::json& resolved_config,
                       const std::filesystem::path& run_dir, bool resume) {
  PpoTrainer trainer(options, resolved_config, run_dir, resume);  // checks what it resumes
  // The baseline has no pre-trained encoder to lock: it always trains.
  const FeatureExtractorOptions& extractor = options.model.extractor;
  const std::string training_mode = extractor.kind == ExtractorKind::kBaseline
                                        ? "trained from scratch"
                                    : extractor.locked ? "locked"
                                                       : "unlocked";
  spdlog::info("{} {} steps (extractor {}, {}) in {}", resume ? "resuming" : "training",
               options.ppo.total_steps, ExtractorKindName(extractor.kind), training_mode,
               run_dir.string());
  if (!resume && !options.init_policy.empty()) {
    spdlog::info("starting from the weights of {}{}", options.init_policy.string(),
                 options.init_keeps_log_std
                     ? ""
                     : fmt::format(", its log std replaced by {} (policy.log_std_init)",
                                   options.model.log_std_init));
  }
  if (options.ppo.std_max > 0.0) {
    spdlog::info("the action std is bounded at {} (ppo.std_max; a wider start is narrowed to it)",
                 options.ppo.std_max);
  }
  if (options.ppo.critic_warmup_steps > 0) {
    spdlog::info("the critic trains alone, the actor held, until step {} (ppo.critic_warmup_steps)",
                 options.ppo.critic_warmup_steps);
  }
  return trainer.Run();
}

}  // namespace colav
