#!/usr/bin/python3
"""Distil a teacher policy (an ensemble, say) into one recurrent policy, by DAgger.

The teacher is any policy file `evaluate` runs: a trained `policy.pt`, or an `ensemble_policy`
file whose members hand the helm to each other. The student starts as INIT, a recurrent
`policy.pt` of `train_ppo` (`policy.recurrent_size` > 0), and keeps its architecture; its memory
(the GRU), actor layers and action layer learn to act as the teacher does. Its perception (the
encoder and extractor, `features_extractor_*`) stays as it is, as a locked encoder does, unless
--perception-learning-rate is above 0: then it learns too, at that step size:

1. Each iteration plays STEPS steps in each of WORLDS training worlds (the paper's, as
   `train_ppo` trains in, under the policies' observation settings). The teacher drives in the
   first iteration, the student in the others; the teacher's deterministic action is recorded
   at every step (DAgger: the student learns what to do in the states it reaches itself).
   With --traps K, the last K of the WORLDS replay, episode after episode, K training
   scenarios in which INIT alone times out (found first, by playing INIT in other training
   worlds): a stall is rare in the paper's worlds, and the teacher's way out of one is learnt
   only where the student stalls.
2. The student trains on the last KEEP iterations' steps, in sequences of SEQUENCE steps that
   start from the memory the student had there, for EPOCHS passes. The loss is the squared
   error between its action mean and the teacher's action, except beyond a bound the teacher
   reached: a mean past +1 where the teacher acted +1 is not an error (actions are clipped).
   With --imitation-loss absolute, the absolute error instead: where the teacher's actions in
   like states split between two ways (one member's or its relief's), the squared error's
   best answer is their average, the absolute error's the way most of them take.
   With --stall-weight W, the steps a relief steers the teacher (an ensemble_policy teacher
   with a stall rule, from the episode's first stall on) weigh W times the others: they are few,
   and the student must tell a second stall from a first by its memory alone. With
   --stall-memory L, a linear readout of the student's memory, used in training only (the
   written file has none), learns the teacher's stall rule at every step (its pace average and
   stall count, colav.Policy.pace and .stalls), its squared error added L times to the loss:
   the memory is taught to keep what tells a second stall from a first. A perception that
   learns sees the steps' observations again, through its weights of the moment.
3. The student is written after every iteration (a temporary file, then renamed), checked
   against the file's own `step`, with INIT's interface, recorded observation settings and
   value layers (which do not act, and are not trained). So is STUDENT.pt.json: the run's
   settings and each iteration's episodes, loss and seconds, with "finished": true once the
   last iteration is written (the study runner's mark of a finished job).

    PYTHONPATH=build/python /usr/bin/python3 scripts/distill_policy.py TEACHER.pt INIT.pt \\
        --out STUDENT.pt [--iterations 8] [--seed 0] [...]

Everything random follows --seed (the worlds' episodes and the order of the sequences), so
the same seed and thread count give the same file. After every iteration the run's state (the
student, its perception, Adam's moments, the kept rollouts, the sequence order's
generator) is written to STUDENT.pt.state (a temporary file, then renamed; removed at the
end): the same command with --resume carries on after the last iteration written and ends with
the uninterrupted run's file, byte for byte. --out's folder is made if missing. --print-config
checks the arguments (not the files), prints the run's settings and exits. Bad input: one line
naming the argument or file, exit status 2.
"""

import argparse
import json
import os
import sys
import time

import numpy as np
import torch

import colav

RECURRENT = ("recurrent_weight_ih", "recurrent_weight_hh", "recurrent_bias_ih",
             "recurrent_bias_hh")
ACTOR_LAYER = "mlp_extractor_policy_net_{}_{}"
PERCEPTION = "features_extractor_"  # the prefix of the parameters `features` computes with
TRAP_SEARCH_WORLDS = 64  # training worlds INIT plays at once while the traps are searched for
TRAP_SEARCH_STEPS = 20000  # steps per search world at most (about 2,000 episodes in all)
TRAP_SEARCH_SEED = 1000000  # added to --seed: the search's worlds are not the iterations' ones
STALL_RULE = ("pace", "stalls")  # the teacher's stall-rule readings (colav.Policy) recorded
STATE_KEYS = {"settings", "iterations_done", "student", "perception", "optimiser",
              "generator", "rollouts", "log"}  # what save_state writes


