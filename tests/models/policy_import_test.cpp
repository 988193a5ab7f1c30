#include "models/policy_import.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <string>
#include <vector>

#include "models/policy_export.h"
#include "tests/src/test_util.h"

namespace colav {
namespace {

using testing::HasSubstr;
using testing_util::UserErrorMessage;

// A small recurrent baseline policy; `seed` draws its weights.
ActorCriticOptions SmallPolicy(std::uint64_t seed) {
  ActorCriticOptions options;
  options.hidden_sizes = {8, 4};
  options.recurrent_size = 3;
  options.seed = seed;
  return options;
}

// Copies of the parameters of `model`, by name.
std::map<std::string, torch::Tensor> WeightsOf(ActorCriticImpl& model) {
  std::map<std::string, torch::Tensor> weights;
  for (const auto& parameter : model.named_parameters()) {
    weights[parameter.key()] = parameter.value().detach().clone();
  }
  return weights;
}

// Two sets of weights with the same names, each equal to the other's, bit for bit.
bool SameWeights(const std::map<std::string, torch::Tensor>& a,
                 const std::map<std::string, torch::Tensor>& b) {
  if (a.size() != b.size()) return false;
  for (const auto& [name, tensor] : a) {
    const auto other = b.find(name);
    if (other == b.end() || !torch::equal(tensor, other->second)) return false;
  }
  return true;
}

class PolicyImportTest : public testing::Test {
 protected:
  // `options` exported (with `settings`) to a file, which it returns.
  std::filesystem::path Exported(const ActorCriticOptions& options,
                                 const ObservationSettings& settings = {},
                                 const std::optional<NavigationNormalization>& navigation = {}) {
    ActorCritic model(options);
    const std::filesystem::path path = folder_.path() / "policy.pt";
    ExportPolicy(*model, 7, settings, path, navigation);
    return path;
  }

  // The message of loading `path` into a fresh policy of `options` (SmallPolicy(2) unless
  // given), which must stay as it was.
  std::string RefusalOf(const std::filesystem::path& path,
                        ActorCriticOptions options = SmallPolicy(2),
                        const ObservationSettings& settings = {}) {
    ActorCritic model(options);
    const std::map<std::string, torch::Tensor> before = WeightsOf(*model);
    const std::string message =
        UserErrorMessage([&] { LoadPolicyWeights(path, settings, *model); });
    EXPECT_TRUE(SameWeights(WeightsOf(*model), before));
    return message;
  }

  testing_util::TemporaryFolder folder_;
};

TEST_F(PolicyImportTest, LoadsEveryWeightOfThePolicyItWasExportedFrom) {
  ActorCritic exported(SmallPolicy(1));
  ActorCritic loaded(SmallPolicy(2));
  ASSERT_FALSE(SameWeights(WeightsOf(*exported), WeightsOf(*loaded)));  // different seeds
  const std::vector<torch::Tensor> tensors = loaded->parameters();
  const std::filesystem::path path = folder_.path() / "policy.pt";
  ExportPolicy(*exported, 7, ObservationSettings{}, path);
  LoadPolicyWeights(path, ObservationSettings{}, *loaded);
  EXPECT_TRUE(SameWeights(WeightsOf(*exported), WeightsOf(*loaded)));
  // Loaded in place: the model's tensors (which the optimiser and fast passes hold) are the same.
  const std::vector<torch::Tensor> after = loaded->parameters();
  ASSERT_EQ(after.size(), tensors.size());
  for (std::size_t i = 0; i < after.size(); ++i) {
    EXPECT_TRUE(after[i].is_same(tensors[i]));
  }
}

TEST_F(PolicyImportTest, AFileOfOtherLayerSizesIsRefusedNamingTheParameter) {
  ActorCriticOptions wider = SmallPolicy(1);
  wider.hidden_sizes = {16, 4};
  const std::string message = RefusalOf(Exported(wider));
  EXPECT_THAT(message, HasSubstr("mlp_extractor_policy_net_0_weight"));
  EXPECT_THAT(message, HasSubstr("[16, 21]"));
  EXPECT_THAT(message, HasSubstr("[8, 21]"));
}

TEST_F(PolicyImportTest, AFileWithParametersTheRunHasNotIsRefused) {
  ActorCriticOptions critic_memory = SmallPolicy(1);
  critic_memory.separate_critic_memory = true;
  EXPECT_THAT(RefusalOf(Exported(critic_memory)), HasSubstr("this run's policy"));
}

TEST_F(PolicyImportTest, AFileMissingAParameterIsRefusedNamingIt) {
  ActorCriticOptions memoryless = SmallPolicy(1);
  memoryless.recurrent_size = 0;
  ActorCriticOptions run = SmallPolicy(2);
  EXPECT_THAT(RefusalOf(Exported(memoryless), run), HasSubstr("no parameter 'recurrent_"));
}

TEST_F(PolicyImportTest, AFileOfAnotherExtractorIsRefused) {
  ActorCriticOptions vae = SmallPolicy(2);
  vae.extractor.kind = ExtractorKind::kVaeShallow;  // no encoder file: its own random weights
  EXPECT_THAT(RefusalOf(Exported(SmallPolicy(1)), vae),
              HasSubstr("not a policy of extractor vae-shallow"));
}

TEST_F(PolicyImportTest, AFileOfOtherObservationsIsRefused) {
  ObservationSettings log_closeness;
  log_closeness.closeness = ClosenessTransform::kLog;
  EXPECT_THAT(RefusalOf(Exported(SmallPolicy(1), log_closeness)), HasSubstr("unlike this run's"));
}

TEST_F(PolicyImportTest, AFileNormalisingItsNavigationValuesIsRefused) {
  NavigationNormalization navigation;
  navigation.mean.fill(0.0f);
  navigation.spread.fill(1.0f);
  EXPECT_THAT(RefusalOf(Exported(SmallPolicy(1), {}, navigation)),
              HasSubstr("normalises its navigation values"));
}

TEST_F(PolicyImportTest, AMissingOrForeignFileIsRefusedNamingIt) {
  const std::filesystem::path missing = folder_.path() / "none.pt";
  EXPECT_THAT(RefusalOf(missing),
              HasSubstr("policy file '" + missing.string() + "' does not exist"));
  const std::filesystem::path text = folder_.path() / "text.pt";
  std::ofstream(text) << "not a model\n";
  EXPECT_THAT(RefusalOf(text), HasSubstr("is not a TorchScript file"));
}

}  // namespace
}  // namespace colav
