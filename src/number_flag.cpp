#include "src/number_flag.h"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cstdint>
#include <limits>
#include <optional>
#include <type_traits>
#include <utility>

#include "src/number_text.h"

namespace colav {
namespace {

constexpr auto kInt64Max = static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max());

// The range of an integer field as int64, for the int64 reading of its text; an unsigned field's
// values above 2^63 - 1 are read apart (ParseUnsignedDigits).
template <typename Number>
std::pair<std::int64_t, std::int64_t> WholeBounds(Number min, Number max) {
  if constexpr (std::is_unsigned_v<Number>) {
    return {static_cast<std::int64_t>(min),
            static_cast<std::int64_t>(std::min<std::uint64_t>(max, kInt64Max))};
  } else {
    return {min, max};
  }
}

template <typename Number>
std::string RangeOf(Number min, Number max) {
  if constexpr (std::is_floating_point_v<Number>) {
    return RangeText(min, max);
  } else {
    const auto [low, high] = WholeBounds(min, max);
    return RangeText(low, high);
  }
}

// Checks the text and rewrites it as CLI11 reads it: "3e6" becomes "3000000" for an integer.
template <typename Number>
std::string CheckAndNormalise(std::string& text, Number min, Number max) {
  if constexpr (std::is_floating_point_v<Number>) {
    return NumberProblem(text, min, max);
  } else {
    if constexpr (std::is_unsigned_v<Number>) {
      const std::optional<std::uint64_t> digits = ParseUnsignedDigits(text);
      if (digits && *digits > kInt64Max) {
        if (*digits < min || *digits > max) return text + " is out of range " + RangeOf(min, max);
        text = std::to_string(*digits);
        return "";
      }
    }
    const auto [low, high] = WholeBounds(min, max);
    std::string problem = WholeNumberProblem(text, low, high);
    if (problem.empty()) text = std::to_string(*ParseWholeNumber(text));
    return problem;
  }
}

}  // namespace

template <typename Number>
CLI::Option* AddNumberFlag(CLI::App& app, const std::string& flag, Number& value,
                           const std::string& doc, Number min, Number max) {
  CLI::Option* option = app.add_option(flag, value, doc);
  // A transform, not a check: CLI11 hands a check a copy of the text, and "3e6" is rewritten.
  option->transform(
      CLI::Validator([min, max](std::string& text) { return CheckAndNormalise(text, min, max); },
                     RangeOf(min, max)));
  return option;
}

template CLI::Option* AddNumberFlag<double>(CLI::App&, const std::string&, double&,
                                            const std::string&, double, double);
template CLI::Option* AddNumberFlag<int>(CLI::App&, const std::string&, int&, const std::string&,
                                         int, int);
template CLI::Option* AddNumberFlag<std::int64_t>(CLI::App&, const std::string&, std::int64_t&,
                                                  const std::string&, std::int64_t, std::int64_t);
template CLI::Option* AddNumberFlag<std::uint64_t>(CLI::App&, const std::string&, std::uint64_t&,
                                                   const std::string&, std::uint64_t,
                                                   std::uint64_t);

}  // namespace colav
