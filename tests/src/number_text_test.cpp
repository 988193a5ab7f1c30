#include "src/number_text.h"

#include <gtest/gtest.h>

#include <CLI/CLI.hpp>
#include <cstdint>
#include <limits>

#include "src/number_flag.h"
#include "tests/src/test_util.h"

namespace colav {
namespace {

TEST(NumberTextTest, FiniteNumbersOnly) {
  EXPECT_EQ(ParseFiniteNumber("3"), 3.0);
  EXPECT_EQ(ParseFiniteNumber("+4"), 4.0);
  EXPECT_EQ(ParseFiniteNumber("-2.5e-3"), -2.5e-3);
  for (const char* text : {"nan", "NaN", "inf", "-inf", "1e400", "3x", "", " 3", "0x10"}) {
    EXPECT_FALSE(ParseFiniteNumber(text)) << text;
  }
}

TEST(NumberTextTest, WholeNumbersAlsoInExponentNotation) {
  EXPECT_EQ(ParseWholeNumber("-3"), -3);
  EXPECT_EQ(ParseWholeNumber("3e6"), 3'000'000);
  for (const char* text : {"1.5", "1e20", "nan", "abc", "18446744073709551616"}) {
    EXPECT_FALSE(ParseWholeNumber(text)) << text;
  }
}

TEST(NumberTextTest, ProblemsAreShortAndShowInfiniteEnds) {
  EXPECT_EQ(NumberProblem("0.5", 0.0, 1.0), "");
  EXPECT_EQ(NumberProblem("nan", 0.0, 1.0), "expects a number, got 'nan'");
  EXPECT_EQ(NumberProblem("-1", 0.0), "-1 is out of range [0, inf)");
  EXPECT_EQ(WholeNumberProblem("0", 1), "0 is out of range [1, inf)");
  EXPECT_EQ(WholeNumberProblem("2.5", 1, 10), "expects an integer, got '2.5'");
  EXPECT_EQ(RangeText(-std::numeric_limits<double>::infinity(), 5.0), "(-inf, 5]");
}

// Parses `arguments` into the flags of NumberFlagTest and returns the UserError-like message of
// CLI11's failure, or "" when parsing succeeds.
std::string ParseFailure(std::vector<std::string> arguments, double& seconds, int& envs,
                         std::uint64_t& seed) {
  CLI::App app{"test"};
  AddNumberFlag(app, "--seconds", seconds, "time", 0.01, 3600.0);
  AddNumberFlag(app, "--envs", envs, "worlds", 1, 1024);
  AddNumberFlag<std::uint64_t>(app, "--seed", seed, "seed", 0,
                               std::numeric_limits<std::uint64_t>::max());
  arguments.insert(arguments.begin(), "prog");
  std::vector<char*> argv = testing_util::Argv(arguments);
  try {
    app.parse(static_cast<int>(arguments.size()), argv.data());
  } catch (const CLI::ParseError& error) {
    return error.what();
  }
  return "";
}

TEST(NumberFlagTest, ReadsValidValuesAndNamesTheFlagOtherwise) {
  double seconds = 0.0;
  int envs = 0;
  std::uint64_t seed = 0;
  EXPECT_EQ(ParseFailure({"--seconds", "2", "--envs", "1e2", "--seed", "7"}, seconds, envs, seed),
            "");
  EXPECT_EQ(seconds, 2.0);
  EXPECT_EQ(envs, 100);
  EXPECT_EQ(seed, 7U);
  EXPECT_EQ(ParseFailure({"--seconds", "nan"}, seconds, envs, seed),
            "--seconds: expects a number, got 'nan'");
  EXPECT_EQ(ParseFailure({"--envs", "100000000"}, seconds, envs, seed),
            "--envs: 100000000 is out of range [1, 1024]");
  EXPECT_EQ(ParseFailure({"--seed", "-3"}, seconds, envs, seed),
            "--seed: -3 is out of range [0, inf)");
  // A test world's seed is as often above 2^63 - 1 as below (simulate --training-seed).
  EXPECT_EQ(ParseFailure({"--seed", "15812142224346123324"}, seconds, envs, seed), "");
  EXPECT_EQ(seed, 15812142224346123324U);
  EXPECT_EQ(ParseFailure({"--seed", "+18446744073709551615"}, seconds, envs, seed), "");
  EXPECT_EQ(seed, std::numeric_limits<std::uint64_t>::max());
  EXPECT_EQ(ParseFailure({"--seed", "18446744073709551616"}, seconds, envs, seed),
            "--seed: expects an integer, got '18446744073709551616'");
}

}  // namespace
}  // namespace colav
