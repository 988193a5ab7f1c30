"""scripts/distill_policy.py with a tiny recurrent train_ppo policy made here: distilled into
itself nothing changes; distilled from a policy that holds one action, the student learns it;
its trap worlds replay scenarios INIT times out in; the steps a teacher's relief steers weigh
--stall-weight, and --stall-memory teaches the memory the teacher's stall rule; with
--perception-learning-rate the perception learns too; --imitation-loss absolute learns the
absolute error; STUDENT.pt.json records each iteration and the end; an interrupted run resumes
to the same file; --print-config checks the arguments alone; bad input is refused."""

import importlib.util
import json
import subprocess
import sys

import numpy as np
import pytest
import torch

import colav
from conftest import HeldAction, SOURCE_DIR, run_program

SCRIPT = SOURCE_DIR / "scripts" / "distill_policy.py"
SMALL = ["--iterations", 3, "--steps", 64, "--worlds", 4, "--sequence", 8, "--batch", 16,
         "--epochs", 2, "--threads", 1]


def run(*args):
    return subprocess.run([sys.executable, str(SCRIPT), *map(str, args)], capture_output=True,
                          text=True)


@pytest.fixture(scope="module")
def recurrent_policy(tmp_path_factory):
    """A recurrent policy.pt (a memory of 4 values) as train_ppo writes one, barely trained."""
    folder = tmp_path_factory.mktemp("recurrent")
    run_program("train_ppo", "--out", folder / "run", "--steps", 128, "--envs", 2, "--set",
                "ppo.n_steps=64", "--set", "ppo.batch_size=64", "--set", "train.env_threads=1",
                "--set", "policy.recurrent_size=4")
    return folder / "run" / "policy.pt"


HELD = (0.3, -0.2)  # the held teacher's surge and rudder


@pytest.fixture(scope="module")
def held_policy(tmp_path_factory):
    """A teacher holding surge 0.3 and rudder -0.2 (HELD), under the recurrent policy's
    settings."""
    path = tmp_path_factory.mktemp("held") / "held.pt"
    torch.jit.script(HeldAction(*HELD)).save(str(path))
    path.with_name("held.pt.yaml").write_text("env:\n  closeness: log\n")
    return path


def actions(policy_file, observations):
    policy = torch.jit.load(str(policy_file))
    state = policy.initial_state(observations.shape[1])
    taken = []
    for observation in observations:
        action, state = policy.step(observation, state)
        taken.append(action)
    return torch.stack(taken)


def observations():
    """Three steps of 8 observations: navigation values and closeness in [0, 1]."""
    generator = torch.Generator().manual_seed(3)
    return torch.cat([torch.randn(3, 8, 6, generator=generator),
                      torch.rand(3, 8, 180, generator=generator)], 2)


def distance_from_held(policy_file):
    """The mean distance of a policy's actions from the held teacher's."""
    return (actions(policy_file, observations()) - torch.tensor(HELD)).abs().mean()


def losses(output):
    return [float(line.split("loss ")[1].split(",")[0]) for line in output.splitlines()
            if line.startswith("iteration")]


def test_a_policy_distilled_into_itself_does_not_change(recurrent_policy, tmp_path):
    # The teacher's actions are the student's own clipped means: no error anywhere, no step.
    result = run(recurrent_policy, recurrent_policy, "--out", tmp_path / "student.pt", *SMALL)
    assert result.returncode == 0, result.stderr
    assert losses(result.stdout) == [0.0, 0.0, 0.0], result.stdout
    assert torch.equal(actions(tmp_path / "student.pt", observations()),
                       actions(recurrent_policy, observations()))
    written = torch.jit.load(str(tmp_path / "student.pt"))
    assert written.recurrent_size == 4
    init = torch.jit.load(str(recurrent_policy))
    assert written.observation_settings == init.observation_settings


