#include "train/ppo/checkpoint.h"

#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <map>
#include <optional>
#include <sstream>
#include <string>

#include "src/atomic_file.h"
#include "src/error.h"
#include "tests/src/test_util.h"
#include "train/ppo/config.h"
#include "train/ppo/trainer.h"
#include "train/ppo/update.h"

namespace colav {
namespace {

TEST(PpoCheckpointTest, RoundTripRestoresWeightsOptimiserGeneratorAndCounters) {
  testing_util::TemporaryFolder directory;
  PpoOptions options;
  options.n_envs = 2;
  options.n_steps = 8;
  options.batch_size = 4;
  ActorCriticOptions model_options;
  model_options.seed = 1;
  ActorCritic model(model_options);
  PpoUpdater updater(model, options);
  // Some Adam steps, so that the optimiser state is not trivial.
  for (int step = 0; step < 3; ++step) {
    std::vector<torch::Tensor> gradients;
    for (const auto& p : model->TrainableParameters()) gradients.push_back(torch::randn_like(p));
    updater.optimizer().Step(gradients);
  }
  auto generator = at::make_generator<at::CPUGeneratorImpl>(5);
  RolloutStart start;
  start.counters = {28672, 12, 3, 15, 0.0};
  start.generator_state = generator.get_state();
  start.worlds = {{4, {0.5, -1.0, 1.0, 0.25}}, {7, {}}};
  start.reward_scaling = {{-3.5, 12.25, 64.0001}, {-1.5, 20.0}};
  for (int j = 0; j < kNavigationSize; ++j) start.navigation_moments[j] = {0.5 * j, 2.0 + j, 9.0};
  torch::randn({10}, generator);
  const TrainingCounters counters{30000, 12, 3, 17, 42.5};
  const std::string config_text = R"({"ppo":{"learning_rate":0.0003,"name":"naïve: yes"}})";
  SaveCheckpoint(directory.path(), *model, updater.optimizer(), generator, counters, start,
                 ObservationSettings{}, std::nullopt, config_text, true);
  EXPECT_EQ(RecordedConfig(directory.path()), config_text);
  EXPECT_TRUE(std::filesystem::exists(directory.path() / "policy.pt"));
  EXPECT_TRUE(std::filesystem::exists(directory.path() / "checkpoints" / "policy_30000.pt"));

  model_options.seed = 2;
  ActorCritic restored(model_options);
  PpoUpdater restored_updater(restored, options);
  const RolloutStart loaded =
      LoadCheckpoint(directory.path(), *restored, restored_updater.optimizer());
  // The run resumes at the start of the rollout in progress, with the training time so far.
  EXPECT_EQ(loaded.counters.global_step, 28672);
  EXPECT_EQ(loaded.counters.n_updates, 12);
  EXPECT_EQ(loaded.counters.rollouts, 3);
  EXPECT_EQ(loaded.counters.episodes, 15);
  EXPECT_DOUBLE_EQ(loaded.counters.wall_s, 42.5);
  ASSERT_EQ(loaded.worlds.size(), 2U);
  EXPECT_EQ(loaded.worlds[0].episode, 4U);
  EXPECT_EQ(loaded.worlds[0].actions, start.worlds[0].actions);
  EXPECT_EQ(loaded.worlds[1].episode, 7U);
  EXPECT_TRUE(loaded.worlds[1].actions.empty());
  EXPECT_EQ(loaded.reward_scaling.return_variance.mean, -3.5);
  EXPECT_EQ(loaded.reward_scaling.return_variance.variance, 12.25);
  EXPECT_EQ(loaded.reward_scaling.return_variance.count, 64.0001);
  EXPECT_EQ(loaded.reward_scaling.returns, start.reward_scaling.returns);
  for (int j = 0; j < kNavigationSize; ++j) {
    EXPECT_EQ(loaded.navigation_moments[j].mean, 0.5 * j);
    EXPECT_EQ(loaded.navigation_moments[j].variance, 2.0 + j);
    EXPECT_EQ(loaded.navigation_moments[j].count, 9.0);
  }
  const auto original = model->parameters(), copy = restored->parameters();
  for (std::size_t i = 0; i < original.size(); ++i) EXPECT_TRUE(torch::equal(original[i], copy[i]));
  EXPECT_EQ(restored_updater.optimizer().step_count(), 3);
  for (std::size_t i = 0; i < updater.optimizer().exp_avg().size(); ++i) {
    EXPECT_TRUE(
        torch::equal(updater.optimizer().exp_avg()[i], restored_updater.optimizer().exp_avg()[i]));
    EXPECT_TRUE(torch::equal(updater.optimizer().exp_avg_sq()[i],
                             restored_updater.optimizer().exp_avg_sq()[i]));
  }
  auto restored_generator = at::make_generator<at::CPUGeneratorImpl>(6);
  restored_generator.set_state(loaded.generator_state);
  auto start_generator = at::make_generator<at::CPUGeneratorImpl>(6);
  start_generator.set_state(start.generator_state);
  EXPECT_TRUE(
      torch::equal(torch::randn({4}, start_generator), torch::randn({4}, restored_generator)));
}

TEST(PpoCheckpointTest, TruncatedStateIsAUserError) {
  testing_util::TemporaryFolder directory;
  ActorCritic model(ActorCriticOptions{});
  PpoUpdater updater(model, PpoOptions{});
  auto generator = at::make_generator<at::CPUGeneratorImpl>(5);
  RolloutStart start;
  start.generator_state = generator.get_state();
  SaveCheckpoint(directory.path(), *model, updater.optimizer(), generator, TrainingCounters{},
                 start, ObservationSettings{}, std::nullopt, "{}", false);
  const std::filesystem::path state = TrainingStatePath(directory.path());
  std::filesystem::resize_file(state, std::filesystem::file_size(state) / 2);
  EXPECT_THROW(LoadCheckpoint(directory.path(), *model, updater.optimizer()), UserError);
  EXPECT_THROW(RecordedConfig(directory.path()), UserError);
}

TEST(PpoCheckpointTest, StateFileFromBeforeTheConfigWasRecordedHasNone) {
  testing_util::TemporaryFolder directory;
  torch::serialize::OutputArchive archive;
  archive.write("global_step", torch::tensor(std::int64_t{64}));
  archive.save_to(TrainingStatePath(directory.path()).string());
  EXPECT_EQ(RecordedConfig(directory.path()), std::nullopt);
}

TEST(PpoCheckpointTest, MissingStateIsAUserError) {
  testing_util::TemporaryFolder directory;
  ActorCritic model(ActorCriticOptions{});
  Adam optimizer(model->TrainableParameters(), AdamOptions{});
  EXPECT_THROW(LoadCheckpoint(directory.path(), *model, optimizer), UserError);
  EXPECT_THROW(RecordedConfig(directory.path()), UserError);
}

Config TinyRun(std::int64_t total_steps) {
  Config config = Config::Defaults(PpoRunBinding().Schema());
  for (const auto& [key, value] : std::vector<std::pair<std::string, std::string>>{
           {"ppo.total_steps", std::to_string(total_steps)},
           {"ppo.n_envs", "2"},
           {"ppo.n_steps", "16"},
           {"ppo.batch_size", "8"},
           {"ppo.n_epochs", "1"},
           {"train.checkpoint_interval", "32"},
           {"train.env_threads", "1"}}) {
    config.Set(key, value, "test");
  }
  return config;
}

PpoRunSummary Train(const Config& config, const std::filesystem::path& run_dir, bool resume) {
  return TrainPpo(PpoRunBinding().Read(config), config.ToJson(), run_dir, resume);
}

std::size_t CountLines(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::size_t lines = 0;
  for (std::string line; std::getline(in, line);) ++lines;
  return lines;
}

TEST(PpoCheckpointTest, ResumedRunContinuesFromTheCheckpointStep) {
  testing_util::TemporaryFolder directory;
  const PpoRunSummary first = Train(TinyRun(64), directory.path(), /*resume=*/false);
  EXPECT_TRUE(first.finished);
  EXPECT_EQ(first.counters.global_step, 64);
  EXPECT_EQ(first.counters.rollouts, 2);
  EXPECT_EQ(first.counters.n_updates, 2);
  for (const char* file : {"policy.pt", "training_state.pt", "summary.json", "episodes.csv",
                           "updates.csv", "checkpoints/policy_32.pt", "checkpoints/policy_64.pt"}) {
    EXPECT_TRUE(std::filesystem::exists(directory.path() / file)) << file;
  }
  EXPECT_EQ(CountLines(directory.path() / "updates.csv"), 3U);
  // The state file keeps the configuration it was trained with, every value as resolved.
  const std::optional<std::string> recorded = RecordedConfig(directory.path());
  ASSERT_TRUE(recorded.has_value());
  EXPECT_EQ(Config::FromYamlText(PpoRunBinding().Schema(), *recorded, "state").ToYaml(),
            TinyRun(64).ToYaml());

  const PpoRunSummary second = Train(TinyRun(128), directory.path(), /*resume=*/true);
  EXPECT_EQ(second.session_steps, 64);
  EXPECT_EQ(second.counters.global_step, 128);
  EXPECT_EQ(second.counters.n_updates, 4);
  EXPECT_EQ(CountLines(directory.path() / "updates.csv"), 5U);

  ActorCritic model(PpoRunBinding().Read(TinyRun(128)).model);
  Adam optimizer(model->TrainableParameters(), AdamOptions{});
  LoadCheckpoint(directory.path(), *model, optimizer);
  EXPECT_EQ(optimizer.step_count(), 4 * 32 / 8);  // 4 rollouts of 32 samples, batches of 8
}

std::string ReadFile(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Episodes finish across the resume (max_steps 20, rollouts of 16 steps per world), so the worlds
// are restored mid-episode.
Config ShortEpisodes(std::int64_t total_steps) {
  Config config = TinyRun(total_steps);
  config.Set("env.max_steps", "20", "test");
  return config;
}

TEST(PpoCheckpointTest, ExtendedRunEqualsTheUninterruptedRun) {
  testing_util::TemporaryFolder directory;
  const std::filesystem::path whole = directory.path() / "whole";
  const std::filesystem::path pieces = directory.path() / "pieces";
  std::filesystem::create_directories(whole);
  std::filesystem::create_directories(pieces);
  Train(ShortEpisodes(160), whole, /*resume=*/false);
  Train(ShortEpisodes(64), pieces, /*resume=*/false);
  Train(ShortEpisodes(160), pieces, /*resume=*/true);
  EXPECT_GT(CountLines(whole / "episodes.csv"), 5U);
  EXPECT_EQ(ReadFile(whole / "episodes.csv"), ReadFile(pieces / "episodes.csv"));
  EXPECT_EQ(ReadFile(whole / "policy.pt"), ReadFile(pieces / "policy.pt"));
}

// A finished run resumed trains no further and keeps its files; with another deterministic
// action it exports the policy a run trained with that action from the start exports.
TEST(PpoCheckpointTest, FinishedRunResumedOnlyExportsItsPolicyAgain) {
  testing_util::TemporaryFolder directory;
  const std::filesystem::path run = directory.path() / "run";
  const std::filesystem::path smoothed = directory.path() / "smoothed";
  std::filesystem::create_directories(run);
  std::filesystem::create_directories(smoothed);
  Train(ShortEpisodes(64), run, /*resume=*/false);
  const auto read_all = [&] {
    std::map<std::string, std::string> files;
    for (const char* file : {"policy.pt", "training_state.pt", "summary.json", "episodes.csv",
                             "updates.csv", "checkpoints/policy_64.pt"}) {
      files[file] = ReadFile(run / file);
    }
    return files;
  };
  const std::map<std::string, std::string> trained = read_all();

  const PpoRunSummary again = Train(ShortEpisodes(64), run, /*resume=*/true);
  EXPECT_TRUE(again.finished);
  EXPECT_EQ(again.session_steps, 0);
  EXPECT_EQ(again.counters.global_step, 64);
  EXPECT_EQ(read_all(), trained);

  Config smoothed_config = ShortEpisodes(64);
  smoothed_config.Set("policy.deterministic_thrust_std_scale", "0.25", "test");
  Train(smoothed_config, run, /*resume=*/true);
  Train(smoothed_config, smoothed, /*resume=*/false);
  std::map<std::string, std::string> exported = read_all();
  EXPECT_NE(exported["policy.pt"], trained.at("policy.pt"));
  EXPECT_EQ(exported["policy.pt"], ReadFile(smoothed / "policy.pt"));
  const nlohmann::json before = nlohmann::json::parse(trained.at("summary.json"));
  nlohmann::json after = nlohmann::json::parse(exported["summary.json"]);
  EXPECT_EQ(after["config"]["policy"]["deterministic_thrust_std_scale"], 0.25);
  after["config"] = before["config"];
  EXPECT_EQ(after, before);
  exported.erase("policy.pt");
  exported.erase("summary.json");
  for (const auto& [file, bytes] : exported) EXPECT_EQ(bytes, trained.at(file)) << file;
}

// Trains 160 steps with `key` true in one go (`whole`) and in two sessions of 64 and 160 steps
// (`pieces`), and 160 steps without it (`plain`): for an option whose state runs across the
// rollouts, which a resume must restore.
struct RunsWithOption {
  std::filesystem::path whole, pieces, plain;
};
RunsWithOption TrainWithOptions(const std::vector<std::pair<std::string, std::string>>& settings,
                                const std::filesystem::path& directory) {
  const auto with_key = [&](std::int64_t total_steps) {
    Config config = ShortEpisodes(total_steps);
    for (const auto& [key, value] : settings) config.Set(key, value, "test");
    return config;
  };
  const RunsWithOption runs{directory / "whole", directory / "pieces", directory / "plain"};
  for (const auto& folder : {runs.whole, runs.pieces, runs.plain}) {
    std::filesystem::create_directories(folder);
  }
  Train(with_key(160), runs.whole, /*resume=*/false);
  Train(with_key(64), runs.pieces, /*resume=*/false);
  Train(with_key(160), runs.pieces, /*resume=*/true);
  Train(ShortEpisodes(160), runs.plain, /*resume=*/false);
  // EXPECT_TRUE: a failure would print the binary files otherwise.
  EXPECT_TRUE(ReadFile(runs.whole / "episodes.csv") == ReadFile(runs.pieces / "episodes.csv"));
  EXPECT_TRUE(ReadFile(runs.whole / "policy.pt") == ReadFile(runs.pieces / "policy.pt"));
  return runs;
}

RunsWithOption TrainWithOption(const std::string& key, const std::filesystem::path& directory,
                               const std::string& value = "true") {
  return TrainWithOptions({{key, value}}, directory);
}

// A recurrent policy's states run across the rollouts (the episodes of 20 steps span them).
TEST(PpoCheckpointTest, ExtendedRecurrentRunEqualsTheUninterruptedRun) {
  testing_util::TemporaryFolder directory;
  const RunsWithOption runs = TrainWithOptions(
      {{"policy.recurrent_size", "4"}, {"ppo.sequence_length", "4"}}, directory.path());
  EXPECT_NE(ReadFile(runs.whole / "episodes.csv"), ReadFile(runs.plain / "episodes.csv"));
}

// The memory's training settings reach the trained model: with the critic's loss kept out of the
// GRU, or given a GRU of its own, the actor's GRU learns other weights.
TEST(PpoCheckpointTest, MemoryTrainingSettingsReachTheTrainedMemory) {
  testing_util::TemporaryFolder directory;
  const auto recurrent_run = [&](const std::string& name, const std::string& key) {
    Config config = ShortEpisodes(160);
    config.Set("policy.recurrent_size", "4", "test");
    config.Set("ppo.sequence_length", "4", "test");
    if (key == "policy.value_trains_memory") config.Set(key, "false", "test");
    if (key == "policy.separate_critic_memory") config.Set(key, "true", "test");
    std::filesystem::create_directories(directory.path() / name);
    Train(config, directory.path() / name, /*resume=*/false);
    return torch::jit::load((directory.path() / name / "policy.pt").string());
  };
  const torch::Tensor shared = recurrent_run("shared", "").attr("recurrent_weight_ih").toTensor();
  const torch::Tensor detached = recurrent_run("detached", "policy.value_trains_memory")
                                     .attr("recurrent_weight_ih")
                                     .toTensor();
  const torch::jit::Module separate = recurrent_run("separate", "policy.separate_critic_memory");
  const torch::Tensor separate_actor = separate.attr("recurrent_weight_ih").toTensor();
  EXPECT_FALSE(torch::equal(shared, detached));
  EXPECT_FALSE(torch::equal(shared, separate_actor));
  EXPECT_FALSE(torch::equal(detached, separate_actor));
  EXPECT_FALSE(
      torch::equal(separate.attr("critic_recurrent_weight_ih").toTensor(), separate_actor));
}

// Both memories' states, [n_envs, 2 * recurrent_size], run across the rollouts and the resume.
TEST(PpoCheckpointTest, ExtendedRunWithASeparateCriticMemoryEqualsTheUninterruptedRun) {
  testing_util::TemporaryFolder directory;
  TrainWithOptions({{"policy.recurrent_size", "4"},
                    {"ppo.sequence_length", "4"},
                    {"policy.separate_critic_memory", "true"}},
                   directory.path());
}

// A privileged critic's observations are rebuilt with the worlds at a resume; its policy file
// acts without them and has no value(obs).
TEST(PpoCheckpointTest, ExtendedRunWithAPrivilegedCriticEqualsTheUninterruptedRun) {
  testing_util::TemporaryFolder directory;
  const RunsWithOption runs = TrainWithOption("policy.critic_vessels", directory.path(), "3");
  EXPECT_NE(ReadFile(runs.whole / "updates.csv"), ReadFile(runs.plain / "updates.csv"));
  const torch::jit::Module policy = torch::jit::load((runs.whole / "policy.pt").string());
  EXPECT_FALSE(policy.find_method("value").has_value());
  EXPECT_TRUE(torch::jit::load((runs.plain / "policy.pt").string()).find_method("value"));
}

// Beside a memory, the critic observations travel with the sequences of the minibatches; the
// policy file steps without them and has no step_value.
TEST(PpoCheckpointTest, ExtendedRecurrentRunWithAPrivilegedCriticEqualsTheUninterruptedRun) {
  testing_util::TemporaryFolder directory;
  const RunsWithOption runs = TrainWithOptions({{"policy.recurrent_size", "4"},
                                                {"ppo.sequence_length", "4"},
                                                {"policy.critic_vessels", "3"}},
                                               directory.path());
  const torch::jit::Module policy = torch::jit::load((runs.whole / "policy.pt").string());
  EXPECT_TRUE(policy.find_method("step").has_value());
  EXPECT_FALSE(policy.find_method("step_value").has_value());
}

// The reward scaler's returns run across the rollouts and episodes.
TEST(PpoCheckpointTest, ExtendedRunWithScaledRewardsEqualsTheUninterruptedRun) {
  testing_util::TemporaryFolder directory;
  const RunsWithOption runs = TrainWithOption("ppo.normalize_reward", directory.path());
  // The scaling changes what is learnt, not what the environment reports.
  EXPECT_NE(ReadFile(runs.whole / "updates.csv"), ReadFile(runs.plain / "updates.csv"));
}

// The navigation moments run across the rollouts, and the exported policy carries them.
TEST(PpoCheckpointTest, ExtendedRunWithNormalisedNavigationEqualsTheUninterruptedRun) {
  testing_util::TemporaryFolder directory;
  const RunsWithOption runs = TrainWithOption("ppo.normalize_navigation", directory.path());
  // The policy sees other values, so it acts otherwise.
  EXPECT_NE(ReadFile(runs.whole / "episodes.csv"), ReadFile(runs.plain / "episodes.csv"));
  EXPECT_TRUE(torch::jit::load((runs.whole / "policy.pt").string()).hasattr("navigation_mean"));
  EXPECT_FALSE(torch::jit::load((runs.plain / "policy.pt").string()).hasattr("navigation_mean"));
}

// A resume replays the worlds' recorded actions: squashed ones, here.
TEST(PpoCheckpointTest, ExtendedRunWithSquashedActionsEqualsTheUninterruptedRun) {
  testing_util::TemporaryFolder directory;
  const RunsWithOption runs = TrainWithOption("policy.squash_actions", directory.path());
  EXPECT_NE(ReadFile(runs.whole / "episodes.csv"), ReadFile(runs.plain / "episodes.csv"));
}

// A resume rebuilds the worlds from the run's own training scenario: crowded ones, here.
TEST(PpoCheckpointTest, ExtendedRunInCrowdedWorldsEqualsTheUninterruptedRun) {
  testing_util::TemporaryFolder directory;
  const RunsWithOption runs = TrainWithOption("world.num_static", directory.path(), "40");
  // The range-finder sees the extra circles, and the reward's closeness penalty with it.
  EXPECT_NE(ReadFile(runs.whole / "episodes.csv"), ReadFile(runs.plain / "episodes.csv"));
}

// A curriculum: both worlds play the paper's scenario until the rollout starting at step 96, then
// one crowded with circles.
Config Curriculum(std::int64_t total_steps) {
  Config config = ShortEpisodes(total_steps);
  config.Set("world2.share", "1", "test");
  config.Set("world2.num_static", "40", "test");
  config.Set("world2.from_step", "96", "test");
  return config;
}

// The lines of `text` whose first field (global_step) is at most `last_step`.
std::string RowsUpTo(const std::string& text, std::int64_t last_step) {
  std::istringstream in(text);
  std::string kept, line;
  std::getline(in, line);
  while (std::getline(in, line) && std::stoll(line) <= last_step) kept += line + "\n";
  return kept;
}

// Runs stopped before, at and after the switch resume into the uninterrupted run; until the
// switch it is the plain run, after it another.
TEST(PpoCheckpointTest, CurriculumSwitchesWorldsAtItsStepAndResumesAcrossIt) {
  testing_util::TemporaryFolder directory;
  const std::filesystem::path whole = directory.path() / "whole";
  const std::filesystem::path plain = directory.path() / "plain";
  std::filesystem::create_directories(whole);
  std::filesystem::create_directories(plain);
  Train(Curriculum(160), whole, /*resume=*/false);
  Train(ShortEpisodes(160), plain, /*resume=*/false);
  const std::string episodes = ReadFile(whole / "episodes.csv");
  const std::string plain_episodes = ReadFile(plain / "episodes.csv");
  EXPECT_GT(RowsUpTo(episodes, 96).size(), 0U);
  EXPECT_EQ(RowsUpTo(episodes, 96), RowsUpTo(plain_episodes, 96));
  EXPECT_TRUE(episodes != plain_episodes);
  for (const std::int64_t first_session : {64, 96, 128}) {
    const std::filesystem::path pieces = directory.path() / std::to_string(first_session);
    std::filesystem::create_directories(pieces);
    Train(Curriculum(first_session), pieces, /*resume=*/false);
    Train(Curriculum(160), pieces, /*resume=*/true);
    EXPECT_TRUE(episodes == ReadFile(pieces / "episodes.csv")) << first_session;
    EXPECT_TRUE(ReadFile(whole / "policy.pt") == ReadFile(pieces / "policy.pt")) << first_session;
  }
}

TEST(PpoCheckpointTest, ResumeRefusesAnEpisodesLogWithGarbageRows) {
  testing_util::TemporaryFolder directory;
  Train(ShortEpisodes(64), directory.path(), /*resume=*/false);
  std::string episodes = ReadFile(directory.path() / "episodes.csv");
  episodes.replace(episodes.find('\n') + 1, 5, "x#@!,");
  WriteTextFileAtomically(directory.path() / "episodes.csv", episodes);
  EXPECT_THROW(Train(ShortEpisodes(128), directory.path(), /*resume=*/true), UserError);
}

TEST(PpoCheckpointTest, ResumeAcceptsTheNanExplainedVarianceOfAnUpdate) {
  testing_util::TemporaryFolder directory;
  Train(ShortEpisodes(64), directory.path(), /*resume=*/false);
  std::string updates = ReadFile(directory.path() / "updates.csv");
  std::size_t field = updates.find('\n');  // explained_variance: the 9th field of the first row
  for (int i = 0; i < 8; ++i) field = updates.find(',', field + 1);
  updates.replace(field + 1, updates.find(',', field + 1) - field - 1, "nan");
  WriteTextFileAtomically(directory.path() / "updates.csv", updates);
  EXPECT_NO_THROW(Train(ShortEpisodes(128), directory.path(), /*resume=*/true));
}

TEST(PpoCheckpointTest, ResumeRefusesAnEpisodesLogMissingRows) {
  testing_util::TemporaryFolder directory;
  Train(ShortEpisodes(64), directory.path(), /*resume=*/false);
  WriteTextFileAtomically(directory.path() / "episodes.csv",
                          ReadFile(directory.path() / "episodes.csv").substr(0, 120));
  EXPECT_THROW(Train(ShortEpisodes(128), directory.path(), /*resume=*/true), UserError);
}

}  // namespace
}  // namespace colav
