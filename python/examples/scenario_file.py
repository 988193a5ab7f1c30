"""One scenario file in a single Gymnasium-style environment, steered by a line-of-sight pilot
(full thrust, rudder from the heading error and yaw rate), printing where the vessel ends up.

    PYTHONPATH=build/python /usr/bin/python3 python/examples/scenario_file.py configs/scenarios/head-on.yaml
"""

import argparse

import numpy as np

import colav


def pilot(obs):
    """Full thrust; rudder 2 * heading error - 4 * yaw rate (observation indices 4 and 2)."""
    return np.array([1.0, np.clip(2.0 * obs[4] - 4.0 * obs[2], -1.0, 1.0)])


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("scenario", help="scenario file (YAML, shared/spec/interfaces.md)")
    parser.add_argument("--max-steps", type=int, default=2000)
    args = parser.parse_args()

    env = colav.make(scenario=args.scenario, test_mode=True, max_steps=args.max_steps)
    obs, _ = env.reset()
    print(f"scenario {colav.load_scenario(args.scenario).name}: start at "
          f"{env.state()['vessel'][:2].round(1)}, nearest return {np.min(env.state()['ranges']):.1f} m")
    terminated = truncated = False
    while not (terminated or truncated):
        obs, reward, terminated, truncated, info = env.step(pilot(obs))
    metrics = info["episode_metrics"]
    state = env.state()
    print(f"after {metrics['steps']} steps at {state['vessel'][:2].round(1)}: progress "
          f"{metrics['progress']:.1%}, collision {metrics['collision']}, goal "
          f"{metrics['goal_reached']}, reward {metrics['cumulative_reward']:.1f}")
    env.close()


if __name__ == "__main__":
    main()