def learn_held_action(recurrent_policy, held_policy, out, *options, loss_falls_by):
    """A run imitating the held teacher at step size 0.01: it succeeds, its loss falls by the
    factor given, and its student acts at least twice as near the held action as INIT."""
    result = run(held_policy, recurrent_policy, "--out", out, "--learning-rate", 0.01, *options,
                 *SMALL)
    assert result.returncode == 0, result.stderr
    first, *_, last = losses(result.stdout)
    assert last < first / loss_falls_by, result.stdout
    assert distance_from_held(out) < distance_from_held(recurrent_policy) / 2


@pytest.fixture(scope="module")
def held_student(recurrent_policy, held_policy, tmp_path_factory):
    """The student of the held teacher, the squared error at step size 0.01."""
    out = tmp_path_factory.mktemp("held_student") / "a.pt"
    learn_held_action(recurrent_policy, held_policy, out, loss_falls_by=4)
    return out


def test_the_student_learns_the_teachers_action_and_the_same_seed_gives_the_same_file(
        recurrent_policy, held_policy, held_student, tmp_path):
    again = run(held_policy, recurrent_policy, "--out", tmp_path / "b.pt", "--learning-rate",
                0.01, *SMALL)
    assert again.returncode == 0, again.stderr
    assert torch.equal(actions(held_student, observations()),
                       actions(tmp_path / "b.pt", observations()))


def script_module():
    spec = importlib.util.spec_from_file_location("distill_policy", SCRIPT)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_the_trap_worlds_replay_scenarios_init_alone_times_out_in(recurrent_policy, held_policy,
                                                                  tmp_path):
    distill = script_module()
    args = distill.parse([str(held_policy), str(recurrent_policy), "--out",
                          str(tmp_path / "s.pt"), "--traps", "4", "--worlds", "8",
                          "--threads", "1", "--seed", "5"])
    settings = colav.Policy(str(recurrent_policy)).observation_settings
    traps = distill.find_traps(args, settings)
    assert len(traps) == 4
    # INIT alone, in each trap, ends its episode neither at the goal nor in a collision.
    envs = colav.make_vec(scenarios=traps, num_threads=1, **settings)
    init = colav.Policy(str(recurrent_policy))
    obs, _ = envs.reset()
    starts, ended = np.ones(4, dtype=bool), {}
    while len(ended) < 4:
        obs, _, terminated, truncated, info = envs.step(init.act(obs, starts))
        starts = terminated | truncated
        for i in np.nonzero(info.get("_episode_metrics", []))[0]:
            metrics = info["episode_metrics"]
            ended.setdefault(int(i), (metrics["goal_reached"][i], metrics["collision"][i],
                                      metrics["steps"][i]))
    limit = settings.get("max_steps", colav.env_settings()["max_steps"][0])
    assert all(not goal and not collided and steps == limit
               for goal, collided, steps in ended.values()), ended
    # An iteration's worlds: the paper's first, the traps last, each replaying its scenario.
    worlds = distill.Worlds(args, settings, traps)
    first = worlds.reset(seed=5)
    assert first.shape == (8, colav.OBSERVATION_SIZE)
    np.testing.assert_array_equal(first[:4], colav.make_vec(4, seed=5, **settings).reset(seed=5)[0])
    np.testing.assert_array_equal(first[4:], envs.reset()[0])


@pytest.fixture(scope="module")
def stalling_teacher(tmp_path_factory):
    """An ensemble whose first member holds the vessel still (surge -1) and whose relief holds
    the held policy's action, the stall rule averaging the pace over 2 steps: it stalls within
    a few steps of each episode's start."""
    folder = tmp_path_factory.mktemp("stalling")
    members = []
    for name, surge in (("still", -1.0), ("going", 0.3)):
        path = folder / f"{name}.pt"
        torch.jit.script(HeldAction(surge, -0.2)).save(str(path))
        path.with_name(f"{name}.pt.yaml").write_text("env:\n  closeness: log\n")
        members.append(path)
    run_program("ensemble_policy", "--out", folder / "teacher.pt", "--stall-pace", 0.1,
                "--stall-steps", 2, *members)
    return folder / "teacher.pt"


