#include "src/seed_aggregates.h"

#include <algorithm>
#include <numeric>
#include <stdexcept>

#include "src/random.h"
#include "src/seeding.h"

namespace colav {
namespace {

// S(x, y) of the Mann-Whitney statistic.
double Beats(double x, double y) { return x > y ? 1.0 : (x == y ? 0.5 : 0.0); }

std::size_t ScenarioCount(const SeedScores& a, const SeedScores& b) {
  if (a.empty() || b.empty() || a[0].empty()) {
    throw std::invalid_argument("ProbabilityOfImprovement: no seeds or no scenarios");
  }
  const std::size_t scenarios = a[0].size();
  for (const SeedScores* scores : {&a, &b}) {
    for (const std::vector<double>& seed : *scores) {
      if (seed.size() != scenarios) {
        throw std::invalid_argument("ProbabilityOfImprovement: seeds with other scenario counts");
      }
    }
  }
  return scenarios;
}

// P(A > B) over the given seeds and scenarios (indices may repeat: a bootstrap resample).
double ProbabilityOver(const SeedScores& a, const SeedScores& b,
                       const std::vector<std::size_t>& a_seeds,
                       const std::vector<std::size_t>& b_seeds,
                       const std::vector<std::size_t>& scenarios) {
  double sum = 0.0;
  for (const std::size_t t : scenarios) {
    for (const std::size_t i : a_seeds) {
      for (const std::size_t j : b_seeds) sum += Beats(a[i][t], b[j][t]);
    }
  }
  return sum / static_cast<double>(scenarios.size() * a_seeds.size() * b_seeds.size());
}

std::vector<std::size_t> AllIndices(std::size_t n) {
  std::vector<std::size_t> indices(n);
  std::iota(indices.begin(), indices.end(), 0);
  return indices;
}

std::vector<std::size_t> Resample(Rng& rng, std::size_t n) {
  std::vector<std::size_t> indices(n);
  for (std::size_t& index : indices) index = UniformIndex(rng, n);
  return indices;
}

}  // namespace

double InterquartileMean(std::vector<double> values) {
  if (values.empty()) throw std::invalid_argument("InterquartileMean: no values");
  std::sort(values.begin(), values.end());
  const std::size_t cut = values.size() / 4;
  const auto first = values.begin() + static_cast<std::ptrdiff_t>(cut);
  const auto last = values.end() - static_cast<std::ptrdiff_t>(cut);
  return std::accumulate(first, last, 0.0) / static_cast<double>(last - first);
}

double ProbabilityOfImprovement(const SeedScores& a, const SeedScores& b) {
  const std::size_t scenarios = ScenarioCount(a, b);
  return ProbabilityOver(a, b, AllIndices(a.size()), AllIndices(b.size()), AllIndices(scenarios));
}

ImprovementEstimate ProbabilityOfImprovementInterval(const SeedScores& a, const SeedScores& b,
                                                     std::uint64_t seed, int resamples,
                                                     double level, bool resample_scenarios) {
  const std::size_t scenarios = ScenarioCount(a, b);
  if (resamples < 1 || !(level > 0.0 && level < 1.0)) {
    throw std::invalid_argument("ProbabilityOfImprovementInterval: bad settings");
  }
  Rng rng = MakeRng(seed, "probability-of-improvement");
  const std::vector<std::size_t> all_scenarios = AllIndices(scenarios);
  std::vector<double> estimates(static_cast<std::size_t>(resamples));
  for (double& estimate : estimates) {
    const std::vector<std::size_t> a_seeds = Resample(rng, a.size());
    const std::vector<std::size_t> b_seeds = Resample(rng, b.size());
    estimate = ProbabilityOver(a, b, a_seeds, b_seeds,
                               resample_scenarios ? Resample(rng, scenarios) : all_scenarios);
  }
  return {ProbabilityOfImprovement(a, b),
          {Quantile(estimates, (1.0 - level) / 2.0), Quantile(estimates, (1.0 + level) / 2.0)}};
}

}  // namespace colav
