"""Runs a trained policy (policy.pt, TorchScript) on evaluate's test scenarios, or on scenario
files, in the batched environment, and prints the metrics evaluate reports (evaluate adds the
confidence intervals and the paired comparisons between models), and how often its actions sit at
a limit of the action box (a policy whose Gaussian grew far wider than the box in training steers
bang-bang: its mean, the deterministic action, is clipped).

    PYTHONPATH=build/python /usr/bin/python3 python/examples/run_policy.py runs/ppo_baseline/policy.pt
    ... run_policy.py POLICY --scenario configs/scenarios/head-on.yaml --scenario ...
"""

import argparse

import numpy as np
import torch

import colav


def run_episodes(policy, envs, actions_taken=None):
    """Each world's first episode under the colav.Policy's deterministic actions; returns the
    episode metrics per world and appends each step's actions of the unfinished episodes to
    `actions_taken` (a list) when given. Only unfinished episodes go through the policy (a
    recurrent one keeps each world's memory), so the numbers are evaluate's to the last bit."""
    obs, _ = envs.reset()
    results = [None] * envs.num_envs
    actions = np.zeros((envs.num_envs, colav.ACTION_SIZE), dtype=np.float32)
    while any(result is None for result in results):
        active = [i for i, result in enumerate(results) if result is None]
        actions[active] = policy.act(obs, worlds=active)
        if actions_taken is not None:
            actions_taken.append(actions[active].copy())
        obs, _, _, _, info = envs.step(actions)
        for i in np.flatnonzero(info.get("_episode_metrics", [])):
            if results[i] is None:
                results[i] = {name: column[i].item() for name, column in info["episode_metrics"].items()}
    return results


def summary_lines(results):
    """evaluate's summary rows: mean (sd) over the episodes."""
    def column(name, scale=1.0):
        values = np.array([r[name] for r in results], dtype=float) * scale
        return f"{values.mean():.1f} (sd {values.std(ddof=1) if len(values) > 1 else 0.0:.1f})"

    goals = sum(r["goal_reached"] for r in results)
    return [
        f"progress %              {column('progress', 100.0)}",
        f"cross-track error (m)   {column('mean_abs_cte')}",
        f"duration (steps)        {column('steps')}",
        f"collisions %            {column('collision', 100.0)}",
        f"reward                  {column('cumulative_reward')}",
        f"goals reached %         {100.0 * goals / len(results):.1f} ({goals}/{len(results)})",
        f"truncated episodes      {sum(r['truncated'] for r in results)}",
    ]


# |action| from which an action counts as at the limit of the box [-1, 1].
AT_LIMIT = 0.99


def action_lines(policy, actions_taken):
    """The share of steps whose surge and rudder actions sit at a limit, and the policy's
    training standard deviation when the file holds it (train_ppo's `log_std`)."""
    at_limit = 100.0 * (np.abs(np.concatenate(actions_taken)) >= AT_LIMIT).mean(axis=0)
    lines = [f"actions at a limit %    surge {at_limit[0]:.1f}, rudder {at_limit[1]:.1f} "
             f"(|a| >= {AT_LIMIT}, all steps)"]
    log_std = dict(policy.module.named_parameters()).get("log_std")
    if log_std is not None:
        std = ", ".join(f"{value:.3g}" for value in log_std.detach().exp().tolist())
        lines.append(f"training std            {std} (surge, rudder)")
    return lines


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument(
        "policy", help="policy.pt (forward: obs [B, 6 + 180*(1+scan_history)] -> action [B, 2]; "
        "a recurrent one: step(obs, state) -> (action, state) from initial_state(B))")
    parser.add_argument("--episodes", type=int, default=100, help="test scenarios")
    parser.add_argument("--seed", type=int, default=0, help="master seed of the test scenarios")
    parser.add_argument("--scenario", action="append", help="scenario file, repeatable")
    args = parser.parse_args()

    torch.set_num_threads(1)  # tiny networks: threads only add overhead
    policy = colav.Policy(args.policy)
    scenarios = args.scenario or colav.evaluation_scenarios(args.episodes, args.seed)
    settings = policy.observation_settings
    envs = colav.make_vec(scenarios=scenarios, test_mode=True, **settings)
    actions_taken = []
    results = run_episodes(policy, envs, actions_taken)
    where = "scenario files" if args.scenario else f"test scenarios of master seed {args.seed}"
    print(f"{args.policy} over {len(results)} episodes ({where}; {settings or 'default settings'}):")
    lines = summary_lines(results) + action_lines(policy, actions_taken)
    print("\n".join("  " + line for line in lines))


if __name__ == "__main__":
    main()