class BadInput(Exception):
    pass


class ArgumentParser(argparse.ArgumentParser):
    """argparse's, its errors one line (BadInput) instead of the usage and a line."""

    def error(self, message):
        raise BadInput(message)


class Student(torch.nn.Module):
    """INIT's acting layers as trainable parameters, computed as its TorchScript `step` does
    (a GRU cell over [features], then tanh layers over [features, memory], then the action
    layer); `mean` is the action before the clip."""

    def __init__(self, named, stall_readout=False):
        super().__init__()
        self.actor_layers = sorted(int(name.split("_")[-2]) for name in named
                                   if name.startswith("mlp_extractor_policy_net_")
                                   and name.endswith("_weight"))
        names = list(RECURRENT) + [ACTOR_LAYER.format(k, kind) for k in self.actor_layers
                                   for kind in ("weight", "bias")]
        names += ["action_net_weight", "action_net_bias"]
        missing = [name for name in names if name not in named]
        if missing or not self.actor_layers:
            raise BadInput(f"no parameter {missing[0] if missing else 'of an actor layer'}")
        self.names = names
        self.weights = torch.nn.ParameterDict(
            {name: torch.nn.Parameter(named[name].detach().clone()) for name in names})
        # The memory's reading of the teacher's stall rule (--stall-memory); zeros at first,
        # so that making it draws nothing random.
        self.stall_readout = None
        if stall_readout:
            memory_size = named["recurrent_weight_hh"].shape[1]
            self.stall_readout = torch.nn.Linear(memory_size, len(STALL_RULE))
            torch.nn.init.zeros_(self.stall_readout.weight)
            torch.nn.init.zeros_(self.stall_readout.bias)

    def remember(self, features, memory):
        w = self.weights
        gates_in = torch.addmm(w["recurrent_bias_ih"], features, w["recurrent_weight_ih"].t())
        gates_memory = torch.addmm(w["recurrent_bias_hh"], memory, w["recurrent_weight_hh"].t())
        reset_in, update_in, new_in = gates_in.chunk(3, 1)
        reset_memory, update_memory, new_memory = gates_memory.chunk(3, 1)
        reset = torch.sigmoid(reset_in + reset_memory)
        update = torch.sigmoid(update_in + update_memory)
        candidate = torch.tanh(new_in + reset * new_memory)
        return (1 - update) * candidate + update * memory

    def mean(self, features, memory):
        w = self.weights
        hidden = torch.cat([features, memory], 1)
        for k in self.actor_layers:
            hidden = torch.tanh(torch.addmm(w[ACTOR_LAYER.format(k, "bias")], hidden,
                                            w[ACTOR_LAYER.format(k, "weight")].t()))
        return torch.addmm(w["action_net_bias"], hidden, w["action_net_weight"].t())

    def act(self, features, memory):
        """(clipped action, next memory), as the file's `step`."""
        memory = self.remember(features, memory)
        return torch.clamp(self.mean(features, memory), -1.0, 1.0), memory


IMITATION_LOSSES = ("squared", "absolute")  # --imitation-loss, the first the default


def imitation_loss(mean, target, weights, kind="squared"):
    """Squared (or absolute) error of the action mean, none past a bound the teacher's action
    sits on, each row weighed by `weights` [B] (weights of 1 give the plain mean to the bit)."""
    error = mean - target
    error = torch.where(target >= 1.0, torch.clamp(error, max=0.0), error)
    error = torch.where(target <= -1.0, torch.clamp(error, min=0.0), error)
    penalty = error * error if kind == "squared" else error.abs()
    return (penalty * weights[:, None]).mean()


class Rollout:
    """One iteration's steps: features [T, N, F], teacher actions [T, N, 2], the teacher's
    stall rule (STALL_RULE) [T, N, 2] (zeros without one), episode starts [T, N] and the
    student's memory before each step [T, N, H]; the last step's observations [N, O] check the
    written file. A perception that learns needs every step's observations [T, N, O] (else
    None: 6 rollouts of them take 300 MB)."""

    def __init__(self, steps, worlds, feature_size, memory_size, observation_size=0):
        self.last_observations = None
        self.observations = (torch.empty(steps, worlds, observation_size) if observation_size
                             else None)
        self.features = torch.empty(steps, worlds, feature_size)
        self.targets = torch.empty(steps, worlds, 2)
        self.stall_rule = torch.empty(steps, worlds, len(STALL_RULE))
        self.starts = torch.empty(steps, worlds, dtype=torch.bool)
        self.memory = torch.empty(steps, worlds, memory_size)

    @classmethod
    def restored(cls, fields):
        """A rollout from its fields as save_state wrote them."""
        rollout = cls(0, 0, 0, 0)
        vars(rollout).update(fields)
        return rollout


