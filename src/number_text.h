// Numbers read from text (flags, configuration values, CSV fields): the whole text must be the
// number, and NaN and infinities are not numbers here, so no input can smuggle one into a run.
#pragma once

#include <cstdint>
#include <limits>
#include <optional>
#include <string>

namespace colav {

/// The finite number `text` spells ("3", "-2.5", "1e-3", "+4"), or nullopt (also for "nan",
/// "inf", "1e400", "3x" and "").
std::optional<double> ParseFiniteNumber(const std::string& text);

/// The integer `text` spells, also in exponent notation ("3e6") when the value is a whole number
/// that a double represents exactly; nullopt otherwise ("3.5", "1e20", "abc").
std::optional<std::int64_t> ParseWholeNumber(const std::string& text);

/// Digits only (after an optional '+') as a uint64, over its whole range: the seeds of training
/// and test worlds (DeriveSeed, the seed column of episodes.csv) are as often above 2^63 - 1 as
/// below; nullopt otherwise ("-3", "3e6", "18446744073709551616").
std::optional<std::uint64_t> ParseUnsignedDigits(const std::string& text);

/// "[1, 1000]", "[0, inf)", "(-inf, 5]": a range with unbounded ends, declared as infinities for
/// doubles and the extreme values for integers, shown as infinite.
std::string RangeText(double min, double max);
std::string RangeText(std::int64_t min, std::int64_t max);

/// Why `text` is not a number in [min, max] ("expects a number, got 'nan'", "0 is out of range
/// [1, 4096]"), or "" when it is one.
std::string NumberProblem(const std::string& text,
                          double min = -std::numeric_limits<double>::infinity(),
                          double max = std::numeric_limits<double>::infinity());
/// The same for an integer.
std::string WholeNumberProblem(const std::string& text,
                               std::int64_t min = std::numeric_limits<std::int64_t>::min(),
                               std::int64_t max = std::numeric_limits<std::int64_t>::max());

}  // namespace colav
