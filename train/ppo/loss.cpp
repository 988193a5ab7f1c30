#include "train/ppo/loss.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "env/environment_spec.h"
#include "train/ppo/normal_log_density.h"

namespace colav {
namespace {

// SB3's guard against a zero advantage spread.
constexpr double kAdvantageEpsilon = 1e-8;

// log(1 - tanh(u)^2) = 2 (log 2 - u - softplus(-2u)), without cancellation for large |u|.
double LogOneMinusTanhSquared(double u) {
  const double y = -2.0 * u;
  const double softplus = std::max(y, 0.0) + std::log1p(std::exp(-std::abs(y)));
  return 2.0 * (std::log(2.0) - u - softplus);
}

}  // namespace

PpoLossStats PpoLossGradients(const float* mean, const float* log_std, const float* value,
                              const PpoMinibatch& batch, const PpoLossOptions& options,
                              float* d_mean, float* d_log_std, float* d_value) {
  const int B = batch.size;
  double advantage_mean = 0.0;
  double advantage_scale = 1.0;
  if (options.normalize_advantage && B > 1) {
    for (int b = 0; b < B; ++b) advantage_mean += batch.advantages[b];
    advantage_mean /= B;
    double variance = 0.0;
    for (int b = 0; b < B; ++b) variance += std::pow(batch.advantages[b] - advantage_mean, 2);
    advantage_scale = 1.0 / (std::sqrt(variance / (B - 1)) + kAdvantageEpsilon);
  }

  double inverse_std[kActionSize];
  double log_std_sum = 0.0;
  for (int j = 0; j < kActionSize; ++j) {
    inverse_std[j] = std::exp(-static_cast<double>(log_std[j]));
    log_std_sum += log_std[j];
    d_log_std[j] = 0.0f;
  }
  double entropy = kActionSize * (0.5 + kLogSqrtTwoPi) + log_std_sum;

  PpoLossStats stats;
  const double low = 1.0 - options.clip_range;
  const double high = 1.0 + options.clip_range;
  double d_log_std_sum[kActionSize] = {};
  for (int b = 0; b < B; ++b) {
    double z[kActionSize];
    double log_prob = -log_std_sum - kActionSize * kLogSqrtTwoPi;
    for (int j = 0; j < kActionSize; ++j) {
      z[j] = (batch.actions[b * kActionSize + j] - mean[j * B + b]) * inverse_std[j];
      log_prob -= 0.5 * z[j] * z[j];
    }
    const double log_ratio = log_prob - batch.old_log_probs[b];
    const double ratio = std::exp(log_ratio);
    const double advantage = (batch.advantages[b] - advantage_mean) * advantage_scale;
    const double clipped = std::clamp(ratio, low, high);
    stats.policy_gradient_loss -= std::min(ratio * advantage, clipped * advantage);
    stats.approx_kl += (ratio - 1.0) - log_ratio;
    stats.clip_fraction += std::abs(ratio - 1.0) > options.clip_range ? 1.0 : 0.0;
    // The min passes the gradient of r A' unless the clipped branch is smaller and flat.
    const bool unclipped_active =
        (ratio >= low && ratio <= high) || ratio * advantage < clipped * advantage;
    const double d_log_prob = unclipped_active ? -advantage * ratio / B : 0.0;
    for (int j = 0; j < kActionSize; ++j) {
      d_mean[j * B + b] = static_cast<float>(d_log_prob * z[j] * inverse_std[j]);
      d_log_std_sum[j] += d_log_prob * (z[j] * z[j] - 1.0);
    }
    if (options.squashed_actions) {
      for (int j = 0; j < kActionSize; ++j) {
        const double u = batch.actions[b * kActionSize + j];
        const double squash = std::tanh(u);
        entropy += LogOneMinusTanhSquared(u) / B;
        // -ent_coef times the entropy's gradient (loss.h), with u - mean = z std.
        d_mean[j * B + b] += static_cast<float>(options.ent_coef * 2.0 * squash / B);
        d_log_std_sum[j] += options.ent_coef * 2.0 * squash * z[j] / (inverse_std[j] * B);
      }
    }
    const double error = value[b] - batch.returns[b];
    stats.value_loss += error * error;
    d_value[b] = static_cast<float>(options.vf_coef * 2.0 * error / B);
  }
  for (int j = 0; j < kActionSize; ++j) {
    d_log_std[j] = static_cast<float>(d_log_std_sum[j] - options.ent_coef);
  }
  stats.policy_gradient_loss /= B;
  stats.value_loss /= B;
  stats.approx_kl /= B;
  stats.clip_fraction /= B;
  stats.entropy_loss = -entropy;
  stats.loss = stats.policy_gradient_loss + options.ent_coef * stats.entropy_loss +
               options.vf_coef * stats.value_loss;
  return stats;
}

}  // namespace colav