def finished_worlds(info):
    """The worlds whose episode ended on the step that returned `info`."""
    return np.nonzero(info.get("_episode_metrics", []))[0]


def timed_out(metrics, i):
    """Whether world i's finished episode ran out of time: neither at the goal nor collided."""
    return not metrics["goal_reached"][i] and not metrics["collision"][i]


def find_traps(args, settings):
    """Up to --traps training scenarios in which INIT alone times out, in the order found."""
    if args.traps == 0:
        return []
    searcher = colav.Policy(args.init)  # its own memories, one per search world
    seed = args.seed + TRAP_SEARCH_SEED
    envs = colav.make_vec(TRAP_SEARCH_WORLDS, seed=seed, num_threads=args.threads, **settings)
    obs, _ = envs.reset(seed=seed)
    starts = np.ones(TRAP_SEARCH_WORLDS, dtype=bool)
    episode = np.zeros(TRAP_SEARCH_WORLDS, dtype=np.int64)  # each world's episode under way
    traps = []
    for _ in range(TRAP_SEARCH_STEPS):
        obs, _, terminated, truncated, info = envs.step(searcher.act(obs, starts))
        starts = terminated | truncated
        for i in finished_worlds(info):
            if timed_out(info["episode_metrics"], i):
                episode_seed = colav.training_episode_seed(seed, int(i), int(episode[i]))
                traps.append(colav.training_scenario(episode_seed))
                if len(traps) == args.traps:
                    return traps
            episode[i] += 1
    return traps


class Worlds:
    """The worlds an iteration plays, as one vector: the paper's training worlds, then one world
    per trap replaying its scenario in every episode."""

    def __init__(self, args, settings, traps):
        self.sets = [colav.make_vec(args.worlds - len(traps), seed=args.seed,
                                    num_threads=args.threads, **settings)]
        if traps:
            self.sets.append(colav.make_vec(scenarios=traps, num_threads=args.threads,
                                            **settings))

    def reset(self, seed):
        return np.concatenate([envs.reset(seed=seed)[0] for envs in self.sets])

    def step(self, actions):
        """(observations, episode starts, [(progress, |cte|, collision, time-out)] of the
        episodes that ended), the paper's worlds' rows first; new arrays, which later steps
        do not overwrite."""
        observations, starts, episodes, first = [], [], [], 0
        for envs in self.sets:
            obs, _, terminated, truncated, info = envs.step(actions[first:first + envs.num_envs])
            first += envs.num_envs
            observations.append(obs)
            starts.append(terminated | truncated)
            metrics = info.get("episode_metrics")
            for i in finished_worlds(info):
                episodes.append((metrics["progress"][i], metrics["mean_abs_cte"][i],
                                 metrics["collision"][i], timed_out(metrics, i)))
        return np.concatenate(observations), np.concatenate(starts), episodes


def play(worlds, teacher, init, student, initial, args, iteration):
    """One iteration's rollout, and the driving policy's episodes."""
    memory_size = initial.shape[1]
    obs = worlds.reset(seed=args.seed + iteration)
    starts = np.ones(args.worlds, dtype=bool)
    memory = initial.expand(args.worlds, memory_size)
    rollout = None
    episodes = []
    for t in range(args.steps):
        observation = torch.from_numpy(obs)
        target = torch.from_numpy(teacher.act(obs, starts))
        stall_rule = torch.zeros(args.worlds, len(STALL_RULE))
        if teacher.has_stall_rule:
            stall_rule = torch.from_numpy(np.stack([getattr(teacher, name)
                                                    for name in STALL_RULE], 1))
        start = torch.from_numpy(starts)
        memory = torch.where(start[:, None], initial, memory)
        with torch.no_grad():
            features = init.features(observation)
            if rollout is None:
                rollout = Rollout(args.steps, args.worlds, features.shape[1], memory_size,
                                  observation.shape[1] if learns_perception(args) else 0)
            if rollout.observations is not None:
                rollout.observations[t] = observation
            rollout.features[t], rollout.targets[t] = features, target
            rollout.stall_rule[t] = stall_rule
            rollout.starts[t], rollout.memory[t] = start, memory
            rollout.last_observations = observation
            action, memory = student.act(features, memory)
        driving = target if iteration == 0 else action
        obs, starts, ended = worlds.step(driving.numpy().astype(np.float32))
        episodes += ended
    return rollout, episodes


