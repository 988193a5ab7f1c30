#include "eval/policy_ensemble.h"

#include <fmt/format.h>

#include <string>
#include <system_error>
#include <vector>

#include "models/observation_settings_record.h"
#include "models/torchscript_source.h"
#include "src/error.h"

namespace colav {
namespace {

std::string MemberName(std::size_t index) { return "member_" + std::to_string(index); }

std::string ClippedSource(const std::string& action) {
  return "torch.clamp(" + action + ", -1.0, 1.0)";
}

// forward(obs): the mean of the memoryless members' clipped actions.
std::string MemorylessSource(std::size_t members) {
  std::vector<std::string> actions;
  for (std::size_t i = 0; i < members; ++i) {
    actions.push_back(ClippedSource("self." + MemberName(i) + ".forward(obs)"));
  }
  return fmt::format(
      "def forward(self, obs: Tensor) -> Tensor:\n"
      "    return torch.stack([{}]).mean(0)\n",
      fmt::join(actions, ", "));
}

// initial_state, step and a failing forward: each recurrent member steps its own columns of the
// state, the memoryless ones act from the observation alone.
std::string RecurrentSource(const std::vector<Policy>& members, int state_size) {
  std::vector<std::string> initial_states;
  std::vector<std::string> actions;
  std::vector<std::string> next_states;
  std::string body;
  int column = 0;
  for (std::size_t i = 0; i < members.size(); ++i) {
    const std::string member = "self." + MemberName(i);
    if (!members[i].recurrent()) {
      actions.push_back(ClippedSource(member + ".forward(obs)"));
      continue;
    }
    const int end = column + members[i].recurrent_size();
    initial_states.push_back(member + ".initial_state(batch)");
    body += fmt::format("    action_{0}, state_{0} = {1}.step(obs, state[:, {2}:{3}])\n", i, member,
                        column, end);
    actions.push_back(ClippedSource(fmt::format("action_{}", i)));
    next_states.push_back(fmt::format("state_{}", i));
    column = end;
  }
  return fmt::format(
      "def initial_state(self, batch: int) -> Tensor:\n"
      "    return torch.cat([{0}], 1)\n"
      "def step(self, obs: Tensor, state: Tensor) -> Tuple[Tensor, Tensor]:\n"
      "    assert state.dim() == 2 and state.size(0) == obs.size(0) and state.size(1) == {1}, "
      "'policy: states [B, recurrent_size] expected (initial_state(B) at an episode start)'\n"
      "{2}"
      "    return torch.stack([{3}]).mean(0), torch.cat([{4}], 1)\n"
      "def forward(self, obs: Tensor) -> Tensor:\n"
      "    assert False, 'recurrent policy: call step(obs, state) starting from "
      "initial_state(B)'\n"
      "    return obs\n",
      fmt::join(initial_states, ", "), state_size, body, fmt::join(actions, ", "),
      fmt::join(next_states, ", "));
}

// The members' common observation settings.
ObservationSettings CommonSettings(const std::vector<Policy>& members) {
  for (const Policy& member : members) {
    if (!member.own_settings()) {
      throw UserError(member.path().string() +
                      ": no observation settings (neither recorded in the file nor in " +
                      SidecarPath(member.path()).string() + ")");
    }
    if (!(*member.own_settings() == *members.front().own_settings())) {
      throw UserError(member.path().string() + ": observation settings differ from those of " +
                      members.front().path().string());
    }
  }
  return *members.front().own_settings();
}

}  // namespace

torch::jit::Module EnsemblePolicy(const std::vector<Policy>& members) {
  if (members.size() < 2) throw UserError("an ensemble needs at least two policies");
  const ObservationSettings settings = CommonSettings(members);
  torch::jit::Module ensemble("PolicyEnsemble");
  std::string paths;
  int state_size = 0;
  for (std::size_t i = 0; i < members.size(); ++i) {
    ensemble.register_module(MemberName(i), members[i].module());
    paths += (i > 0 ? "\n" : "") + std::filesystem::absolute(members[i].path()).string();
    state_size += members[i].recurrent_size();
  }
  RecordObservationSettings(ensemble, settings);
  ensemble.register_attribute("member_paths", c10::StringType::get(), paths);
  if (state_size > 0) {
    ensemble.register_attribute("recurrent_size", c10::IntType::get(), state_size);
    ensemble.define(RecurrentSource(members, state_size));
  } else {
    ensemble.define(MemorylessSource(members.size()));
  }
  ensemble.eval();
  return ensemble;
}

void WriteEnsemblePolicy(const std::vector<std::filesystem::path>& members,
                         const std::filesystem::path& out) {
  if (members.size() < 2) throw UserError("an ensemble needs at least two policies");
  for (const std::filesystem::path& member : members) {
    std::error_code same_file_unknown;
    if (std::filesystem::equivalent(member, out, same_file_unknown)) {
      throw UserError("--out " + out.string() + ": is one of the members");
    }
  }
  std::vector<Policy> policies;
  for (const std::filesystem::path& member : members) {
    policies.emplace_back(member, DefaultPolicyName(member));
  }
  SaveScript(EnsemblePolicy(policies), out);
}

}  // namespace colav
