#include "python/batch_arrays.h"

#include <algorithm>
#include <string>

#include "python/episode_metrics.h"

namespace colav::python {
namespace {

std::string ShapeText(const py::array& array) {
  std::string text = "(";
  for (py::ssize_t d = 0; d < array.ndim(); ++d) {
    text += (d > 0 ? ", " : "") + std::to_string(array.shape(d));
  }
  return text + (array.ndim() == 1 ? ",)" : ")");
}

}  // namespace

BatchArrays::BatchArrays(int rows, int observation_size)
    : observations({rows, observation_size}),
      final_observations({rows, observation_size}),
      rewards(rows),
      terminated(rows),
      truncated(rows) {
  std::fill_n(final_observations.mutable_data(), final_observations.size(), 0.0f);
  static_assert(sizeof(bool) == sizeof(std::uint8_t), "numpy bools are written as bytes");
  pointers = {observations.mutable_data(), final_observations.mutable_data(),
              rewards.mutable_data(), reinterpret_cast<std::uint8_t*>(terminated.mutable_data()),
              reinterpret_cast<std::uint8_t*>(truncated.mutable_data())};
}

void RequireActionShape(const py::array& actions, int rows) {
  if (actions.ndim() != 2 || actions.shape(0) != rows || actions.shape(1) != kActionSize) {
    throw py::value_error("actions: expected shape (" + std::to_string(rows) + ", " +
                          std::to_string(kActionSize) + "), got " + ShapeText(actions));
  }
}

int CountFinished(const std::vector<std::optional<EpisodeMetrics>>& episodes) {
  return static_cast<int>(
      std::count_if(episodes.begin(), episodes.end(), [](const auto& e) { return e.has_value(); }));
}

py::dict FinishedEpisodesInfo(const std::vector<std::optional<EpisodeMetrics>>& episodes,
                              const py::array_t<float>& final_observations) {
  py::array_t<bool> mask(static_cast<py::ssize_t>(episodes.size()));
  std::transform(episodes.begin(), episodes.end(), mask.mutable_data(),
                 [](const auto& episode) { return episode.has_value(); });
  py::dict info;
  info["final_obs"] = final_observations;
  info["_final_obs"] = mask;
  info["episode_metrics"] = MetricColumns(episodes);
  info["_episode_metrics"] = mask;
  return info;
}

}  // namespace colav::python