def relieved(stall_rule):
    """Where a relief steered the teacher (it had stalled), from its recorded stall rule."""
    return stall_rule[..., STALL_RULE.index("stalls")] >= 1


def loss_weights(stall_rule, stall_weight):
    """Each step's weight in the loss: stall_weight where a relief steered the teacher, else 1."""
    return torch.where(relieved(stall_rule), stall_weight, 1.0)


def learns_perception(args):
    return args.perception_learning_rate > 0


def perception_parameters(init):
    """INIT's parameters that its `features` computes with, by name."""
    return {name: value for name, value in init.named_parameters()
            if name.startswith(PERCEPTION)}


def make_optimiser(student, init, args):
    """Adam over the student's parameters, and INIT's perception's at their own step size when
    it learns."""
    if not learns_perception(args):
        return torch.optim.Adam(student.parameters(), lr=args.learning_rate)
    perception = list(perception_parameters(init).values())
    for parameter in perception:
        parameter.requires_grad_(True)
    return torch.optim.Adam([{"params": student.parameters()},
                             {"params": perception, "lr": args.perception_learning_rate}],
                            lr=args.learning_rate)


def sequence_features(init, observations):
    """The features of observations [S, B, O] as INIT's perception of the moment sees them."""
    flat = init.features(observations.flatten(0, 1))
    return flat.view(observations.shape[0], observations.shape[1], -1)


