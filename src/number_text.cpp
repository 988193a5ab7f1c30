#include "src/number_text.h"

#include <fmt/format.h>

#include <charconv>
#include <cmath>

namespace colav {
namespace {

template <typename Number>
std::string RangeTextOf(Number min, Number max) {
  using Limits = std::numeric_limits<Number>;
  constexpr Number kLowest = Limits::has_infinity ? -Limits::infinity() : Limits::lowest();
  constexpr Number kHighest = Limits::has_infinity ? Limits::infinity() : Limits::max();
  return (min == kLowest ? std::string("(-inf") : fmt::format("[{}", min)) + ", " +
         (max == kHighest ? std::string("inf)") : fmt::format("{}]", max));
}

template <typename Number>
std::string Problem(const std::string& text, const std::optional<Number>& value, Number min,
                    Number max, const char* expectation) {
  if (!value) return std::string("expects ") + expectation + ", got '" + text + "'";
  if (*value < min || *value > max) return text + " is out of range " + RangeText(min, max);
  return "";
}

// `text` as a Number when std::from_chars reads all of it, after an optional '+' (which from_chars
// rejects).
template <typename Number>
std::optional<Number> ReadAll(const std::string& text) {
  const std::size_t start = !text.empty() && text[0] == '+' ? 1 : 0;
  const char* end = text.data() + text.size();
  Number value{};
  const auto result = std::from_chars(text.data() + start, end, value);
  if (result.ec != std::errc() || result.ptr != end) return std::nullopt;
  return value;
}

}  // namespace

std::optional<double> ParseFiniteNumber(const std::string& text) {
  const std::optional<double> value = ReadAll<double>(text);
  if (!value || !std::isfinite(*value)) return std::nullopt;
  return value;
}

std::optional<std::uint64_t> ParseUnsignedDigits(const std::string& text) {
  return ReadAll<std::uint64_t>(text);
}

std::optional<std::int64_t> ParseWholeNumber(const std::string& text) {
  if (const std::optional<std::int64_t> value = ReadAll<std::int64_t>(text)) return value;
  constexpr double kExactLimit = 9007199254740992.0;  // 2^53
  const std::optional<double> real = ParseFiniteNumber(text);
  if (!real || std::floor(*real) != *real || std::fabs(*real) > kExactLimit) return std::nullopt;
  return static_cast<std::int64_t>(*real);
}

std::string RangeText(double min, double max) { return RangeTextOf(min, max); }

std::string RangeText(std::int64_t min, std::int64_t max) { return RangeTextOf(min, max); }

std::string NumberProblem(const std::string& text, double min, double max) {
  return Problem(text, ParseFiniteNumber(text), min, max, "a number");
}

std::string WholeNumberProblem(const std::string& text, std::int64_t min, std::int64_t max) {
  return Problem(text, ParseWholeNumber(text), min, max, "an integer");
}

}  // namespace colav
