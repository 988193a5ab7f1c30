// The observation settings' YAML form (model files and sidecars) and layout text.
#include "env/observation_settings.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "tests/src/test_util.h"

namespace colav {
namespace {

using ::testing::HasSubstr;
using testing_util::UserErrorMessage;

TEST(ObservationSettingsTest, YamlRoundTripsEverySetting) {
  for (const ClosenessTransform closeness :
       {ClosenessTransform::kLinear, ClosenessTransform::kLog}) {
    const ObservationSettings settings{closeness};
    EXPECT_EQ(ParseObservationSettingsYaml(ObservationSettingsYaml(settings), "f"), settings);
  }
  EXPECT_EQ(ObservationSettingsYaml(ObservationSettings{ClosenessTransform::kLog}),
            "env:\n  closeness: log\n");
}

TEST(ObservationSettingsTest, BadTextsNameTheSourceAndTheKey) {
  EXPECT_THAT(
      UserErrorMessage([] { ParseObservationSettingsYaml("env: {closeness: cubic}", "a.yaml"); }),
      HasSubstr("a.yaml: env.closeness: unknown closeness transform 'cubic'"));
  EXPECT_THAT(
      UserErrorMessage([] { ParseObservationSettingsYaml("env: {max_steps: 5}", "b.yaml"); }),
      HasSubstr("b.yaml: env.max_steps is not an observation setting"));
  EXPECT_THAT(UserErrorMessage([] { ParseObservationSettingsYaml("closeness: log", "c.yaml"); }),
              HasSubstr("c.yaml: observation settings must be one map 'env:'"));
  EXPECT_THAT(UserErrorMessage([] { ParseObservationSettingsYaml("env: [", "d.yaml"); }),
              HasSubstr("d.yaml: malformed"));
}

TEST(ObservationSettingsTest, TheLayoutTextGivesTheClosenessFormulaInUse) {
  EXPECT_THAT(ObservationLayoutText({ClosenessTransform::kLinear}),
              HasSubstr("closeness 1 - d/150"));
  EXPECT_THAT(ObservationLayoutText({ClosenessTransform::kLog}),
              HasSubstr("closeness 1 - ln(1+d)/ln(151)"));
}

TEST(ObservationSettingsTest, AppliesToAnEnvironmentConfigurationAndBack) {
  EnvironmentConfig config;
  config.max_steps = 77;
  const EnvironmentConfig log = WithObservationSettings(config, {ClosenessTransform::kLog});
  EXPECT_EQ(log.closeness, ClosenessTransform::kLog);
  EXPECT_EQ(log.max_steps, 77);
  EXPECT_EQ(ObservationSettingsOf(log), ObservationSettings{ClosenessTransform::kLog});
}

}  // namespace
}  // namespace colav
