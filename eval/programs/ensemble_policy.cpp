// ensemble_policy: one policy file acting with the mean of several trained policies' actions
// (eval/policy_ensemble.h).
#include <CLI/CLI.hpp>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include "env/range_finder.h"
#include "eval/policy_ensemble.h"
#include "src/cli.h"
#include "src/number_flag.h"
#include "src/output_path.h"

namespace colav {
namespace {

int EnsemblePolicyProgram(int argc, char** argv) {
  CLI::App app{
      "Writes one TorchScript policy that acts with the mean of its members' deterministic\n"
      "actions (each clipped to [-1, 1]): trained policy files of any recipe, memoryless or\n"
      "recurrent, sharing their observation settings. The output has a trained policy.pt's\n"
      "interface, so evaluate, study and colav.Policy run it; with a recurrent member it is\n"
      "recurrent, each member stepping its own slice of the state. With --near-within M, two\n"
      "members: the first steers while an obstacle is within M metres, the second otherwise.\n"
      "With --stall-pace P: the second member steers from the step the vessel stalls (its pace\n"
      "towards the look-ahead point, averaged over --stall-steps, falls below P m/s) to the end\n"
      "of the episode; a third, if given, from the step it stalls again (the average restarts at\n"
      "each stall), and so on. With both rules, the members after the second are reliefs only."};
  std::vector<std::string> members;
  std::string out;
  double near_within_m = 0.0;
  app.add_option("policies", members, "the members' policy files (TorchScript), two or more")
      ->required();
  app.add_option("--out", out, "the ensemble's policy file")->required();
  CLI::Option* near_within = AddNumberFlag<double>(
      app, "--near-within", near_within_m,
      "metres: the first of two members steers while the newest scan's nearest return is this "
      "close, the second otherwise (default: the mean of every member's action)",
      0.0, RangeFinder::kRange);
  StallRule stall;
  CLI::Option* stall_pace = AddNumberFlag<double>(
      app, "--stall-pace", stall.pace_mps,
      "m/s: the next member takes the helm each time the vessel's pace towards the look-ahead "
      "point, u cos(heading error), averaged over --stall-steps, falls below this (the second at "
      "the first stall, a third at the second, ...; the last keeps it to the episode's end; "
      "default: no stall rule)",
      0.0, kStallPaceStartMps);
  AddNumberFlag<int>(app, "--stall-steps", stall.steps,
                     "steps the stall rule's pace is averaged over (exponentially)", 1,
                     kMaxStallSteps)
      ->needs(stall_pace);
  const ConfigFlags config_flags(app, ConfigSchema());  // no keys; --print-config as everywhere
  ParseCommandLine(app, argc, argv);
  config_flags.Resolve();
  RequireWritableFile(out, "--out");
  const std::vector<std::filesystem::path> paths(members.begin(), members.end());
  EnsembleRule rule;
  if (near_within->count() > 0) rule.near_within_m = near_within_m;
  if (stall_pace->count() > 0) rule.stall = stall;
  WriteEnsemblePolicy(paths, out, rule);
  std::cout << "ensemble_policy: " << out << ": " << members.size() << " members\n";
  return 0;
}

}  // namespace
}  // namespace colav

int main(int argc, char** argv) {
  return colav::RunProgram("ensemble_policy", argc, argv, colav::EnsemblePolicyProgram);
}
