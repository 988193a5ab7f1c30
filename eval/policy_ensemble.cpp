#include "eval/policy_ensemble.h"

#include <fmt/format.h>

#include <string>
#include <system_error>
#include <vector>

#include "env/environment_spec.h"
#include "env/range_finder.h"
#include "models/observation_settings_record.h"
#include "models/torchscript_source.h"
#include "src/error.h"

namespace colav {
namespace {

std::string MemberName(std::size_t index) { return "member_" + std::to_string(index); }

// Where the stall rule reads the vessel's pace in an observation (env/environment_spec.h: [u, v,
// r, cte/100, heading error, look-ahead heading error, scans]).
constexpr int kSurgeSpeedIndex = 0;
constexpr int kHeadingErrorIndex = 4;
// The stall rule's columns of the state, after the members': the pace average, then the number
// of stalls so far (at most the number of reliefs, the members after the first).
constexpr int kStallColumns = 2;

// TorchScript statements that give every member's clipped action, action_<i>, and every recurrent
// member's next state, state_<i>, from its own columns of `state`; and the recurrent members'
// initial states.
struct MemberSource {
  std::string body;
  std::vector<std::string> actions;
  std::vector<std::string> initial_states;
  std::vector<std::string> next_states;
};

MemberSource MembersSource(const std::vector<Policy>& members) {
  MemberSource source;
  int column = 0;
  for (std::size_t i = 0; i < members.size(); ++i) {
    const std::string member = "self." + MemberName(i);
    if (members[i].recurrent()) {
      const int end = column + members[i].recurrent_size();
      source.initial_states.push_back(member + ".initial_state(batch)");
      source.body += fmt::format("    action_{0}, state_{0} = {1}.step(obs, state[:, {2}:{3}])\n",
                                 i, member, column, end);
      source.next_states.push_back(fmt::format("state_{}", i));
      column = end;
    } else {
      source.body += fmt::format("    action_{} = {}.forward(obs)\n", i, member);
    }
    source.body += fmt::format("    action_{0} = torch.clamp(action_{0}, -1.0, 1.0)\n", i);
    source.actions.push_back(fmt::format("action_{}", i));
  }
  return source;
}

// The expression of the ensemble's action from the members' clipped actions, before a stall.
std::string CombinedActionSource(const std::vector<std::string>& actions, const EnsembleRule& rule,
                                 const ObservationSettings& settings) {
  if (!rule.near_within_m) {
    if (rule.stall) return actions[0];
    return fmt::format("torch.stack([{}]).mean(0)", fmt::join(actions, ", "));
  }
  // Closeness falls as the range grows: a ray at most near_within_m away reads at least this.
  const double near = Closeness(*rule.near_within_m, settings.closeness);
  return fmt::format("torch.where(obs[:, {}:{}].max(1, keepdim=True)[0] >= {:.17g}, {}, {})",
                     kNavigationSize, kNavigationSize + kNumRays, near, actions[0], actions[1]);
}

// Adds to `source` the statements that keep the stall rule's columns of the state, from `column`
// on, and returns `action` with member k's action from the k-th stall on (k >= 1).
std::string AddStallSource(const StallRule& stall, int column, const std::string& action,
                           MemberSource& source) {
  const double keep = 1.0 - 1.0 / static_cast<double>(stall.steps);
  const std::size_t reliefs = source.actions.size() - 1;
  source.body += fmt::format(
      "    pace = {0:.17g} * state[:, {2}:{3}] + {1:.17g} * (obs[:, {5}:{6}] * "
      "torch.cos(obs[:, {7}:{8}]))\n"
      "    stalled = pace < {9:.17g}\n"
      "    stalls = torch.clamp(state[:, {3}:{4}] + stalled.float(), 0.0, {10}.0)\n"
      "    pace = torch.where(stalled, torch.full_like(pace, {11:.17g}), pace)\n",
      keep, 1.0 - keep, column, column + 1, column + 2, kSurgeSpeedIndex, kSurgeSpeedIndex + 1,
      kHeadingErrorIndex, kHeadingErrorIndex + 1, stall.pace_mps, reliefs, kStallPaceStartMps);
  source.initial_states.push_back(
      fmt::format("torch.tensor([{:.17g}, 0.0]).repeat(batch, 1)", kStallPaceStartMps));
  source.next_states.insert(source.next_states.end(), {"pace", "stalls"});
  std::string steered = action;
  for (std::size_t k = 1; k <= reliefs; ++k) {
    steered = fmt::format("torch.where(stalls > {}.5, {}, {})", k - 1, source.actions[k], steered);
  }
  return steered;
}

std::string MemorylessSource(const MemberSource& source, const std::string& action) {
  return fmt::format(
      "def forward(self, obs: Tensor) -> Tensor:\n"
      "{}"
      "    return {}\n",
      source.body, action);
}

std::string RecurrentSource(const MemberSource& source, const std::string& action, int state_size) {
  return fmt::format(
      "def initial_state(self, batch: int) -> Tensor:\n"
      "    return torch.cat([{0}], 1)\n"
      "def step(self, obs: Tensor, state: Tensor) -> Tuple[Tensor, Tensor]:\n"
      "    assert state.dim() == 2 and state.size(0) == obs.size(0) and state.size(1) == {1}, "
      "'policy: states [B, recurrent_size] expected (initial_state(B) at an episode start)'\n"
      "{2}"
      "    return {3}, torch.cat([{4}], 1)\n"
      "def forward(self, obs: Tensor) -> Tensor:\n"
      "    assert False, 'recurrent policy: call step(obs, state) starting from "
      "initial_state(B)'\n"
      "    return obs\n",
      fmt::join(source.initial_states, ", "), state_size, source.body, action,
      fmt::join(source.next_states, ", "));
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

void CheckEnsemble(std::size_t members, const EnsembleRule& rule) {
  if (members < 2) throw UserError("an ensemble needs at least two policies");
  if (rule.near_within_m) {
    if (!RangeRuleFits(members, rule.stall.has_value())) {
      throw UserError(fmt::format(
          "--near-within: takes two policies (the one near obstacles, the other), or more with "
          "--stall-pace (the later ones relieve at the second stall and after), got {}",
          members));
    }
    if (!(*rule.near_within_m > 0.0 && *rule.near_within_m < RangeFinder::kRange)) {
      throw UserError(fmt::format("--near-within {}: expects metres in (0, {})",
                                  *rule.near_within_m, RangeFinder::kRange));
    }
  }
  if (rule.stall) {
    if (!(rule.stall->pace_mps > 0.0 && rule.stall->pace_mps < kStallPaceStartMps)) {
      throw UserError(fmt::format("--stall-pace {}: expects m/s in (0, {})", rule.stall->pace_mps,
                                  kStallPaceStartMps));
    }
    if (rule.stall->steps < 1) {
      throw UserError(fmt::format("--stall-steps {}: expects at least 1", rule.stall->steps));
    }
  }
}

torch::jit::Module EnsemblePolicy(const std::vector<Policy>& members, const EnsembleRule& rule) {
  CheckEnsemble(members.size(), rule);
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
  MemberSource source = MembersSource(members);
  std::string action = CombinedActionSource(source.actions, rule, settings);
  if (rule.stall) {
    action = AddStallSource(*rule.stall, state_size, action, source);
    state_size += kStallColumns;
  }
  if (state_size > 0) {
    ensemble.register_attribute("recurrent_size", c10::IntType::get(), state_size);
    ensemble.define(RecurrentSource(source, action, state_size));
  } else {
    ensemble.define(MemorylessSource(source, action));
  }
  ensemble.eval();
  return ensemble;
}

void WriteEnsemblePolicy(const std::vector<std::filesystem::path>& members,
                         const std::filesystem::path& out, const EnsembleRule& rule) {
  CheckEnsemble(members.size(), rule);
  for (const std::filesystem::path& member : members) {
    std::error_code same_file_unknown;
    if (std::filesystem::equivalent(member, out, same_file_unknown)) {
      throw UserError("--out " + out.string() + ": is one of the members");
    }
  }
  std::vector<Policy> policies;
  policies.reserve(members.size());
  for (const std::filesystem::path& member : members) {
    policies.emplace_back(member, DefaultPolicyName(member));
  }
  SaveScript(EnsemblePolicy(policies, rule), out);
}

}  // namespace colav
