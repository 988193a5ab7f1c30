#include "src/config.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "tests/src/test_util.h"

namespace colav {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;
using testing_util::TemporaryFolder;
using testing_util::UserErrorMessage;
using testing_util::WriteFile;

ConfigSchema TestSchema() {
  ConfigSchema schema;
  schema.AddDouble("ppo.learning_rate", 2e-4, "Adam learning rate", 0.0, 1.0)
      .AddInt("ppo.n_epochs", 4, "epochs per update", 1, 1000)
      .AddInt("ppo.total_steps", 3000000, "environment steps", 1)
      .AddBool("ppo.normalize_advantage", true, "normalise advantages per minibatch")
      .AddString("vae.model", "shallow", "encoder architecture", {"shallow", "deep"})
      .AddString("run.name", "baseline", "free-form run name")
      .AddDouble("seed_offset", 0.5, "a top-level key");
  return schema;
}

class ConfigFileTest : public ::testing::Test {
 protected:
  // Writes `yaml` as config.yaml in the temporary folder and returns its path.
  std::string WriteYaml(const std::string& yaml) {
    const std::string path = (folder_ / "config.yaml").string();
    WriteFile(path, yaml);
    return path;
  }

  std::string ErrorOfYaml(const std::string& yaml) {
    const std::string path = WriteYaml(yaml);
    return UserErrorMessage([&] { Config::Load(TestSchema(), path); });
  }

