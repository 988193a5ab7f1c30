// A finished run's recorded settings against those a study asks for
// (eval/study/recorded_settings.h).
#include "eval/study/recorded_settings.h"

#include <gtest/gtest.h>

namespace colav {
namespace {

constexpr const char* kRecorded = R"(ppo:
  total_steps: 3000000
  gamma: 0.999
train:
  env_threads: 1
extractor:
  encoder: "/old/study/vae/shallow/seed_0/encoder.pt"
  head: "fc_mu"
)";

TEST(RecordedSettings, NamesTheFirstSettingThatChanged) {
  const std::string printed = R"(# train_ppo configuration (train_ppo --print-config)
ppo:
  total_steps: 15000000  # environment steps
  gamma: 0.995
train:
  env_threads: 1
)";
  EXPECT_EQ(FirstSettingDifference(kRecorded, printed),
            "ppo.total_steps = 3000000, the study asks for 15000000");
}

TEST(RecordedSettings, PathsThreadsAndNewKeysAreNotCompared) {
  // Copied from another study folder, run with --jobs 1, by a program that has since gained a key.
  const std::string printed = R"(ppo:
  total_steps: 3000000
  gamma: 0.999
  gae_lambda: 0.98
train:
  env_threads: 2
extractor:
  encoder: "/new/study/vae/shallow/seed_0/encoder.pt"
  head: "fc_mu"
)";
  EXPECT_EQ(FirstSettingDifference(kRecorded, printed), std::nullopt);
  EXPECT_EQ(FirstSettingDifference(kRecorded, "extractor:\n  head: reference\n"),
            "extractor.head = fc_mu, the study asks for reference");
  EXPECT_EQ(FirstSettingDifference("ppo: [unclosed", "ppo:\n  gamma: 0.9\n"), std::nullopt);
}

}  // namespace
}  // namespace colav
