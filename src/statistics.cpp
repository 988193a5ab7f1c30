#include "src/statistics.h"

#include <cmath>
#include <numeric>
#include <stdexcept>

#include "src/log_gamma.h"

namespace colav {
namespace {

// Continued fraction of the regularised incomplete beta function (modified Lentz method), the
// part that converges fast for x < (a + 1) / (a + b + 2).
double IncompleteBetaFraction(double a, double b, double x) {
  constexpr double kTiny = 1e-300;
  constexpr double kEpsilon = 1e-16;
  double c = 1.0;
  double d = 1.0 - (a + b) * x / (a + 1.0);
  if (std::fabs(d) < kTiny) d = kTiny;
  d = 1.0 / d;
  double result = d;
  for (int m = 1; m <= 10000; ++m) {
    const double two_m = 2.0 * m;
    // Even step.
    double coefficient = m * (b - m) * x / ((a + two_m - 1.0) * (a + two_m));
    d = 1.0 + coefficient * d;
    if (std::fabs(d) < kTiny) d = kTiny;
    c = 1.0 + coefficient / c;
    if (std::fabs(c) < kTiny) c = kTiny;
    d = 1.0 / d;
    result *= d * c;
    // Odd step.
    coefficient = -(a + m) * (a + b + m) * x / ((a + two_m) * (a + two_m + 1.0));
    d = 1.0 + coefficient * d;
    if (std::fabs(d) < kTiny) d = kTiny;
    c = 1.0 + coefficient / c;
    if (std::fabs(c) < kTiny) c = kTiny;
    d = 1.0 / d;
    const double delta = d * c;
    result *= delta;
    if (std::fabs(delta - 1.0) < kEpsilon) break;
  }
  return result;
}

// I_x(a, b).
double RegularisedIncompleteBeta(double a, double b, double x) {
  if (x <= 0.0) return 0.0;
  if (x >= 1.0) return 1.0;
  const double log_front =
      LogGamma(a + b) - LogGamma(a) - LogGamma(b) + a * std::log(x) + b * std::log1p(-x);
  const double front = std::exp(log_front);
  if (x < (a + 1.0) / (a + b + 2.0)) return front * IncompleteBetaFraction(a, b, x) / a;
  return 1.0 - front * IncompleteBetaFraction(b, a, 1.0 - x) / b;
}

}  // namespace

double Mean(const std::vector<double>& values) {
  if (values.empty()) throw std::invalid_argument("Mean of no values");
  return std::accumulate(values.begin(), values.end(), 0.0) / static_cast<double>(values.size());
}

double SampleStandardDeviation(const std::vector<double>& values) {
  if (values.size() < 2) return 0.0;
  const double mean = Mean(values);
  double sum_squares = 0.0;
  for (const double value : values) sum_squares += (value - mean) * (value - mean);
  return std::sqrt(sum_squares / static_cast<double>(values.size() - 1));
}

double StudentTCdf(double t, double dof) {
  if (!(dof > 0.0)) throw std::invalid_argument("StudentTCdf: dof must be positive");
  const double tail = 0.5 * RegularisedIncompleteBeta(dof / 2.0, 0.5, dof / (dof + t * t));
  return t >= 0.0 ? 1.0 - tail : tail;
}

double StudentTQuantile(double p, double dof) {
  if (!(p > 0.0 && p < 1.0)) throw std::invalid_argument("StudentTQuantile: p must be in (0, 1)");
  if (p < 0.5) return -StudentTQuantile(1.0 - p, dof);
  // The CDF is monotone: bisection on a bracket that doubles until it holds the quantile.
  double low = 0.0;
  double high = 1.0;
  while (StudentTCdf(high, dof) < p) {
    low = high;
    high *= 2.0;
  }
  for (int iteration = 0; iteration < 200 && high - low > 1e-13 * high; ++iteration) {
    const double middle = 0.5 * (low + high);
    (StudentTCdf(middle, dof) < p ? low : high) = middle;
  }
  return 0.5 * (low + high);
}

MeanConfidenceInterval Summarise(const std::vector<double>& values, double level) {
  MeanConfidenceInterval summary;
  summary.count = values.size();
  summary.mean = Mean(values);
  summary.sd = SampleStandardDeviation(values);
  if (values.size() >= 2) {
    const double n = static_cast<double>(values.size());
    summary.half_width = StudentTQuantile(0.5 + level / 2.0, n - 1.0) * summary.sd / std::sqrt(n);
  }
  summary.low = summary.mean - summary.half_width;
  summary.high = summary.mean + summary.half_width;
  return summary;
}

Interval PredictionInterval(const std::vector<double>& values, double level) {
  if (values.size() < 2) {
    throw std::invalid_argument("a prediction interval needs at least two values");
  }
  const double n = static_cast<double>(values.size());
  const double mean = Mean(values);
  const double half_width = StudentTQuantile(0.5 + level / 2.0, n - 1.0) *
                            SampleStandardDeviation(values) * std::sqrt(1.0 + 1.0 / n);
  return {mean - half_width, mean + half_width};
}

nlohmann::ordered_json ConfidenceIntervalJson(const MeanConfidenceInterval& interval) {
  return {{"n", interval.count}, {"mean", interval.mean}, {"sd", interval.sd},
          {"low", interval.low}, {"high", interval.high}, {"half_width", interval.half_width}};
}

MeanConfidenceInterval ConfidenceIntervalFromJson(const nlohmann::json& json) {
  MeanConfidenceInterval interval;
  interval.count = json.at("n").get<std::size_t>();
  interval.mean = json.at("mean").get<double>();
  interval.sd = json.at("sd").get<double>();
  interval.low = json.at("low").get<double>();
  interval.high = json.at("high").get<double>();
  interval.half_width = json.at("half_width").get<double>();
  return interval;
}

}  // namespace colav
