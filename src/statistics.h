// Summary statistics of repeated measurements (VAE seeds, evaluation episodes): mean, sample
// standard deviation and the Student-t 95 % confidence interval of the mean, as the paper reports
// them (reference-learning 7.2: t with n - 1 degrees of freedom, scale = sd / sqrt(n), ddof 1).
#pragma once

#include <cstddef>
#include <nlohmann/json.hpp>
#include <vector>

#include "src/rate_interval.h"

namespace colav {

double Mean(const std::vector<double>& values);
/// Sample standard deviation (n - 1 in the denominator); 0 for fewer than two values.
double SampleStandardDeviation(const std::vector<double>& values);

/// Student-t CDF with `dof` > 0 degrees of freedom.
double StudentTCdf(double t, double dof);
/// The p-quantile (0 < p < 1) of the Student-t distribution with `dof` > 0 degrees of freedom.
double StudentTQuantile(double p, double dof);

/// Mean with its two-sided confidence interval mean +- t_{(1+level)/2, n-1} * sd / sqrt(n).
struct MeanConfidenceInterval {
  std::size_t count = 0;
  double mean = 0.0;
  double sd = 0.0;          ///< sample standard deviation
  double half_width = 0.0;  ///< 0 for fewer than two values (no spread to estimate)
  double low = 0.0;
  double high = 0.0;
};

/// The summary of `values` (not empty; std::invalid_argument otherwise).
MeanConfidenceInterval Summarise(const std::vector<double>& values, double level = 0.95);

/// The two-sided interval that holds one more draw from the population of `values` (at least
/// two) with probability `level`, if that population is normal: mean +- t_{(1+level)/2, n-1} *
/// sd * sqrt(1 + 1/n). Where the confidence interval bounds the population's mean, this bounds
/// one new member: one more training seed's result, say. std::invalid_argument for fewer than two.
Interval PredictionInterval(const std::vector<double>& values, double level = 0.95);

/// `interval` as the JSON object {n, mean, sd, low, high, half_width}, in this order.
nlohmann::ordered_json ConfidenceIntervalJson(const MeanConfidenceInterval& interval);
/// The inverse of ConfidenceIntervalJson (nlohmann::json::exception for a missing field).
MeanConfidenceInterval ConfidenceIntervalFromJson(const nlohmann::json& json);

}  // namespace colav
