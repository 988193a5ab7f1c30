// OptionsBinding: the schema's defaults are the options struct's, Read fills the struct from a
// resolved Config, coded fields (enums, lists) round-trip through their text, included bindings
// take the outer defaults, and checks run after reading.
#include "src/options_binding.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "src/error.h"
#include "tests/src/test_util.h"

namespace colav {
namespace {

using testing_util::UserErrorMessage;

enum class Shape { kCircle, kSquare };

struct Inner {
  bool enabled = false;
  double radius = 2.5;
};

struct Options {
  std::int64_t steps = 100;
  int small = 3;
  std::uint64_t seed = 7;
  double rate = 0.25;
  std::string name = "plain";
  std::filesystem::path file = "a/b.txt";
  Shape shape = Shape::kSquare;
  std::vector<int> sizes = {4, 5};
  Inner inner;
};

Shape ParseShape(const std::string& text) {
  if (text == "circle") return Shape::kCircle;
  if (text == "square") return Shape::kSquare;
  throw UserError("unknown shape '" + text + "'");
}

std::string ShapeName(Shape shape) { return shape == Shape::kCircle ? "circle" : "square"; }

std::vector<int> ParseSizes(const std::string& text) {
  std::vector<int> sizes;
  std::stringstream stream(text);
  for (std::string item; std::getline(stream, item, ',');) sizes.push_back(std::stoi(item));
  return sizes;
}

std::string SizesText(const std::vector<int>& sizes) {
  std::string text;
  for (int size : sizes) text += (text.empty() ? "" : ",") + std::to_string(size);
  return text;
}

OptionsBinding<Inner> InnerBinding() {
  OptionsBinding<Inner> binding;
  binding.Bool("inner.enabled", &Inner::enabled, "switch")
      .Number("inner.radius", &Inner::radius, "radius", 0.0)
      .Then([](Inner& inner) {
        if (inner.enabled && inner.radius == 0.0) throw UserError("enabled needs a radius");
      });
  return binding;
}

OptionsBinding<Options> TestBinding(Options defaults = Options()) {
  OptionsBinding<Options> binding(std::move(defaults));
  binding.Number("run.steps", &Options::steps, "steps", 1)
      .Number("run.small", &Options::small, "small", 0, 10)
      .Number("run.seed", &Options::seed, "seed", 0)
      .Number("run.rate", &Options::rate, "rate", 0.0, 1.0)
      .Text("run.name", &Options::name, "name", {"plain", "fancy"})
      .Text("run.file", &Options::file, "file")
      .Coded("run.shape", &Options::shape, "shape", TextCodec<Shape>{ShapeName, ParseShape},
             {"circle", "square"})
      .Coded("run.sizes", &Options::sizes, "sizes",
             TextCodec<std::vector<int>>{SizesText, ParseSizes})
      .Include(InnerBinding(), &Options::inner);
  return binding;
}

bool operator==(const Options& a, const Options& b) {
  return a.steps == b.steps && a.small == b.small && a.seed == b.seed && a.rate == b.rate &&
         a.name == b.name && a.file == b.file && a.shape == b.shape && a.sizes == b.sizes &&
         a.inner.enabled == b.inner.enabled && a.inner.radius == b.inner.radius;
}

TEST(OptionsBindingTest, SchemaDefaultsAreTheStructsDefaultsInDeclarationOrder) {
  const ConfigSchema schema = TestBinding().Schema();
  const std::vector<std::pair<std::string, ConfigValue>> expected = {
      {"run.steps", std::int64_t{100}},
      {"run.small", std::int64_t{3}},
      {"run.seed", std::int64_t{7}},
      {"run.rate", 0.25},
      {"run.name", std::string("plain")},
      {"run.file", std::string("a/b.txt")},
      {"run.shape", std::string("square")},
      {"run.sizes", std::string("4,5")},
      {"inner.enabled", false},
      {"inner.radius", 2.5}};
  ASSERT_EQ(schema.entries().size(), expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i) {
    EXPECT_EQ(schema.entries()[i].key, expected[i].first);
    EXPECT_EQ(schema.entries()[i].default_value, expected[i].second) << expected[i].first;
  }
  EXPECT_EQ(schema.Find("run.small")->max_int, 10);
  EXPECT_EQ(schema.Find("run.rate")->max_double, 1.0);
  EXPECT_EQ(schema.Find("run.shape")->choices, (std::vector<std::string>{"circle", "square"}));
}

TEST(OptionsBindingTest, ReadingTheDefaultsGivesTheDefaultStruct) {
  const OptionsBinding<Options> binding = TestBinding();
  EXPECT_TRUE(binding.Read(Config::Defaults(binding.Schema())) == Options());
}

TEST(OptionsBindingTest, ReadSetsEveryField) {
  const OptionsBinding<Options> binding = TestBinding();
  const Config config = Config::Load(binding.Schema(), "",
                                     {"run.steps=3e6", "run.small=10", "run.seed=42", "run.rate=1",
                                      "run.name=fancy", "run.file=/x/y", "run.shape=circle",
                                      "run.sizes=1,2,3", "inner.enabled=true", "inner.radius=9"});
  Options expected;
  expected.steps = 3'000'000;
  expected.small = 10;
  expected.seed = 42;
  expected.rate = 1.0;
  expected.name = "fancy";
  expected.file = "/x/y";
  expected.shape = Shape::kCircle;
  expected.sizes = {1, 2, 3};
  expected.inner = {true, 9.0};
  EXPECT_TRUE(binding.Read(config) == expected);
}

TEST(OptionsBindingTest, CodedFieldsRoundTripThroughTheirText) {
  Options changed;
  changed.shape = Shape::kCircle;
  changed.sizes = {8, 16, 32};
  const OptionsBinding<Options> binding = TestBinding(changed);
  const ConfigSchema schema = binding.Schema();
  EXPECT_EQ(std::get<std::string>(schema.Find("run.shape")->default_value), "circle");
  EXPECT_EQ(std::get<std::string>(schema.Find("run.sizes")->default_value), "8,16,32");
  EXPECT_TRUE(binding.Read(Config::Defaults(schema)) == changed);
}

TEST(OptionsBindingTest, IncludedKeysTakeTheOuterDefaults) {
  Options defaults;
  defaults.inner.enabled = true;
  const ConfigSchema schema = TestBinding(defaults).Schema();
  EXPECT_EQ(schema.Find("inner.enabled")->default_value, ConfigValue(true));
  EXPECT_EQ(schema.Find("inner.enabled")->doc, "switch");
}

TEST(OptionsBindingTest, ChecksRunAfterReading) {
  const OptionsBinding<Options> binding = TestBinding();
  const Config config =
      Config::Load(binding.Schema(), "", {"inner.enabled=true", "inner.radius=0"});
  EXPECT_EQ(UserErrorMessage([&] { binding.Read(config); }), "enabled needs a radius");
}

TEST(OptionsBindingTest, BadDeclarationsFailAtOnce) {
  OptionsBinding<Options> binding;
  binding.Number("run.steps", &Options::steps, "steps");
  EXPECT_THROW(binding.Number("run.steps", &Options::small, "again"), std::invalid_argument);
  EXPECT_THROW(binding.Number("run.rate", &Options::rate, "default 0.25 outside", 0.5, 1.0),
               std::invalid_argument);
  EXPECT_THROW(binding.Text("run.name", &Options::name, "default not a choice", {"fancy"}),
               std::invalid_argument);
}

}  // namespace
}  // namespace colav