def train(student, init, optimiser, rollouts, initial, args, generator):
    """EPOCHS passes over every sequence of the kept rollouts, the memory restarting at
    `initial` at each episode's start; the mean imitation loss and the mean squared error of
    the stall readout (0 without one) of the last pass. The features are the recorded ones,
    or, when the perception learns, its features of the recorded observations."""
    trained = [parameter for group in optimiser.param_groups for parameter in group["params"]]
    windows = [(r, t, n) for r in range(len(rollouts))
               for t in range(0, args.steps - args.sequence + 1, args.sequence // 2)
               for n in range(args.worlds)]
    for _ in range(args.epochs):
        order = torch.randperm(len(windows), generator=generator).tolist()
        total, readout_total, batches = 0.0, 0.0, 0
        for first in range(0, len(order), args.batch):
            chosen = [windows[i] for i in order[first:first + args.batch]]
            pick = lambda field: torch.stack(  # noqa: E731: [sequence, batch, ...]
                [getattr(rollouts[r], field)[t:t + args.sequence, n] for r, t, n in chosen], 1)
            features = (sequence_features(init, pick("observations")) if learns_perception(args)
                        else pick("features"))
            targets, starts = pick("targets"), pick("starts")
            stall_rule = pick("stall_rule")
            weights = loss_weights(stall_rule, args.stall_weight)
            memory = torch.stack([rollouts[r].memory[t, n] for r, t, n in chosen])
            loss, readout_error = 0.0, 0.0
            for j in range(args.sequence):
                if j > 0:
                    memory = torch.where(starts[j][:, None], initial, memory)
                memory = student.remember(features[j], memory)
                loss = loss + imitation_loss(student.mean(features[j], memory), targets[j],
                                             weights[j], args.imitation_loss)
                if student.stall_readout is not None:
                    error = student.stall_readout(memory) - stall_rule[j]
                    readout_error = readout_error + (error * error).mean()
            loss, readout_error = loss / args.sequence, readout_error / args.sequence
            optimiser.zero_grad()
            (loss + args.stall_memory * readout_error).backward()
            torch.nn.utils.clip_grad_norm_(trained, args.max_grad_norm)
            optimiser.step()
            total, batches = total + loss.item(), batches + 1
            readout_total += float(readout_error)
    return total / max(batches, 1), readout_total / max(batches, 1)


def write_student(init, student, rollout, path):
    """INIT's file with the student's weights (and its perception's, as they are), checked
    against its own step, then renamed."""
    parameters = dict(init.named_parameters())
    with torch.no_grad():
        for name in student.names:
            parameters[name].copy_(student.weights[name])
        memory = rollout.memory[-1]
        expected, _ = student.act(init.features(rollout.last_observations), memory)
    temporary = f"{path}.tmp"
    learning = [value for value in parameters.values() if value.requires_grad]
    for value in learning:  # the file's parameters load as INIT's do, not requiring gradients
        value.requires_grad_(False)
    init.save(temporary)
    for value in learning:
        value.requires_grad_(True)
    written = torch.jit.load(temporary)
    action, _ = written.step(rollout.last_observations, memory)
    if not torch.allclose(action, expected, atol=1e-5):
        os.remove(temporary)
        raise RuntimeError("the written student does not act as trained (internal error)")
    os.replace(temporary, path)


def episode_means(episodes):
    """The episodes that ended in a rollout: their count and means (% and m), as the summary
    file records them."""
    if not episodes:
        return {"episodes": 0}
    progress, cte, collided, late = (float(np.mean(column)) for column in zip(*episodes))
    return {"episodes": len(episodes), "progress": 100 * progress, "cte_m": cte,
            "collisions": 100 * collided, "time_outs": 100 * late}


def describe(means):
    """episode_means in a few words."""
    if not means["episodes"]:
        return "no episode to its end"
    return (f"{means['episodes']} episodes (progress {means['progress']:.1f} %, "
            f"cte {means['cte_m']:.1f} m, collisions {means['collisions']:.1f} %, "
            f"time-outs {means['time_outs']:.1f} %)")


def summary_path(args):
    return f"{args.out}.json"


def write_summary(args, log, finished):
    """STUDENT.pt.json: the settings and the iterations so far, a temporary file then renamed."""
    path = summary_path(args)
    with open(f"{path}.tmp", "w") as out:
        json.dump({"finished": finished, "settings": run_settings(args), "iterations": log,
                   "seconds": sum(entry["seconds"] for entry in log)}, out, indent=2)
        out.write("\n")
    os.replace(f"{path}.tmp", path)


def state_path(args):
    return f"{args.out}.state"


def run_settings(args):
    """What a resumed run must share with the one that wrote the state."""
    return {name: value for name, value in vars(args).items()
            if name not in ("resume", "print_config")}


def save_state(args, iteration, student, init, optimiser, generator, rollouts, log):
    """The run after `iteration` (0 first), to a temporary file, then renamed."""
    path = state_path(args)
    perception = {name: value.detach() for name, value in perception_parameters(init).items()}
    torch.save({"settings": run_settings(args), "iterations_done": iteration + 1,
                "student": student.state_dict(), "perception": perception,
                "optimiser": optimiser.state_dict(),
                "generator": generator.get_state(), "rollouts": [vars(r) for r in rollouts],
                "log": log}, f"{path}.tmp")
    os.replace(f"{path}.tmp", path)


def load_state(args, student, init, optimiser, generator):
    """(iterations done, kept rollouts, iteration log) of the state --resume carries on from."""
    path = state_path(args)
    try:
        state = torch.load(path)
    except Exception as error:  # noqa: BLE001: whatever torch.load fails on, the file is bad
        raise BadInput(f"--resume: {path}: {(str(error) or type(error).__name__).splitlines()[0]}")
    if not isinstance(state, dict) or set(state) != STATE_KEYS:
        raise BadInput(f"--resume: {path}: not a distill_policy.py state")
    differing = [name for name, value in run_settings(args).items()
                 if state["settings"].get(name) != value]
    if differing:
        raise BadInput(f"--resume: {path} was written with --{differing[0].replace('_', '-')} "
                       f"{state['settings'].get(differing[0])}, not {getattr(args, differing[0])}")
    student.load_state_dict(state["student"])
    with torch.no_grad():
        parameters = perception_parameters(init)
        for name, value in state["perception"].items():
            parameters[name].copy_(value)
    optimiser.load_state_dict(state["optimiser"])
    generator.set_state(state["generator"])
    return (state["iterations_done"], [Rollout.restored(fields) for fields in state["rollouts"]],
            state["log"])


def parse(argv):
    # No abbreviations: a misspelt option (a study file's, say) is refused, not taken for another.
    parser = ArgumentParser(description=__doc__.split("\n")[0], allow_abbrev=False)
    parser.add_argument("teacher", metavar="TEACHER.pt", help="the policy to imitate")
    parser.add_argument("init", metavar="INIT.pt", help="recurrent train_ppo policy to start from")
    parser.add_argument("--out", required=True, metavar="STUDENT.pt", help="the student's file")
    parser.add_argument("--iterations", type=int, default=8, help="DAgger iterations")
    parser.add_argument("--steps", type=int, default=2048, help="steps per world and iteration")
    parser.add_argument("--worlds", type=int, default=32, help="training worlds played at once")
    parser.add_argument("--traps", type=int, default=0,
                        help="worlds replaying training scenarios INIT times out in")
    parser.add_argument("--keep", type=int, default=6, help="last iterations trained on")
    parser.add_argument("--epochs", type=int, default=3, help="passes over the kept steps")
    parser.add_argument("--sequence", type=int, default=32, help="steps per training sequence")
    parser.add_argument("--batch", type=int, default=128, help="sequences per minibatch")
    parser.add_argument("--learning-rate", type=float, default=3e-4, help="Adam's step size")
    parser.add_argument("--perception-learning-rate", type=float, default=0.0,
                        help="the perception's step size (0: it stays as INIT's)")
    parser.add_argument("--max-grad-norm", type=float, default=0.5, help="gradient clip")
    parser.add_argument("--imitation-loss", choices=IMITATION_LOSSES,
                        default=IMITATION_LOSSES[0],
                        help="the error of the student's action mean to the teacher's action")
    parser.add_argument("--stall-weight", type=float, default=1.0,
                        help="loss weight of the steps a relief steers the teacher")
    parser.add_argument("--stall-memory", type=float, default=0.0,
                        help="loss weight of the memory's reading of the teacher's stall rule")
    parser.add_argument("--seed", type=int, default=0, help="worlds' episodes, sequence order")
    parser.add_argument("--threads", type=int, default=2, help="PyTorch and simulator threads")
    parser.add_argument("--resume", action="store_true",
                        help="carry on from STUDENT.pt.state, written by the same command")
    parser.add_argument("--print-config", action="store_true",
                        help="check the arguments (not the files), print the settings, exit")
    args = parser.parse_args(argv)
    bounds = {"iterations": (1, 1000), "steps": (2, 100000), "worlds": (1, 1024),
              "keep": (1, 1000), "epochs": (1, 100), "sequence": (2, 1000),
              "batch": (1, 100000), "seed": (0, 2**31 - 1), "threads": (1, 256)}
    for name, (low, high) in bounds.items():
        value = getattr(args, name)
        if not low <= value <= high:
            raise BadInput(f"--{name} {value}: expected {low} to {high}")
    if not 0 <= args.traps < args.worlds:
        raise BadInput(f"--traps {args.traps}: expected 0 to --worlds - 1 ({args.worlds - 1})")
    if args.sequence > args.steps:
        raise BadInput(f"--sequence {args.sequence}: longer than --steps {args.steps}")
    for name in ("learning_rate", "max_grad_norm", "stall_weight"):
        value = getattr(args, name)
        if not 0 < value < 1e3:
            raise BadInput(f"--{name.replace('_', '-')} {value}: expected a positive value")
    for name in ("stall_memory", "perception_learning_rate"):
        value = getattr(args, name)
        if not 0 <= value < 1e3:
            raise BadInput(f"--{name.replace('_', '-')} {value}: expected 0 or a positive value")
    if os.path.isdir(args.out):
        raise BadInput(f"--out {args.out}: a folder, not a file name")
    return args


def make_out_folder(args):
    folder = os.path.dirname(os.path.abspath(args.out))
    try:
        os.makedirs(folder, exist_ok=True)
    except OSError as error:
        raise BadInput(f"--out {args.out}: cannot make its folder ({error.strerror})")


def load(args):
    """The teacher, INIT as TorchScript, and the student made from INIT."""
    policies = []
    for path in (args.teacher, args.init):
        try:
            policies.append(colav.Policy(path))
        except (ValueError, RuntimeError) as error:
            raise BadInput(f"{path}: {str(error).splitlines()[0]}")
    teacher, init = policies
    if init.recurrent_size <= 0:
        raise BadInput(f"{args.init}: not a recurrent policy (train_ppo with "
                       "policy.recurrent_size > 0)")
    for name, used in (("stall_weight", args.stall_weight != 1.0),
                       ("stall_memory", args.stall_memory > 0)):
        if used and not teacher.has_stall_rule:
            raise BadInput(f"--{name.replace('_', '-')} {getattr(args, name)}: {args.teacher} "
                           "has no stall rule (ensemble_policy --stall-pace)")
    if init.observation_settings != teacher.observation_settings:
        raise BadInput(f"{args.init}: observation settings {init.observation_settings} differ "
                       f"from the teacher's {teacher.observation_settings}")
    try:
        student = Student(dict(init.module.named_parameters()), args.stall_memory > 0)
    except BadInput as error:
        raise BadInput(f"{args.init}: {error}")
    if learns_perception(args) and not perception_parameters(init.module):
        raise BadInput(f"--perception-learning-rate {args.perception_learning_rate}: "
                       f"{args.init} has no parameter {PERCEPTION}*")
    return teacher, init.module, student


def main(argv):
    try:
        args = parse(argv)
        if args.print_config:  # as STUDENT.pt.json records them (JSON is YAML)
            print("settings:")
            for name, value in run_settings(args).items():
                print(f"  {name}: {json.dumps(value)}")
            return 0
        teacher, init, student = load(args)
        generator = torch.Generator().manual_seed(args.seed)
        optimiser = make_optimiser(student, init, args)
        done, rollouts, log = (load_state(args, student, init, optimiser, generator)
                               if args.resume else (0, [], []))
        make_out_folder(args)
    except BadInput as error:
        print(f"distill_policy: error: {error}", file=sys.stderr)
        return 2
    torch.set_num_threads(args.threads)
    traps = find_traps(args, teacher.observation_settings)
    if args.traps:
        print(f"found {len(traps)} of {args.traps} traps", flush=True)
    worlds = Worlds(args, teacher.observation_settings, traps)
    initial = init.initial_state(1)  # the memory at an episode's start, as `evaluate` begins it
    kept = [min(i + 1, args.keep) for i in range(args.iterations)]  # rollouts trained on
    if done:
        print(f"resuming after iteration {done}/{args.iterations}", flush=True)
    began = time.monotonic()
    playing = training = 0.0  # seconds so far, in this process
    for iteration in range(done, args.iterations):
        started = time.monotonic()
        rollout, episodes = play(worlds, teacher, init, student, initial, args, iteration)
        rollouts = (rollouts + [rollout])[-args.keep:]
        played = time.monotonic()
        loss, readout_error = train(student, init, optimiser, rollouts, initial, args,
                                    generator)
        means = episode_means(episodes)
        relieved_share = (100 * float(relieved(rollout.stall_rule).float().mean())
                          if teacher.has_stall_rule else None)
        log.append({"iteration": iteration + 1, "driver": "teacher" if iteration == 0
                    else "student", **means, "relieved_steps": relieved_share, "loss": loss,
                    "stall_readout_error": readout_error if args.stall_memory else None,
                    "seconds": time.monotonic() - started})
        write_student(init, student, rollouts[-1], args.out)
        save_state(args, iteration, student, init, optimiser, generator, rollouts, log)
        write_summary(args, log, finished=False)
        playing, training = playing + played - started, training + time.monotonic() - played
        # Training time grows with the rollouts kept: ETA from the seconds per play and per
        # rollout trained on.
        left = (playing / (iteration + 1 - done) * (args.iterations - iteration - 1)
                + training / sum(kept[done:iteration + 1]) * sum(kept[iteration + 1:]))
        elapsed = time.monotonic() - began
        reliefs = (f", a relief steering the teacher in {relieved_share:.1f} % of steps"
                   if teacher.has_stall_rule else "")
        readout = f", stall readout error {readout_error:.4f}" if args.stall_memory else ""
        print(f"iteration {iteration + 1}/{args.iterations}: "
              f"{log[-1]['driver']} drove {describe(means)}"
              f"{reliefs}, loss {loss:.4f}{readout}, elapsed {elapsed:.0f} s, "
              f"ETA {left:.0f} s", flush=True)
    write_summary(args, log, finished=True)
    if os.path.exists(state_path(args)):
        os.remove(state_path(args))
    print(f"wrote {args.out}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
