// Numeric command-line flags that are not configuration keys (bench_env --seconds, simulate
// --training-seed, plot_training --window), checked like the keys: a finite number, a whole one
// for integer fields, inside a declared range. CLI11's own checks print the range's infinite end
// as a 300-digit number, accept "nan", and wrap "-3" into an unsigned seed.
#pragma once

#include <cstdint>
#include <string>

namespace CLI {
class App;
class Option;
}  // namespace CLI

namespace colav {

/// Adds `flag VALUE` read into `value`; a value outside [min, max], or not a (whole) number, fails
/// the parse with one line: "--envs: 0 is out of range [1, 4096]", "--seconds: expects a
/// number, got 'nan'". Defined for double, int, std::int64_t and std::uint64_t; a std::uint64_t
/// flag reads its whole range (seeds above 2^63 - 1 included).
template <typename Number>
CLI::Option* AddNumberFlag(CLI::App& app, const std::string& flag, Number& value,
                           const std::string& doc, Number min, Number max);

}  // namespace colav