def test_the_loss_weighs_each_row():
    loss = script_module().imitation_loss
    mean, target = torch.zeros(2, 2), torch.tensor([[0.5, 0.0], [0.0, -0.5]])
    assert loss(mean, target, torch.ones(2)).item() == 0.125  # (0.25 + 0.25) / 4
    assert loss(mean, target, torch.tensor([1.0, 3.0])).item() == 0.25  # (0.25 + 0.75) / 4
    assert loss(mean, target, torch.ones(2), "absolute").item() == 0.25  # (0.5 + 0.5) / 4
    assert loss(mean, target, torch.tensor([1.0, 3.0]), "absolute").item() == 0.5  # (0.5+1.5)/4
    # Past a bound the teacher sits on, neither counts an error.
    beyond, bound = torch.tensor([[1.5, -2.0]]), torch.tensor([[1.0, -1.0]])
    assert loss(beyond, bound, torch.ones(1)).item() == 0.0
    assert loss(beyond, bound, torch.ones(1), "absolute").item() == 0.0


def test_the_absolute_loss_trains_toward_the_action_most_of_the_teachers_take():
    # One state, the teacher's rudder +0.5 in 3 of 4 rows and -0.5 in the other: the squared
    # error's answer is their mean (+0.25), the absolute error's the majority's (+0.5).
    loss = script_module().imitation_loss
    target = torch.tensor([[0.0, 0.5], [0.0, 0.5], [0.0, 0.5], [0.0, -0.5]])
    answers = {}
    for kind in ("squared", "absolute"):
        mean = torch.zeros(1, 2, requires_grad=True)
        optimiser = torch.optim.Adam([mean], lr=0.01)
        for _ in range(500):
            optimiser.zero_grad()
            loss(mean.expand(4, 2), target, torch.ones(4), kind).backward()
            optimiser.step()
        answers[kind] = mean[0, 1].item()
    assert answers["squared"] == pytest.approx(0.25, abs=0.02)
    assert answers["absolute"] == pytest.approx(0.5, abs=0.02)


def test_a_rollout_records_the_teachers_stall_rule_and_weighs_its_reliefs(recurrent_policy,
                                                                          stalling_teacher):
    distill = script_module()
    args = distill.parse([str(stalling_teacher), str(recurrent_policy), "--out", "s.pt",
                          "--worlds", "3", "--steps", "40", "--threads", "1",
                          "--stall-weight", "4"])
    teacher, init, student = distill.load(args)
    settings = teacher.observation_settings
    rollout, _ = distill.play(distill.Worlds(args, settings, []), teacher, init, student,
                              init.initial_state(1), args, 0)
    # The same steps again, the teacher's stall rule read at each.
    replayed, worlds = colav.Policy(str(stalling_teacher)), distill.Worlds(args, settings, [])
    obs, starts, rule = worlds.reset(seed=args.seed), np.ones(3, dtype=bool), []
    for _ in range(args.steps):
        actions = replayed.act(obs, starts)
        rule.append(np.stack([replayed.pace, replayed.stalls], 1))
        obs, starts, _ = worlds.step(actions)
    rule = torch.from_numpy(np.array(rule))
    assert torch.equal(rollout.stall_rule, rule)
    stalled = rule[:, :, 1] >= 1
    assert stalled.any() and not stalled.all()
    assert torch.equal(distill.relieved(rollout.stall_rule), stalled)
    torch.testing.assert_close(distill.loss_weights(rollout.stall_rule, args.stall_weight),
                               torch.where(stalled, 4.0, 1.0))


def test_a_run_with_a_stall_weight_reports_the_relieved_steps_and_trains_on_them(
        recurrent_policy, stalling_teacher, tmp_path):
    result = run(stalling_teacher, recurrent_policy, "--out", tmp_path / "s.pt",
                 "--stall-weight", 3, *SMALL)
    assert result.returncode == 0, result.stderr
    shares = [float(line.split("steering the teacher in ")[1].split(" %")[0])
              for line in result.stdout.splitlines() if line.startswith("iteration")]
    assert len(shares) == 3 and all(0 < share < 100 for share in shares), result.stdout
    plain = run(stalling_teacher, recurrent_policy, "--out", tmp_path / "plain.pt", *SMALL)
    assert plain.returncode == 0, plain.stderr
    assert not torch.equal(actions(tmp_path / "s.pt", observations()),
                           actions(tmp_path / "plain.pt", observations()))


