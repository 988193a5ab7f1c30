"""A random agent in 8 training worlds: the batched environment's loop, autoreset included.

    PYTHONPATH=build/python /usr/bin/python3 python/examples/random_agent.py --steps 2000
"""

import argparse

import numpy as np

import colav


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--envs", type=int, default=8, help="worlds")
    parser.add_argument("--steps", type=int, default=2000, help="batched steps")
    parser.add_argument("--seed", type=int, default=0)
    args = parser.parse_args()

    envs = colav.make_vec(args.envs, seed=args.seed)
    envs.action_space.seed(args.seed)
    obs, _ = envs.reset()
    episodes = []
    for _ in range(args.steps):
        obs, reward, terminated, truncated, info = envs.step(envs.action_space.sample())
        if info:  # some episodes ended; obs already holds their worlds' next first observation
            finished = info["_episode_metrics"]
            metrics = info["episode_metrics"]
            episodes += [{name: column[i] for name, column in metrics.items()}
                         for i in np.flatnonzero(finished)]
    print(f"{args.steps * args.envs} steps in {args.envs} worlds, {len(episodes)} episodes ended")
    if episodes:
        for name in ("steps", "progress", "collision", "cumulative_reward"):
            print(f"  mean {name}: {np.mean([e[name] for e in episodes]):.3f}")
    envs.close()


if __name__ == "__main__":
    main()