  TemporaryFolder folder_;
};

TEST(ConfigTest, DefaultsAreTheDeclaredValues) {
  const Config config = Config::Defaults(TestSchema());
  EXPECT_DOUBLE_EQ(config.GetDouble("ppo.learning_rate"), 2e-4);
  EXPECT_EQ(config.GetInt("ppo.n_epochs"), 4);
  EXPECT_TRUE(config.GetBool("ppo.normalize_advantage"));
  EXPECT_EQ(config.GetString("vae.model"), "shallow");
}

TEST_F(ConfigFileTest, OverridesBeatFileBeatsDefaults) {
  const std::string path = WriteYaml(
      "ppo:\n"
      "  learning_rate: 1.0e-3\n"
      "  n_epochs: 8\n"
      "vae:\n"
      "  model: deep\n");
  const Config config = Config::Load(TestSchema(), path, {"ppo.n_epochs=10", "vae.model=shallow"});
  EXPECT_DOUBLE_EQ(config.GetDouble("ppo.learning_rate"), 1e-3);  // file
  EXPECT_EQ(config.GetInt("ppo.n_epochs"), 10);                   // override
  EXPECT_EQ(config.GetString("vae.model"), "shallow");            // override
  EXPECT_EQ(config.GetInt("ppo.total_steps"), 3000000);           // default
}

TEST(ConfigTest, LaterOverridesBeatEarlierOnes) {
  const Config config = Config::Load(TestSchema(), "", {"ppo.n_epochs=2", "ppo.n_epochs = 3"});
  EXPECT_EQ(config.GetInt("ppo.n_epochs"), 3);
}

TEST_F(ConfigFileTest, AcceptsDottedKeysInTheFile) {
  const Config config = Config::Load(TestSchema(), WriteYaml("ppo.n_epochs: 7\nseed_offset: 2\n"));
  EXPECT_EQ(config.GetInt("ppo.n_epochs"), 7);
  EXPECT_DOUBLE_EQ(config.GetDouble("seed_offset"), 2.0);
}

TEST_F(ConfigFileTest, EmptyFileKeepsDefaults) {
  const Config config = Config::Load(TestSchema(), WriteYaml(""));
  EXPECT_EQ(config.GetInt("ppo.n_epochs"), 4);
}

TEST_F(ConfigFileTest, UnknownKeyNamesFileKeyAndSuggestion) {
  const std::string path = WriteYaml("ppo:\n  learnig_rate: 0.1\n");
  EXPECT_EQ(UserErrorMessage([&] { Config::Load(TestSchema(), path); }),
            path + ": unknown key 'ppo.learnig_rate' (did you mean 'ppo.learning_rate'?)");
}

TEST_F(ConfigFileTest, UnknownKeyWithoutNearMatchHasNoSuggestion) {
  EXPECT_EQ(ErrorOfYaml("completely_different: 1\n"),
            folder_.path().string() + "/config.yaml: unknown key 'completely_different'");
}

TEST_F(ConfigFileTest, WrongTypeNamesFileKeyAndValue) {
  const std::string path = WriteYaml("ppo:\n  learning_rate: fast\n");
  EXPECT_EQ(UserErrorMessage([&] { Config::Load(TestSchema(), path); }),
            path + ": key 'ppo.learning_rate' expects a number, got 'fast'");
}

TEST_F(ConfigFileTest, ListOrMapWhereAValueBelongsIsRejected) {
  EXPECT_THAT(ErrorOfYaml("ppo:\n  n_epochs: [1, 2]\n"),
              HasSubstr("key 'ppo.n_epochs' expects an integer, got a list"));
  EXPECT_THAT(ErrorOfYaml("ppo:\n  n_epochs: {a: 1}\n"),
              HasSubstr("key 'ppo.n_epochs' expects an integer, got a map"));
  EXPECT_THAT(ErrorOfYaml("ppo:\n  n_epochs:\n"),
              HasSubstr("key 'ppo.n_epochs' expects an integer, got an empty value"));
}

TEST_F(ConfigFileTest, TopLevelMustBeAMap) {
  EXPECT_THAT(ErrorOfYaml("- 1\n- 2\n"), HasSubstr("expected a map of keys at the top level"));
}

TEST_F(ConfigFileTest, MalformedYamlNamesFileAndLine) {
  const std::string path = WriteYaml("ppo:\n  n_epochs: 3\n  learning_rate: [1, 2\n");
  const std::string message = UserErrorMessage([&] { Config::Load(TestSchema(), path); });
  EXPECT_THAT(message, HasSubstr(path + ": malformed YAML at line "));
  EXPECT_THAT(message, Not(HasSubstr("\n")));
}

TEST(ConfigTest, MissingFileIsNamed) {
  EXPECT_EQ(UserErrorMessage([] { Config::Load(TestSchema(), "no/such/config.yaml"); }),
            "no/such/config.yaml: no such file");
}

TEST(ConfigTest, OutOfRangeOverrideShowsRange) {
  EXPECT_EQ(UserErrorMessage([] { Config::Load(TestSchema(), "", {"ppo.n_epochs=0"}); }),
            "--set: key 'ppo.n_epochs' = 0 is out of range [1, 1000]");
  EXPECT_EQ(UserErrorMessage([] { Config::Load(TestSchema(), "", {"ppo.learning_rate=2"}); }),
            "--set: key 'ppo.learning_rate' = 2.0 is out of range [0, 1]");
}

TEST(ConfigTest, OverrideNeedsAnEqualsSign) {
  EXPECT_EQ(UserErrorMessage([] { Config::Load(TestSchema(), "", {"ppo.n_epochs"}); }),
            "--set: expected key=value, got 'ppo.n_epochs'");
}

TEST(ConfigTest, UnknownOverrideKeySuggestsTheKeyWithItsPrefix) {
  EXPECT_EQ(UserErrorMessage([] { Config::Load(TestSchema(), "", {"n_epochs=3"}); }),
            "--set: unknown key 'n_epochs' (did you mean 'ppo.n_epochs'?)");
}

TEST(ConfigTest, IntegerKeysAcceptWholeNumbersOnly) {
  Config config = Config::Defaults(TestSchema());
  config.Set("ppo.total_steps", "3e6", "--steps");
  EXPECT_EQ(config.GetInt("ppo.total_steps"), 3000000);
  config.Set("ppo.n_epochs", "+12", "--epochs");
  EXPECT_EQ(config.GetInt("ppo.n_epochs"), 12);
  EXPECT_EQ(UserErrorMessage([&] { config.Set("ppo.n_epochs", "3.5", "--epochs"); }),
            "--epochs: key 'ppo.n_epochs' expects an integer, got '3.5'");
  EXPECT_EQ(UserErrorMessage([&] { config.Set("ppo.n_epochs", "", "--epochs"); }),
            "--epochs: key 'ppo.n_epochs' expects an integer, got ''");
}

TEST(ConfigTest, DoubleKeysAcceptIntegersAndRejectNonFiniteValues) {
  Config config = Config::Defaults(TestSchema());
  config.Set("seed_offset", "3", "--set");
  EXPECT_DOUBLE_EQ(config.GetDouble("seed_offset"), 3.0);
  config.Set("seed_offset", "-.5e1", "--set");
  EXPECT_DOUBLE_EQ(config.GetDouble("seed_offset"), -5.0);
  EXPECT_THAT(UserErrorMessage([&] { config.Set("seed_offset", "nan", "--set"); }),
              HasSubstr("expects a number, got 'nan'"));
  EXPECT_THAT(UserErrorMessage([&] { config.Set("seed_offset", "1.5x", "--set"); }),
              HasSubstr("expects a number, got '1.5x'"));
}

TEST(ConfigTest, BoolKeysAcceptTrueAndFalseOnly) {
  Config config = Config::Defaults(TestSchema());
  config.Set("ppo.normalize_advantage", "false", "--set");
  EXPECT_FALSE(config.GetBool("ppo.normalize_advantage"));
  EXPECT_EQ(UserErrorMessage([&] { config.Set("ppo.normalize_advantage", "yes", "--set"); }),
            "--set: key 'ppo.normalize_advantage' expects true or false, got 'yes'");
}

TEST(ConfigTest, StringChoicesAreEnforced) {
  Config config = Config::Defaults(TestSchema());
  config.Set("vae.model", "deep", "--model");
  EXPECT_EQ(config.GetString("vae.model"), "deep");
  EXPECT_EQ(UserErrorMessage([&] { config.Set("vae.model", "medium", "--model"); }),
            "--model: key 'vae.model' = 'medium' is not one of: shallow, deep");
  config.Set("run.name", "anything at all = fine", "--set");
  EXPECT_EQ(config.GetString("run.name"), "anything at all = fine");
}

TEST(ConfigTest, GettersRejectUndeclaredKeysAndWrongTypes) {
  const Config config = Config::Defaults(TestSchema());
  EXPECT_THROW(config.GetDouble("ppo.nope"), std::invalid_argument);
  EXPECT_THROW(config.GetDouble("ppo.n_epochs"), std::invalid_argument);
  EXPECT_THROW(config.GetString("ppo.normalize_advantage"), std::invalid_argument);
}

TEST(ConfigSchemaTest, RejectsBadDeclarations) {
  ConfigSchema schema;
  schema.AddInt("a.b", 1, "doc", 0, 10);
  EXPECT_THROW(schema.AddInt("a.b", 1, "declared twice"), std::invalid_argument);
  EXPECT_THROW(schema.AddInt("a", 1, "a is a group of keys"), std::invalid_argument);
  EXPECT_THROW(schema.AddInt("a.b.c", 1, "a.b is a key"), std::invalid_argument);
  EXPECT_THROW(schema.AddInt("c", 11, "default out of range", 0, 10), std::invalid_argument);
  EXPECT_THROW(schema.AddString("d", "x", "default not a choice", {"y"}), std::invalid_argument);
  EXPECT_THROW(schema.AddBool("bad..key", true, "empty part"), std::invalid_argument);
  EXPECT_THROW(schema.AddBool("bad key", true, "space"), std::invalid_argument);
}

TEST(ConfigSchemaTest, DescribeListsEveryKeyWithDefaultAndRange) {
  const std::string text = TestSchema().Describe();
  EXPECT_THAT(text, HasSubstr("ppo.n_epochs = 4 (int in [1, 1000]) epochs per update"));
  EXPECT_THAT(text,
              HasSubstr("vae.model = 'shallow' (string: shallow, deep) encoder architecture"));
  EXPECT_THAT(text, HasSubstr("ppo.learning_rate = 0.0002 (double in [0, 1]) Adam learning rate"));
}

TEST_F(ConfigFileTest, ToYamlRoundTripsEveryValue) {
  Config original = Config::Load(TestSchema(), "",
                                 {"ppo.learning_rate=1e-5", "run.name=true", "ppo.n_epochs=9",
                                  "ppo.normalize_advantage=false", "seed_offset=3"});
  const std::string yaml = original.ToYaml();
  EXPECT_THAT(yaml, HasSubstr("learning_rate: 1.0e-05"));  // a float for YAML 1.1 readers too
  EXPECT_THAT(yaml, HasSubstr("name: \"true\""));          // a string stays a string
  EXPECT_THAT(yaml, HasSubstr("seed_offset: 3.0"));
  const Config reloaded = Config::Load(TestSchema(), WriteYaml(yaml));
  EXPECT_EQ(reloaded.ToJson(), original.ToJson());
  EXPECT_EQ(reloaded.GetString("run.name"), "true");
}

TEST(ConfigTest, FromYamlTextReadsToJsonAndToYamlBack) {
  const Config original = Config::Load(TestSchema(), "",
                                       {"ppo.learning_rate=1e-5", "run.name=true", "seed_offset=3",
                                        "ppo.normalize_advantage=false", "vae.model=deep"});
  const Config from_json = Config::FromYamlText(TestSchema(), original.ToJson().dump(), "state");
  EXPECT_EQ(from_json.ToJson(), original.ToJson());
  EXPECT_EQ(from_json.GetString("run.name"), "true");
  EXPECT_EQ(Config::FromYamlText(TestSchema(), original.ToYaml(), "state").ToJson(),
            original.ToJson());
  // Keys the text lacks keep their defaults (a record from before a key was declared).
  EXPECT_EQ(Config::FromYamlText(TestSchema(), R"({"ppo": {"n_epochs": 7}})", "state")
                .GetDouble("ppo.learning_rate"),
            2e-4);
}

TEST(ConfigTest, FromYamlTextErrorsNameTheOrigin) {
  EXPECT_EQ(UserErrorMessage([] {
              Config::FromYamlText(TestSchema(), "{ppo: [", "run/state.pt");
            }).rfind("run/state.pt: malformed YAML at line 1", 0),
            0U);
  EXPECT_THAT(UserErrorMessage([] {
                Config::FromYamlText(TestSchema(), R"({"ppo": {"n_epoch": 7}})", "run/state.pt");
              }),
              HasSubstr("run/state.pt: unknown key 'ppo.n_epoch'"));
}

TEST(ConfigTest, ToYamlKeepsSchemaOrderAndNesting) {
  const std::string yaml = Config::Defaults(TestSchema()).ToYaml();
  EXPECT_LT(yaml.find("ppo:"), yaml.find("vae:"));
  EXPECT_LT(yaml.find("vae:"), yaml.find("run:"));
  EXPECT_THAT(yaml, HasSubstr("ppo:\n  learning_rate: 0.0002\n  n_epochs: 4\n"));
}

TEST_F(ConfigFileTest, ToDocumentedYamlCommentsEveryKeyAndReadsBackAsToYaml) {
  const Config original = Config::Load(TestSchema(), "", {"ppo.n_epochs=9", "run.name=x"});
  const std::string yaml = original.ToDocumentedYaml();
  EXPECT_THAT(yaml, HasSubstr("ppo:\n  learning_rate: 0.0002  # Adam learning rate\n"));
  EXPECT_THAT(yaml, HasSubstr("seed_offset: 0.5  # a top-level key\n"));
  EXPECT_EQ(Config::Load(TestSchema(), WriteYaml(yaml)).ToYaml(), original.ToYaml());
  EXPECT_EQ(Config::Defaults(ConfigSchema()).ToDocumentedYaml(), "");
}

TEST(ConfigTest, ToJsonNestsKeysWithTheirTypes) {
  const nlohmann::json json = Config::Defaults(TestSchema()).ToJson();
  EXPECT_EQ(json["ppo"]["n_epochs"], 4);
  EXPECT_TRUE(json["ppo"]["n_epochs"].is_number_integer());
  EXPECT_TRUE(json["ppo"]["learning_rate"].is_number_float());
  EXPECT_EQ(json["vae"]["model"], "shallow");
  EXPECT_EQ(json["ppo"]["normalize_advantage"], true);
  EXPECT_DOUBLE_EQ(json["seed_offset"].get<double>(), 0.5);
}

}  // namespace
}  // namespace colav
