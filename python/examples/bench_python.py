"""Steps per second of a Python loop over the batched environment, with random actions or a
policy's: the speed a Python agent sees (the C++ side alone: build/bin/bench_env).

    PYTHONPATH=build/python /usr/bin/python3 python/examples/bench_python.py --envs 8 --seconds 5
    ... bench_python.py --policy runs/best/ppo/best/seed_0/policy.pt --batch 4

--batch B steps the worlds asynchronously (colav.make_async, EnvPool's mode): each loop receives
the first B worlds done and sends their actions, so the worlds step while Python computes the
next actions. --policy FILE.pt computes the actions with a TorchScript policy (python3-torch, one
intra-op thread) instead of drawing them at random.
"""

import argparse
import time

import numpy as np

import colav

BLOCK = 1000  # loop iterations whose random actions are drawn with one numpy call
WARM_UP = 200  # loop iterations before the clock starts


def random_actions(rng, rows):
    """Uniform random actions: `choose(obs)` for the `rows` worlds of one loop iteration, drawn
    BLOCK iterations at a time."""
    queue = []

    def choose(_obs):
        if not queue:
            size = (BLOCK, rows, colav.ACTION_SIZE)
            queue.extend(rng.uniform(-1.0, 1.0, size=size).astype(np.float32))
        return queue.pop()
    return choose


def policy_actions(path):
    """A policy's actions: `choose(obs)` for the rows of one loop iteration."""
    import torch  # only for --policy: the environment itself needs no torch

    torch.set_num_threads(1)
    policy = torch.jit.load(path)

    def choose(obs):
        with torch.no_grad():
            return policy(torch.from_numpy(obs)).numpy()
    return choose


def steps_per_second(envs, seconds, step, rows):
    """Runs `step` (one loop iteration over `rows` worlds) for `seconds`, after a warm-up."""
    for _ in range(WARM_UP):
        step()
    steps, start = 0, time.perf_counter()
    while time.perf_counter() - start < seconds:
        for _ in range(BLOCK):
            step()
        steps += BLOCK * rows
    return steps / (time.perf_counter() - start)


def synchronous_loop(envs, choose):
    obs, _ = envs.reset(seed=0)

    def step():
        nonlocal obs
        obs = envs.step(choose(obs))[0]
    return step


def asynchronous_loop(envs, choose):
    obs, info = envs.reset(seed=0)
    env_id = info["env_id"]

    def step():
        nonlocal obs, env_id
        envs.send(choose(obs), env_id)
        obs, _, _, _, info = envs.recv()
        env_id = info["env_id"]
    return step


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--envs", type=int, default=8, help="worlds")
    parser.add_argument("--threads", type=int, default=0, help="threads (0: one per core)")
    parser.add_argument("--seconds", type=float, default=3.0, help="measuring time")
    parser.add_argument("--batch", type=int, default=0,
                        help="step asynchronously in batches of this many worlds (0: all together)")
    parser.add_argument("--policy", help="TorchScript policy.pt whose actions to take")
    args = parser.parse_args()

    if args.batch:
        envs = colav.make_async(args.envs, batch_size=args.batch, num_threads=args.threads)
        rows, make_loop, mode = args.batch, asynchronous_loop, f"asynchronous batches of {args.batch}"
    else:
        envs = colav.make_vec(args.envs, num_threads=args.threads)
        rows, make_loop, mode = args.envs, synchronous_loop, "stepped together"
    if args.policy:
        choose, source = policy_actions(args.policy), "policy actions"
    else:
        choose, source = random_actions(np.random.default_rng(0), rows), "random actions"
    rate = steps_per_second(envs, args.seconds, make_loop(envs, choose), rows)
    print(f"python loop, {args.envs} worlds ({mode}), {source}: {rate:,.0f} steps/s")


if __name__ == "__main__":
    main()