def test_the_stall_readout_trains_the_memory_and_is_not_written(recurrent_policy,
                                                                stalling_teacher, tmp_path):
    # No gradient clipping, which would tie every parameter's step to the readout's gradient.
    unclipped = [*SMALL, "--max-grad-norm", 100]
    plain = run(stalling_teacher, recurrent_policy, "--out", tmp_path / "plain.pt", *unclipped)
    read = run(stalling_teacher, recurrent_policy, "--out", tmp_path / "read.pt",
               "--stall-memory", 1, *unclipped)
    assert plain.returncode == 0 and read.returncode == 0, plain.stderr + read.stderr
    errors = [float(line.split("stall readout error ")[1].split(",")[0])
              for line in read.stdout.splitlines() if line.startswith("iteration")]
    assert len(errors) == 3 and errors[-1] < errors[0], read.stdout
    plain_parameters = dict(torch.jit.load(str(tmp_path / "plain.pt")).named_parameters())
    read_parameters = dict(torch.jit.load(str(tmp_path / "read.pt")).named_parameters())
    assert read_parameters.keys() == plain_parameters.keys()  # INIT's, no readout
    # The readout's error reaches the memory's weights, not the readout alone.
    assert not torch.equal(read_parameters["recurrent_weight_hh"],
                           plain_parameters["recurrent_weight_hh"])


def perception(policy_file):
    return script_module().perception_parameters(torch.jit.load(str(policy_file)))


def test_the_perception_learns_at_its_own_step_size_and_only_when_asked(
        recurrent_policy, held_policy, tmp_path):
    init = perception(recurrent_policy)
    assert init, "the recurrent policy has no perception parameter"
    fixed = run(held_policy, recurrent_policy, "--out", tmp_path / "fixed.pt", *SMALL)
    learnt = run(held_policy, recurrent_policy, "--out", tmp_path / "learnt.pt",
                 "--perception-learning-rate", 0.01, *SMALL)
    assert fixed.returncode == 0 and learnt.returncode == 0, fixed.stderr + learnt.stderr
    for name, value in perception(tmp_path / "fixed.pt").items():
        assert torch.equal(value, init[name]), name
    learnt_perception = perception(tmp_path / "learnt.pt")
    assert all(not torch.equal(value, init[name]) for name, value in learnt_perception.items())
    # Written as INIT's are: loaded, no parameter requires a gradient.
    assert not any(value.requires_grad for value in learnt_perception.values())
    # The acting layers learnt from the same teacher, but through other features.
    assert not torch.equal(actions(tmp_path / "learnt.pt", observations()),
                           actions(tmp_path / "fixed.pt", observations()))


def test_the_optimiser_steps_the_perception_at_its_own_rate(recurrent_policy, held_policy):
    distill = script_module()
    common = [str(held_policy), str(recurrent_policy), "--out", "s.pt", "--learning-rate", "0.002"]
    _, init, student = distill.load(distill.parse(common))
    fixed = distill.make_optimiser(student, init, distill.parse(common))
    assert [group["lr"] for group in fixed.param_groups] == [0.002]
    assert fixed.param_groups[0]["params"] == list(student.parameters())
    args = distill.parse(common + ["--perception-learning-rate", "0.005"])
    learning = distill.make_optimiser(student, init, args)
    assert [group["lr"] for group in learning.param_groups] == [0.002, 0.005]
    perception_parameters = distill.perception_parameters(init)
    assert all(value.requires_grad for value in perception_parameters.values())
    assert learning.param_groups[1]["params"] == list(perception_parameters.values())
    # A sequence's features, computed at once, are each step's.
    sequence = observations()
    expected = torch.stack([init.features(step) for step in sequence])
    torch.testing.assert_close(distill.sequence_features(init, sequence), expected)


def test_an_absolute_loss_run_learns_the_teachers_action(recurrent_policy, held_policy,
                                                        held_student, tmp_path):
    learn_held_action(recurrent_policy, held_policy, tmp_path / "a.pt", "--imitation-loss",
                      "absolute", loss_falls_by=2)
    assert not torch.equal(actions(tmp_path / "a.pt", observations()),
                           actions(held_student, observations()))


