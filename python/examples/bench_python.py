"""Steps per second of a Python loop over the batched environment with random actions: the
speed a Python agent sees (the C++ side alone: build/bin/bench_env).

    PYTHONPATH=build/python /usr/bin/python3 python/examples/bench_python.py --envs 8 --seconds 5
"""

import argparse
import time

import numpy as np

import colav

BLOCK = 1000  # steps whose random actions are drawn with one numpy call


def steps_per_second(envs, seconds, rng):
    envs.reset(seed=0)
    shape = (BLOCK, envs.num_envs, colav.ACTION_SIZE)
    actions = rng.uniform(-1.0, 1.0, size=shape).astype(np.float32)
    for action in actions[:200]:  # warm-up
        envs.step(action)
    steps, start = 0, time.perf_counter()
    while time.perf_counter() - start < seconds:
        actions = rng.uniform(-1.0, 1.0, size=shape).astype(np.float32)
        for action in actions:
            envs.step(action)
        steps += BLOCK * envs.num_envs
    return steps / (time.perf_counter() - start)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--envs", type=int, default=8, help="worlds")
    parser.add_argument("--threads", type=int, default=0, help="threads (0: one per core)")
    parser.add_argument("--seconds", type=float, default=3.0, help="measuring time")
    args = parser.parse_args()

    envs = colav.make_vec(args.envs, num_threads=args.threads)
    rate = steps_per_second(envs, args.seconds, np.random.default_rng(0))
    print(f"python loop, {args.envs} worlds, random actions: {rate:,.0f} steps/s")


if __name__ == "__main__":
    main()
