// ensemble_policy: one policy file acting with the mean of several trained policies' actions
// (eval/policy_ensemble.h).
#include <CLI/CLI.hpp>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include "eval/policy_ensemble.h"
#include "src/cli.h"
#include "src/output_path.h"

namespace colav {
namespace {

int EnsemblePolicyProgram(int argc, char** argv) {
  CLI::App app{
      "Writes one TorchScript policy that acts with the mean of its members' deterministic\n"
      "actions (each clipped to [-1, 1]): trained policy files of any recipe, memoryless or\n"
      "recurrent, sharing their observation settings. The output has a trained policy.pt's\n"
      "interface, so evaluate, study and colav.Policy run it; with a recurrent member it is\n"
      "recurrent, each member stepping its own slice of the state."};
  std::vector<std::string> members;
  std::string out;
  app.add_option("policies", members, "the members' policy files (TorchScript), two or more")
      ->required();
  app.add_option("--out", out, "the ensemble's policy file")->required();
  const ConfigFlags config_flags(app, ConfigSchema());  // no keys; --print-config as everywhere
  ParseCommandLine(app, argc, argv);
  config_flags.Resolve();
  RequireWritableFile(out, "--out");
  const std::vector<std::filesystem::path> paths(members.begin(), members.end());
  WriteEnsemblePolicy(paths, out);
  std::cout << "ensemble_policy: " << out << ": " << members.size() << " members\n";
  return 0;
}

}  // namespace
}  // namespace colav

int main(int argc, char** argv) {
  return colav::RunProgram("ensemble_policy", argc, argv, colav::EnsemblePolicyProgram);
}
