"""Checks replay pages as headless Chromium showed them (replay_browser_test.sh). Uses only the
standard library (the PNG is decoded with zlib).

simulate: the page's self-check against the `simulate` trace, the screenshots' pixels where the
trace puts the vessel, and playback (#step=10&play=1, 2 s of the browser's virtual time at 25
steps/s).
evaluate: the pages `evaluate --replay` chose, each with every model's run as long as
episodes.csv says.

usage: replay_browser_check.py simulate TRACE.csv START_DOM COLLISION_DOM FOLLOW.png SCENE_DOM SCENE.png PLAYING_DOM
       replay_browser_check.py evaluate EPISODES.csv FIRST COLLIDED REPLAY_DIR DOM...
"""

import csv
import html
import json
import os
import re
import struct
import sys
import zlib

VESSEL = (0x1F, 0x77, 0xB4)  # the first model's hull (eval/replay/replay_page.html COLOURS.runs[0])
OBSTACLE = (0xC0, 0x39, 0x2B)  # moving vessels' hulls
COLLISION = (0xD6, 0x27, 0x28)  # the ring around a vessel that collided
CANVAS_SIZE = 640


def fail(message):
    print("replay_browser_check: " + message)
    sys.exit(1)


def trace_rows(path):
    with open(path, newline="") as handle:
        return list(csv.DictReader(handle))


def self_check(dom_path):
    text = open(dom_path, encoding="utf-8").read()
    found = re.search(r'<pre id="selfcheck">(.*?)</pre>', text, re.S)
    if not found or not found.group(1).strip():
        fail(dom_path + ": no self-check in the page's DOM")
    return json.loads(html.unescape(found.group(1)))


