#include "train/ppo/running_variance.h"

namespace colav {

void RunningVariance::Update(const std::vector<double>& batch) {
  if (batch.empty()) return;
  const double n = static_cast<double>(batch.size());
  double batch_mean = 0.0;
  for (const double x : batch) batch_mean += x;
  batch_mean /= n;
  double batch_variance = 0.0;
  for (const double x : batch) batch_variance += (x - batch_mean) * (x - batch_mean);
  batch_variance /= n;

  const double delta = batch_mean - mean;
  const double total = count + n;
  const double m2 = variance * count + batch_variance * n + delta * delta * count * n / total;
  mean += delta * n / total;
  variance = m2 / total;
  count = total;
}

}  // namespace colav
