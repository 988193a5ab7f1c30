// train_ppo refuses an encoder trained on other observations than its configuration expects.
#include "train/ppo/encoder_check.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "models/torchscript_export.h"
#include "src/config.h"
#include "tests/src/test_util.h"

namespace colav {
namespace {

using ::testing::HasSubstr;
using testing_util::UserErrorMessage;

PpoRunOptions ShallowRun(const std::filesystem::path& encoder, ClosenessTransform env_closeness,
                         std::optional<ClosenessTransform> encoder_closeness) {
  PpoRunOptions options;
  options.model.extractor.kind = ExtractorKind::kVaeShallow;
  options.model.extractor.encoder = encoder;
  options.env.closeness = env_closeness;
  options.encoder_closeness = encoder_closeness;
  return options;
}

constexpr ClosenessTransform kLinear = ClosenessTransform::kLinear;
constexpr ClosenessTransform kLog = ClosenessTransform::kLog;
constexpr std::nullopt_t kSameAsEnvironment = std::nullopt;

class EncoderCheckTest : public ::testing::Test {
 protected:
  std::filesystem::path EncoderTrainedOn(ClosenessTransform closeness) {
    const std::filesystem::path path = folder_ / "encoder.pt";
    ExportEncoder(VaeEncoder(VaeEncoderOptions{}), ObservationSettings{closeness}, path);
    return path;
  }
  testing_util::TemporaryFolder folder_;
};

TEST_F(EncoderCheckTest, AnEncoderOfAnotherTransformThanTheEnvironmentsIsRefusedInOneLine) {
  const std::filesystem::path encoder = EncoderTrainedOn(kLinear);
  const std::string message = UserErrorMessage(
      [&] { CheckEncoderObservationSettings(ShallowRun(encoder, kLog, kSameAsEnvironment)); });
  EXPECT_THAT(message, HasSubstr(encoder.string()));
  EXPECT_THAT(message, HasSubstr("trained on closeness linear, extractor.encoder_closeness "
                                 "expects closeness log (env has closeness log)"));
  EXPECT_THAT(message, HasSubstr("set extractor.encoder_closeness=linear"));
  EXPECT_EQ(message.find('\n'), std::string::npos);
}

TEST_F(EncoderCheckTest, AnEncoderOfTheExpectedTransformPasses) {
  const std::filesystem::path encoder = EncoderTrainedOn(kLog);
  EXPECT_NO_THROW(CheckEncoderObservationSettings(ShallowRun(encoder, kLog, kSameAsEnvironment)));
  EXPECT_NO_THROW(CheckEncoderObservationSettings(ShallowRun(encoder, kLinear, kLog)));
  EXPECT_THROW(CheckEncoderObservationSettings(ShallowRun(encoder, kLinear, kSameAsEnvironment)),
               UserError);
  EXPECT_THROW(CheckEncoderObservationSettings(ShallowRun(encoder, kLog, kLinear)), UserError);
}

TEST_F(EncoderCheckTest, TheDefaultsAreThePaperRecipeLinearTrainedEncoderInLogCloseness) {
  const OptionsBinding<PpoRunOptions> binding = PpoRunBinding();
  const PpoRunOptions defaults = binding.Read(Config::Defaults(binding.Schema()));
  EXPECT_EQ(defaults.env.closeness, kLog);
  ASSERT_TRUE(defaults.encoder_closeness.has_value());
  EXPECT_EQ(*defaults.encoder_closeness, kLinear);
  PpoRunOptions paper_recipe = defaults;
  paper_recipe.model.extractor.kind = ExtractorKind::kVaeShallow;
  paper_recipe.model.extractor.encoder = EncoderTrainedOn(kLinear);
  EXPECT_NO_THROW(CheckEncoderObservationSettings(paper_recipe));
  paper_recipe.model.extractor.encoder = EncoderTrainedOn(kLog);
  EXPECT_THROW(CheckEncoderObservationSettings(paper_recipe), UserError);
}

TEST_F(EncoderCheckTest, TheBaselineHasNoEncoderToCheck) {
  PpoRunOptions baseline = ShallowRun(folder_ / "missing.pt", kLog, kLinear);
  baseline.model.extractor.kind = ExtractorKind::kBaseline;
  EXPECT_NO_THROW(CheckEncoderObservationSettings(baseline));
}

}  // namespace
}  // namespace colav
