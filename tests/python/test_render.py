"""colav.Env(render_mode="rgb_array").render(): the scene as pixels, drawn as `simulate --gif`
draws its frames (eval/replay/scene_frame.h): the vessel in the middle of a 300 m wide view."""

import numpy as np
import pytest

import colav
from conftest import SOURCE_DIR

HEAD_ON = SOURCE_DIR / "configs" / "scenarios" / "head-on.yaml"
VESSEL = (0x1F, 0x77, 0xB4)  # our hull (the first run's colour)
OBSTACLE = (0xC0, 0x39, 0x2B)  # moving vessels' hulls
PIXELS_PER_METRE = colav.RENDER_SIZE / 300.0


def pixels_of_colour(frame, centre, radius, colour):
    x, y = round(centre[0]), round(centre[1])
    patch = frame[max(0, y - radius) : y + radius + 1, max(0, x - radius) : x + radius + 1]
    return int(np.all(patch == np.array(colour, dtype=np.uint8), axis=-1).sum())


def pixel_of(point, vessel):
    """The follow view: the vessel at the centre, y up."""
    half = colav.RENDER_SIZE / 2
    return (half + (point[0] - vessel[0]) * PIXELS_PER_METRE,
            half - (point[1] - vessel[1]) * PIXELS_PER_METRE)


def test_frame_is_an_rgb_array_with_the_vessel_in_the_middle():
    env = colav.make(scenario=HEAD_ON, render_mode="rgb_array")
    env.reset()
    frame = env.render()
    assert isinstance(frame, np.ndarray) and frame.dtype == np.uint8
    assert frame.shape == (colav.RENDER_SIZE, colav.RENDER_SIZE, 3)
    centre = (colav.RENDER_SIZE / 2, colav.RENDER_SIZE / 2)
    assert pixels_of_colour(frame, centre, 4, VESSEL) > 10


def test_frame_shows_the_oncoming_vessel_where_it_is():
    env = colav.make(scenario=HEAD_ON, render_mode="rgb_array")
    env.reset()
    steps = 250
    for _ in range(steps):
        env.step(np.array([1.0, 0.0]))
    vessel = env.state()["vessel"][:2]
    # head-on.yaml: the vessel starts at (0, 380) and moves south at 0.5 m/s.
    obstacle = (0.0, 380.0 - 0.5 * steps)
    frame = env.render()
    assert pixels_of_colour(frame, pixel_of(obstacle, vessel), 4, OBSTACLE) > 10
    assert pixels_of_colour(frame, pixel_of(vessel, vessel), 4, VESSEL) > 10
    # Nothing red where there is no obstacle: the same distance behind the vessel.
    behind = (vessel[0], 2 * vessel[1] - obstacle[1])
    assert pixels_of_colour(frame, pixel_of(behind, vessel), 4, OBSTACLE) == 0


def test_frames_are_deterministic():
    frames = []
    for _ in range(2):
        env = colav.make(seed=5, render_mode="rgb_array")
        env.reset()
        for _ in range(20):
            env.step(np.array([0.5, 0.2]))
        frames.append(env.render())
    assert np.array_equal(frames[0], frames[1])


def test_render_modes():
    assert colav.Env.metadata["render_modes"] == ["rgb_array"]
    assert colav.make(seed=0).render() is None
    with pytest.raises(ValueError, match="render_mode"):
        colav.make(seed=0, render_mode="human")
    with pytest.raises(RuntimeError, match="reset"):
        colav.make(seed=0, render_mode="rgb_array").render()
