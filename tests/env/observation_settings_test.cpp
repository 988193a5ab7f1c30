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
  const ObservationSettings history{ClosenessTransform::kLog, 3, 7};
  EXPECT_EQ(ObservationSettingsYaml(history),
            "env:\n  closeness: log\n  scan_history: 3\n  scan_history_interval: 7\n");
  EXPECT_EQ(ParseObservationSettingsYaml(ObservationSettingsYaml(history), "f"), history);
}

TEST(ObservationSettingsTest, TheIntervalMattersOnlyWithAHistory) {
  EXPECT_EQ((ObservationSettings{ClosenessTransform::kLinear, 0, 5}),
            (ObservationSettings{ClosenessTransform::kLinear, 0, 9}));
  EXPECT_NE((ObservationSettings{ClosenessTransform::kLinear, 2, 5}),
            (ObservationSettings{ClosenessTransform::kLinear, 2, 9}));
  EXPECT_NE((ObservationSettings{ClosenessTransform::kLinear, 2, 5}),
            (ObservationSettings{ClosenessTransform::kLinear, 0, 5}));
}

TEST(ObservationSettingsTest, BadTextsNameTheSourceAndTheKey) {
  EXPECT_THAT(
      UserErrorMessage([] { ParseObservationSettingsYaml("env: {closeness: cubic}", "a.yaml"); }),
      HasSubstr("a.yaml: key 'env.closeness' = 'cubic' is not one of: linear, log"));
  EXPECT_THAT(
      UserErrorMessage([] { ParseObservationSettingsYaml("env: {scan_history: 16}", "e.yaml"); }),
      HasSubstr("e.yaml: key 'env.scan_history'"));
  EXPECT_THAT(UserErrorMessage([] {
                ParseObservationSettingsYaml("env: {scan_history_interval: 0}", "f.yaml");
              }),
              HasSubstr("f.yaml: key 'env.scan_history_interval'"));
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
  EXPECT_THAT(ObservationLayoutText({ClosenessTransform::kLog, 2, 5}),
              HasSubstr("obs[:, 186:546] = the scans of 2 earlier steps, 5 steps apart"));
  EXPECT_THAT(DescribeObservationSettings({ClosenessTransform::kLog, 2, 5}),
              HasSubstr("scan history 2 every 5 steps"));
}

TEST(ObservationSettingsTest, AppliesToAnEnvironmentConfigurationAndBack) {
  EnvironmentConfig config;
  config.max_steps = 77;
  const EnvironmentConfig log = WithObservationSettings(config, {ClosenessTransform::kLog});
  EXPECT_EQ(log.closeness, ClosenessTransform::kLog);
  EXPECT_EQ(log.max_steps, 77);
  EXPECT_EQ(ObservationSettingsOf(log), ObservationSettings{ClosenessTransform::kLog});
  const EnvironmentConfig history =
      WithObservationSettings(config, {ClosenessTransform::kLog, 3, 4});
  EXPECT_EQ(history.scan_history, 3);
  EXPECT_EQ(history.scan_history_interval, 4);
  EXPECT_EQ(ObservationSize(history), 6 + 4 * 180);
}

}  // namespace
}  // namespace colav