def test_a_run_with_traps_reports_them(recurrent_policy, held_policy, tmp_path):
    result = run(held_policy, recurrent_policy, "--out", tmp_path / "s.pt", "--traps", 1, *SMALL)
    assert result.returncode == 0, result.stderr
    assert result.stdout.startswith("found 1 of 1 traps\n"), result.stdout
    assert (tmp_path / "s.pt").exists()


@pytest.mark.parametrize("learning", [[], ["--perception-learning-rate", 0.01]],
                         ids=["perception fixed", "perception learning"])
def test_an_interrupted_run_resumes_to_the_same_file(recurrent_policy, held_policy, tmp_path,
                                                     learning):
    options = [*SMALL, *learning]
    whole = run(held_policy, recurrent_policy, "--out", tmp_path / "whole.pt", "--traps", 1,
                *options)
    assert whole.returncode == 0, whole.stderr
    assert not (tmp_path / "whole.pt.state").exists()
    # Stopped as soon as the second of three iterations is reported, then run again.
    command = [sys.executable, str(SCRIPT), str(held_policy), str(recurrent_policy), "--out",
               str(tmp_path / "cut.pt"), "--traps", "1", *map(str, options)]
    process = subprocess.Popen(command, stdout=subprocess.PIPE, text=True)
    for line in process.stdout:
        if line.startswith("iteration 2/3"):
            process.kill()
            break
    process.wait()
    assert (tmp_path / "cut.pt.state").exists()
    assert json.loads((tmp_path / "cut.pt.json").read_text())["finished"] is False
    other = subprocess.run(command + ["--resume", "--seed", "1"], capture_output=True, text=True)
    assert "cut.pt.state was written with --seed 0, not 1" in refusal(other)
    resumed = subprocess.run(command + ["--resume"], capture_output=True, text=True)
    assert resumed.returncode == 0, resumed.stderr
    assert "resuming after iteration 2/3" in resumed.stdout, resumed.stdout
    reported = [line.split(":")[0] for line in resumed.stdout.splitlines()
                if line.startswith("iteration")]
    assert reported == ["iteration 3/3"], resumed.stdout
    assert not (tmp_path / "cut.pt.state").exists()
    summary = json.loads((tmp_path / "cut.pt.json").read_text())
    assert summary["finished"] is True
    assert [i["iteration"] for i in summary["iterations"]] == [1, 2, 3]
    whole_parameters = dict(torch.jit.load(str(tmp_path / "whole.pt")).named_parameters())
    for name, value in torch.jit.load(str(tmp_path / "cut.pt")).named_parameters():
        assert torch.equal(value, whole_parameters[name]), name


def refusal(result):
    assert result.returncode == 2, result.stdout + result.stderr
    assert len(result.stderr.strip().splitlines()) == 1, result.stderr
    return result.stderr


