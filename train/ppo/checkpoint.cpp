#include "train/ppo/checkpoint.h"

#include <string>

#include "models/policy_export.h"
#include "src/atomic_file.h"
#include "src/error.h"

namespace colav {
namespace {

constexpr char kModelPrefix[] = "model/";
constexpr char kOptimizerPrefix[] = "optimizer/";

torch::Tensor ReadTensor(torch::serialize::InputArchive& archive, const std::string& key) {
  torch::Tensor tensor;
  archive.read(key, tensor);
  return tensor;
}

}  // namespace

std::filesystem::path TrainingStatePath(const std::filesystem::path& run_dir) {
  return run_dir / "training_state.pt";
}

void SaveCheckpoint(const std::filesystem::path& run_dir, ActorCriticImpl& model,
                    const Adam& optimizer, torch::Generator& generator,
                    const TrainingCounters& counters, const ObservationSettings& settings,
                    bool keep_policy_copy) {
  ExportPolicy(model, counters.global_step, settings, run_dir / "policy.pt");
  if (keep_policy_copy) {
    ExportPolicy(
        model, counters.global_step, settings,
        run_dir / "checkpoints" / ("policy_" + std::to_string(counters.global_step) + ".pt"));
  }
  torch::serialize::OutputArchive archive;
  for (const auto& parameter : model.named_parameters()) {
    archive.write(kModelPrefix + parameter.key(), parameter.value().detach());
  }
  torch::serialize::OutputArchive optimizer_archive;
  optimizer.Save(optimizer_archive);
  archive.write("optimizer", optimizer_archive);
  archive.write("generator_state", generator.get_state());
  archive.write("global_step", torch::tensor(counters.global_step));
  archive.write("n_updates", torch::tensor(counters.n_updates));
  archive.write("rollouts", torch::tensor(counters.rollouts));
  archive.write("episodes", torch::tensor(counters.episodes));
  archive.write("wall_s", torch::tensor(counters.wall_s, torch::kFloat64));
  WriteFileAtomically(TrainingStatePath(run_dir), [&](const std::filesystem::path& temporary) {
    archive.save_to(temporary.string());
  });
}

TrainingCounters LoadCheckpoint(const std::filesystem::path& run_dir, ActorCriticImpl& model,
                                Adam& optimizer, torch::Generator& generator) {
  const std::filesystem::path path = TrainingStatePath(run_dir);
  const std::string file = "training state '" + path.string() + "'";
  if (!std::filesystem::is_regular_file(path)) throw UserError(file + " does not exist");
  TrainingCounters counters;
  try {
    torch::serialize::InputArchive archive;
    archive.load_from(path.string());
    torch::NoGradGuard no_grad;
    for (const auto& parameter : model.named_parameters()) {
      const torch::Tensor stored = ReadTensor(archive, kModelPrefix + parameter.key());
      if (stored.sizes() != parameter.value().sizes()) {
        throw UserError(file + ": parameter '" + parameter.key() +
                        "' does not fit the configured model");
      }
      parameter.value().copy_(stored);  // in place: the fast path keeps pointing at it
    }
    torch::serialize::InputArchive optimizer_archive;
    archive.read("optimizer", optimizer_archive);
    optimizer.Load(optimizer_archive);
    generator.set_state(ReadTensor(archive, "generator_state"));
    counters.global_step = ReadTensor(archive, "global_step").item<std::int64_t>();
    counters.n_updates = ReadTensor(archive, "n_updates").item<std::int64_t>();
    counters.rollouts = ReadTensor(archive, "rollouts").item<std::int64_t>();
    counters.episodes = ReadTensor(archive, "episodes").item<std::int64_t>();
    counters.wall_s = ReadTensor(archive, "wall_s").item<double>();
  } catch (const UserError&) {
    throw;
  } catch (const std::exception& error) {
    const std::string reason = error.what();
    throw UserError(file + " cannot be read: " + reason.substr(0, reason.find('\n')));
  }
  return counters;
}

}  // namespace colav
