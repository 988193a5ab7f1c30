#include "models/policy_import.h"

#include <string>
#include <utility>
#include <vector>

#include "models/observation_settings_record.h"
#include "models/torchscript_source.h"
#include "src/error.h"

namespace colav {
namespace {

std::string PolicyFileName(const std::filesystem::path& path) {
  return "policy file '" + path.string() + "'";
}

// The file's extractor, observation settings and navigation map against the run's.
void RequireSameInputs(const torch::jit::Module& script, const std::string& file,
                       const ObservationSettings& settings, ActorCriticImpl& model) {
  const std::string extractor = ExtractorKindName(model.options().extractor.kind);
  if (!script.hasattr("extractor") || !script.attr("extractor").isString() ||
      script.attr("extractor").toStringRef() != extractor) {
    throw UserError(file + ": not a policy of extractor " + extractor);
  }
  const std::optional<ObservationSettings> recorded = RecordedObservationSettings(script, file);
  if (recorded && *recorded != settings) {
    throw UserError(file + " was trained on observations (" +
                    DescribeObservationSettings(*recorded) + ") unlike this run's (" +
                    DescribeObservationSettings(settings) + ")");
  }
  // Its map of the navigation values is not a parameter: the run would not apply it.
  if (script.hasattr("navigation_mean")) {
    throw UserError(file +
                    " normalises its navigation values (ppo.normalize_navigation): a run "
                    "cannot start from it");
  }
}

}  // namespace

void LoadPolicyWeights(const std::filesystem::path& path, const ObservationSettings& settings,
                       ActorCriticImpl& model) {
  const std::string file = PolicyFileName(path);
  const torch::jit::Module script = LoadScript(path, file);
  RequireSameInputs(script, file, settings, model);
  const std::string context = " by this run's policy (policy.*, extractor.*)";
  // Every parameter is checked before any is copied, so that a refused file changes nothing.
  std::vector<std::pair<torch::Tensor, torch::Tensor>> destination_and_stored;
  for (const auto& parameter : model.named_parameters()) {
    destination_and_stored.emplace_back(
        parameter.value(), StoredParameter(script, ScriptedParameterName(parameter.key()),
                                           parameter.value().sizes(), file, context));
  }
  const std::size_t file_parameters = script.named_parameters().size();
  if (file_parameters != destination_and_stored.size()) {
    throw UserError(file + " has " + std::to_string(file_parameters) + " parameters, this run's " +
                    "policy " + std::to_string(destination_and_stored.size()) +
                    " (policy.*, extractor.*)");
  }
  torch::NoGradGuard no_grad;
  for (auto& [destination, stored] : destination_and_stored) destination.copy_(stored);
}

}  // namespace colav
