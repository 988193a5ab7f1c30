#include "eval/study/ensemble_observations.h"

#include <gtest/gtest.h>

#include <fstream>

#include "tests/src/test_util.h"

namespace colav {
namespace {

using testing_util::TemporaryFolder;
using testing_util::UserErrorMessage;

// The env part of train_ppo's resolved configuration.
std::string Resolved(const std::string& closeness, int history, int interval = 5) {
  return "env:\n  closeness: \"" + closeness +
         "\"  # doc\n  scan_history: " + std::to_string(history) +
         "\n  scan_history_interval: " + std::to_string(interval) + "\n";
}

StudySpec EnsembleOf(const std::vector<std::string>& members) {
  StudySpec spec;
  for (const std::string& member : members) {
    PpoConfigSpec config;
    config.name = member;
    spec.ppo_configs.push_back(config);
  }
  spec.ensembles = {{"pair", members, 1, std::nullopt, std::nullopt}};
  return spec;
}

TEST(EnsembleObservationSettings, RunsThatObserveAlikeMayJoin) {
  const TemporaryFolder folder;
  // Without a history the interval does not matter.
  EXPECT_NO_THROW(CheckEnsembleObservationSettings(
      EnsembleOf({"a", "b"}), "s.yaml", folder.path(),
      {{"ppo/a/seed_0", Resolved("log", 0, 5)}, {"ppo/b/seed_0", Resolved("log", 0, 9)}}));
  // A configuration not known yet (no printed configuration, no trained run) is not checked.
  EXPECT_NO_THROW(CheckEnsembleObservationSettings(EnsembleOf({"a", "b"}), "s.yaml", folder.path(),
                                                   {{"ppo/a/seed_0", Resolved("log", 0)}}));
}

TEST(EnsembleObservationSettings, RunsThatObserveDifferentlyAreRefusedBeforeTraining) {
  const TemporaryFolder folder;
  EXPECT_EQ(UserErrorMessage([&] {
              CheckEnsembleObservationSettings(
                  EnsembleOf({"a", "b"}), "s.yaml", folder.path(),
                  {{"ppo/a/seed_0", Resolved("log", 0)}, {"ppo/b/seed_0", Resolved("linear", 0)}});
            }),
            "s.yaml: ensembles.pair: the runs of a (env.closeness log, env.scan_history 0) and of "
            "b (env.closeness linear, env.scan_history 0) observe differently; ensemble_policy "
            "would refuse them");
  // A trained run's config.yaml stands in for the printed configuration.
  std::filesystem::create_directories(folder / "ppo" / "b" / "seed_0");
  std::ofstream(folder / "ppo" / "b" / "seed_0" / "config.yaml") << Resolved("log", 2, 5);
  EXPECT_NE(UserErrorMessage([&] {
              CheckEnsembleObservationSettings(EnsembleOf({"a", "b"}), "s.yaml", folder.path(),
                                               {{"ppo/a/seed_0", Resolved("log", 2, 10)}});
            }).find("env.scan_history_interval 5) observe differently"),
            std::string::npos);
}

}  // namespace
}  // namespace colav
