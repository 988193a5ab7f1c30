// train_ppo refuses an encoder trained on observations of another meaning than its environment's.
#include "train/ppo/encoder_check.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "models/torchscript_export.h"
#include "tests/src/test_util.h"

namespace colav {
namespace {

using ::testing::HasSubstr;
using testing_util::UserErrorMessage;

PpoRunOptions ShallowRun(const std::filesystem::path& encoder, ClosenessTransform env_closeness) {
  PpoRunOptions options;
  options.model.extractor.kind = ExtractorKind::kVaeShallow;
  options.model.extractor.encoder = encoder;
  options.env.closeness = env_closeness;
  return options;
}

class EncoderCheckTest : public ::testing::Test {
 protected:
  std::filesystem::path EncoderTrainedOn(ClosenessTransform closeness) {
    const std::filesystem::path path = folder_ / "encoder.pt";
    ExportEncoder(VaeEncoder(VaeEncoderOptions{}), ObservationSettings{closeness}, path);
    return path;
  }
  testing_util::TemporaryFolder folder_;
};

TEST_F(EncoderCheckTest, AMismatchedEncoderIsRefusedInOneLine) {
  const std::filesystem::path encoder = EncoderTrainedOn(ClosenessTransform::kLinear);
  const std::string message = UserErrorMessage(
      [&] { CheckEncoderObservationSettings(ShallowRun(encoder, ClosenessTransform::kLog)); });
  EXPECT_THAT(message, HasSubstr(encoder.string()));
  EXPECT_THAT(message, HasSubstr("trained on closeness linear, env has closeness log"));
  EXPECT_THAT(message, HasSubstr("--allow-encoder-mismatch"));
  EXPECT_EQ(message.find('\n'), std::string::npos);
}

TEST_F(EncoderCheckTest, AMatchingEncoderOrAnExplicitOverridePasses) {
  const std::filesystem::path encoder = EncoderTrainedOn(ClosenessTransform::kLog);
  EXPECT_NO_THROW(CheckEncoderObservationSettings(ShallowRun(encoder, ClosenessTransform::kLog)));
  PpoRunOptions mismatched = ShallowRun(encoder, ClosenessTransform::kLinear);
  EXPECT_THROW(CheckEncoderObservationSettings(mismatched), UserError);
  mismatched.allow_encoder_mismatch = true;
  EXPECT_NO_THROW(CheckEncoderObservationSettings(mismatched));
}

TEST_F(EncoderCheckTest, TheBaselineHasNoEncoderToCheck) {
  PpoRunOptions baseline = ShallowRun(folder_ / "missing.pt", ClosenessTransform::kLog);
  baseline.model.extractor.kind = ExtractorKind::kBaseline;
  EXPECT_NO_THROW(CheckEncoderObservationSettings(baseline));
}

}  // namespace
}  // namespace colav