def test_bad_input_is_refused_before_any_work(recurrent_policy, held_policy, tmp_path):
    out = tmp_path / "student.pt"
    assert "not a recurrent policy" in refusal(run(recurrent_policy, held_policy, "--out", out))
    linear = tmp_path / "linear.pt"
    torch.jit.script(HeldAction(*HELD)).save(str(linear))
    linear.with_name("linear.pt.yaml").write_text("env:\n  closeness: linear\n")
    assert "differ from the teacher's" in refusal(run(linear, recurrent_policy, "--out", out))
    assert "missing.pt" in refusal(run(tmp_path / "missing.pt", recurrent_policy, "--out", out))
    assert "--sequence 99: longer than --steps 64" in refusal(
        run(held_policy, recurrent_policy, "--out", out, "--steps", 64, "--sequence", 99))
    assert "--worlds 0" in refusal(run(held_policy, recurrent_policy, "--out", out,
                                       "--worlds", 0))
    assert "--stall-weight 2.0: " + str(held_policy) + " has no stall rule" in refusal(
        run(held_policy, recurrent_policy, "--out", out, "--stall-weight", 2))
    assert "--stall-weight 0.0: expected a positive value" in refusal(
        run(held_policy, recurrent_policy, "--out", out, "--stall-weight", 0))
    assert "--stall-memory 1.0: " + str(held_policy) + " has no stall rule" in refusal(
        run(held_policy, recurrent_policy, "--out", out, "--stall-memory", 1))
    assert "--stall-memory -1.0: expected 0 or a positive value" in refusal(
        run(held_policy, recurrent_policy, "--out", out, "--stall-memory", -1))
    assert "argument --imitation-loss: invalid choice: 'huber'" in refusal(
        run(held_policy, recurrent_policy, "--out", out, "--imitation-loss", "huber"))
    assert "--perception-learning-rate -1.0: expected 0 or a positive value" in refusal(
        run(held_policy, recurrent_policy, "--out", out, "--perception-learning-rate", -1))
    assert "--traps 4: expected 0 to --worlds - 1 (3)" in refusal(
        run(held_policy, recurrent_policy, "--out", out, "--worlds", 4, "--traps", 4))
    assert "--resume: " + str(out) + ".state" in refusal(
        run(held_policy, recurrent_policy, "--out", out, "--resume"))
    (tmp_path / "a_file").write_text("")
    assert "--out " + str(tmp_path / "a_file" / "s.pt") + ": cannot make its folder" in refusal(
        run(held_policy, recurrent_policy, "--out", tmp_path / "a_file" / "s.pt"))
    assert "--out " + str(tmp_path) + ": a folder, not a file name" in refusal(
        run(held_policy, recurrent_policy, "--out", tmp_path))
    assert "unrecognized arguments: --iteration" in refusal(
        run(held_policy, recurrent_policy, "--out", out, "--iteration", 2, "--print-config"))
    assert not out.exists()


def test_print_config_checks_the_arguments_only_and_makes_nothing(tmp_path):
    # The study runner checks a student's job this way before its teacher exists.
    out = tmp_path / "students" / "s.pt"
    result = run(tmp_path / "teacher.pt", tmp_path / "init.pt", "--out", out, "--traps", 2,
                 "--print-config")
    assert result.returncode == 0, result.stderr
    assert result.stdout.startswith("settings:\n"), result.stdout
    assert "\n  traps: 2\n" in result.stdout and f'\n  out: "{out}"\n' in result.stdout
    names = [line.split(":")[0].strip() for line in result.stdout.splitlines()[1:]]
    assert "traps" in names and "resume" not in names and "print_config" not in names, names
    assert not (tmp_path / "students").exists()
    assert "--traps 9: expected 0 to --worlds - 1 (3)" in refusal(
        run(tmp_path / "teacher.pt", tmp_path / "init.pt", "--out", out, "--worlds", 4,
            "--traps", 9, "--print-config"))


def test_the_summary_records_each_iteration_and_the_end(recurrent_policy, held_policy,
                                                        tmp_path):
    out = tmp_path / "made" / "here" / "s.pt"
    result = run(held_policy, recurrent_policy, "--out", out, *SMALL)
    assert result.returncode == 0, result.stderr
    summary = json.loads(out.with_name("s.pt.json").read_text())
    assert summary["finished"] is True
    assert summary["settings"]["iterations"] == 3 and summary["settings"]["out"] == str(out)
    iterations = summary["iterations"]
    assert [i["iteration"] for i in iterations] == [1, 2, 3]
    assert [i["driver"] for i in iterations] == ["teacher", "student", "student"]
    assert [i["loss"] for i in iterations] == pytest.approx(losses(result.stdout), abs=5e-5)
    assert all(i["relieved_steps"] is None and i["seconds"] > 0 for i in iterations)
    assert summary["seconds"] == pytest.approx(sum(i["seconds"] for i in iterations))
    # --print-config prints the settings the summary records (the study compares the two).
    printed = run(held_policy, recurrent_policy, "--out", out, *SMALL, "--print-config")
    lines = printed.stdout.splitlines()
    assert lines[0] == "settings:", printed.stdout
    assert {name.strip(): json.loads(value) for name, value in
            (line.split(": ", 1) for line in lines[1:])} == summary["settings"]