def png_pixels(path):
    """(width, height, rows of RGB tuples) of an 8-bit RGB or RGBA, non-interlaced PNG."""
    data = open(path, "rb").read()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        fail(path + ": not a PNG")
    at, idat = 8, b""
    while at < len(data):
        length, kind = struct.unpack(">I4s", data[at : at + 8])
        body = data[at + 8 : at + 8 + length]
        if kind == b"IHDR":
            width, height, depth, colour, _, _, interlace = struct.unpack(">IIBBBBB", body)
        elif kind == b"IDAT":
            idat += body
        at += 12 + length
    if depth != 8 or colour not in (2, 6) or interlace:
        fail(f"{path}: unexpected PNG format (depth {depth}, colour type {colour})")
    channels = 3 if colour == 2 else 4
    raw = zlib.decompress(idat)
    stride = width * channels
    rows, previous = [], bytearray(stride)
    for y in range(height):
        kind = raw[y * (stride + 1)]
        line = bytearray(raw[y * (stride + 1) + 1 : (y + 1) * (stride + 1)])
        for x in range(stride):
            left = line[x - channels] if x >= channels else 0
            up = previous[x]
            corner = previous[x - channels] if x >= channels else 0
            if kind == 1:
                line[x] = (line[x] + left) & 255
            elif kind == 2:
                line[x] = (line[x] + up) & 255
            elif kind == 3:
                line[x] = (line[x] + (left + up) // 2) & 255
            elif kind == 4:
                p = left + up - corner
                pa, pb, pc = abs(p - left), abs(p - up), abs(p - corner)
                line[x] = (line[x] + (left if pa <= pb and pa <= pc else up if pb <= pc else corner)) & 255
        rows.append([tuple(line[i : i + 3]) for i in range(0, stride, channels)])
        previous = line
    return width, height, rows


def pixels_of_colour(rows, centre, radius, colour):
    cx, cy = round(centre[0]), round(centre[1])
    return sum(
        1
        for y in range(max(0, cy - radius), min(len(rows), cy + radius + 1))
        for x in range(max(0, cx - radius), min(len(rows[0]), cx + radius + 1))
        if rows[y][x] == colour
    )


def page_pixel(check, x, y):
    """The page's documented view transform: (W/2 + (x - cx) s, H/2 - (y - cy) s) on the canvas."""
    view, canvas = check["view"], check["canvas"]
    return (
        canvas["left"] + CANVAS_SIZE / 2 + (x - view["cx"]) * view["s"],
        canvas["top"] + CANVAS_SIZE / 2 - (y - view["cy"]) * view["s"],
    )


def position(row):
    return float(row["x"]), float(row["y"])


def close(a, b, tolerance=1e-3):
    return all(abs(u - v) <= tolerance * (1 + abs(v)) for u, v in zip(a, b))


def check_frames_and_positions(rows, check):
    if not check["ok"]:
        fail("the page's self-check failed: " + "; ".join(check["errors"]))
    run = check["runs"][0]
    if check["frames"] != len(rows) or run["frames"] != len(rows):
        fail(f"page shows {check['frames']} frames, the trace has {len(rows)} rows")
    if len(run["positions"]) < 3:
        fail("the self-check reports fewer than 3 positions")
    for step, xy in run["positions"].items():
        if not close(xy, position(rows[int(step)])):
            fail(f"step {step}: page position {xy}, trace {position(rows[int(step)])}")
    collisions = [int(row["step"]) for row in rows if row["collision"] == "1"]
    if run["collisions"] != collisions:
        fail(f"page collisions {run['collisions']}, trace {collisions}")
    return collisions


def check_follow_screenshot(rows, check, png, step):
    if check["step"] != step:
        fail(f"#step={step} shows step {check['step']}")
    vessel = position(rows[step])
    # The follow view is centred on the vessel's recorded position.
    if check["view"]["mode"] != "follow" or not close((check["view"]["cx"], check["view"]["cy"]), vessel):
        fail(f"follow view centred on {check['view']}, vessel at {vessel}")
    _, _, pixels = png_pixels(png)
    at = page_pixel(check, *vessel)
    for name, colour, minimum in (("vessel", VESSEL, 10), ("obstacle", OBSTACLE, 10), ("collision ring", COLLISION, 20)):
        count = pixels_of_colour(pixels, at, 20, colour)
        if count < minimum:
            fail(f"{png}: {count} pixels of the {name}'s colour near {at} (step {step}), expected >= {minimum}")
        print(f"{png}: {count} {name} pixels within 20 px of {tuple(round(v) for v in at)}")


def check_scene_screenshot(rows, check, png, step):
    if check["view"]["mode"] != "scene":
        fail("#view=scene shows view " + check["view"]["mode"])
    _, _, pixels = png_pixels(png)
    at = page_pixel(check, *position(rows[step]))
    count = pixels_of_colour(pixels, at, 6, VESSEL)
    if count < 10:
        fail(f"{png}: {count} vessel pixels near {at} in the scene view")
    print(f"{png}: {count} vessel pixels near {tuple(round(v) for v in at)}")


def check_playback(check):
    # 2 s at 25 steps/s from step 10 (50 steps), give or take the page's load and timer ticks.
    if not 10 + 25 <= check["step"] <= 10 + 60:
        fail(f"after 2 s of playing from step 10 the page shows step {check['step']}")
    print(f"playing: step 10 -> {check['step']} in 2 s")


def check_simulate(trace, start_dom, collision_dom, follow_png, scene_dom, scene_png, playing_dom):
    rows = trace_rows(trace)
    collisions = check_frames_and_positions(rows, self_check(start_dom))
    if not collisions:
        fail("the episode has no collision to scrub to")
    check_frames_and_positions(rows, self_check(collision_dom))
    check_follow_screenshot(rows, self_check(collision_dom), follow_png, collisions[0])
    check_scene_screenshot(rows, self_check(scene_dom), scene_png, collisions[0])
    check_playback(self_check(playing_dom))
    print(f"replay_browser_check: {len(rows)} frames, collision at step {collisions[0]}: ok")


def chosen_scenarios(episodes, first, collided):
    """evaluate --replay's choice: the first `first` test scenarios, then the first `collided`
    others in which some model collided."""
    scenarios = list(dict.fromkeys(row["scenario"] for row in episodes))
    hit = {row["scenario"] for row in episodes if row["collision"] == "1"}
    others = [s for s in scenarios[first:] if s in hit][:collided]
    return scenarios[:first] + others


def check_evaluate(episodes_csv, first, collided, replay_dir, *doms):
    episodes = trace_rows(episodes_csv)
    chosen = chosen_scenarios(episodes, int(first), int(collided))
    written = sorted(name[: -len(".html")] for name in os.listdir(replay_dir))
    if written != sorted(chosen):
        fail(f"evaluate wrote replays of {written}, expected {sorted(chosen)}")
    for dom in doms:
        check = self_check(dom)
        if not check["ok"]:
            fail(dom + ": the page's self-check failed: " + "; ".join(check["errors"]))
        rows = [row for row in episodes if row["scenario"] == check["scene"]]
        labels = [run["label"] for run in check["runs"]]
        if labels != [row["model"] for row in rows]:
            fail(f"{dom}: models {labels}, episodes.csv has {[row['model'] for row in rows]}")
        for run, row in zip(check["runs"], rows):
            if run["frames"] != int(row["steps"]) + 1:
                fail(f"{dom}: {run['label']} has {run['frames']} frames for {row['steps']} steps")
            if bool(run["collisions"]) != (row["collision"] == "1"):
                fail(f"{dom}: {run['label']} collisions {run['collisions']}, episodes.csv {row['collision']}")
            if abs(run["cumulative_reward"] - float(row["reward"])) > 1e-3 * (1 + abs(float(row["reward"]))):
                fail(f"{dom}: {run['label']} reward {run['cumulative_reward']}, episodes.csv {row['reward']}")
        print(f"{dom}: {check['scene']}, models {labels}: ok")
    print(f"replay_browser_check: evaluate wrote {chosen}: ok")


if __name__ == "__main__":
    checks = {"simulate": (check_simulate, 7), "evaluate": (check_evaluate, None)}
    if len(sys.argv) < 2 or sys.argv[1] not in checks:
        fail("usage: see the docstring of " + sys.argv[0])
    check, count = checks[sys.argv[1]]
    if count is not None and len(sys.argv) - 2 != count:
        fail(f"{sys.argv[1]}: expected {count} arguments")
    check(*sys.argv[2:])
