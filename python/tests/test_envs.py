"""SpherusEnv: the Gymnasium-style API's shapes and types, rewards, reset determinism."""

import math

import numpy as np
import pytest

import thyrix
from conftest import TOLERANCE
from thyrix.envs import SpherusEnv


def random_actions(count, seed=0):
    return np.random.default_rng(seed).uniform(0.0, 1.0, size=(count, 5))


def run(env, actions, seed):
    observation, _ = env.reset(seed=seed)
    trace = [observation]
    rewards = []
    for action in actions:
        observation, reward, _, _, _ = env.step(action)
        trace.append(observation)
        rewards.append(reward)
    return np.array(trace), np.array(rewards)


def test_spaces_and_the_api_shapes_and_types():
    env = SpherusEnv(seed=1, steps=3)
    assert env.observation_space.shape == (35,)
    assert env.action_space.shape == (5,)
    assert env.observation_space.dtype == thyrix.real_dtype
    assert float(env.action_space.low.min()) == 0.0 and float(env.action_space.high.max()) == 1.0
    observation, info = env.reset()
    assert isinstance(observation, np.ndarray) and observation.shape == (35,)
    assert observation.dtype == thyrix.real_dtype
    assert isinstance(info, dict)
    for step in range(3):
        action = env.action_space.sample()
        assert env.action_space.contains(action)
        observation, reward, terminated, truncated, info = env.step(action)
        assert observation.shape == (35,) and env.observation_space.contains(observation)
        assert isinstance(reward, float)
        assert terminated is False
        assert truncated is (step == 2)
        assert isinstance(info, dict)


def test_rewards_sum_to_the_distance_covered():
    env = SpherusEnv(seed=4, steps=300)
    env.reset()
    start = np.array(env.agent_centre)
    total = 0.0
    for _ in range(300):
        _, reward, _, truncated, _ = env.step([1.0, 0.0, 1.0, 0.0, 0.5])
        total += reward
    end = np.array(env.agent_centre)
    assert truncated
    tolerance = 1e-9 if TOLERANCE < 1e-9 else 1e-3
    assert total == pytest.approx(float(np.linalg.norm(end - start)), rel=tolerance)
    # Both rockets pushing forward at 1 N on 1 N s/m circles: about 1 m/s for 3 s, less where
    # balls are in the way.
    assert 0.5 < total <= 3.0 + 1e-6


def test_the_same_seed_and_actions_give_the_same_episode():
    actions = random_actions(200)
    a, ra = run(SpherusEnv(steps=1000), actions, seed=11)
    b, rb = run(SpherusEnv(steps=1000), actions, seed=11)
    c, _ = run(SpherusEnv(steps=1000), actions, seed=12)
    assert np.array_equal(a, b) and np.array_equal(ra, rb)
    assert not np.array_equal(a, c)


def test_an_unseeded_reset_continues_the_stream_deterministically():
    first, second = SpherusEnv(steps=5), SpherusEnv(steps=5)
    episodes = []
    for env in (first, second):
        env.reset(seed=3)
        starts = []
        for _ in range(3):
            starts.append(env.agent_centre)
            env.reset()
        episodes.append(starts)
    assert episodes[0] == episodes[1]
    assert len(set(episodes[0])) == 3  # each episode starts at its own pose


def test_the_constructor_seed_is_the_first_reset_seed():
    a, b = SpherusEnv(seed=21), SpherusEnv()
    a.reset()
    b.reset(seed=21)
    assert a.agent_centre == b.agent_centre


def test_render_returns_svg_without_a_display():
    env = SpherusEnv(seed=2)
    env.reset()
    env.step([1, 0, 1, 0, 1])
    svg = env.render()
    assert svg.startswith("<?xml") and "</svg>" in svg


def test_bad_actions_and_options():
    env = SpherusEnv(seed=1)
    with pytest.raises(ValueError, match="reset"):
        env.step([0, 0, 0, 0, 0])
    env.reset()
    with pytest.raises(ValueError, match=r"action must have shape \(5,\), not \(4,\)"):
        env.step([0, 0, 0, 0])
    with pytest.raises(ValueError, match="action must be finite"):
        env.step([0, 0, math.inf, 0, 0])
    with pytest.raises(TypeError, match="action must be an array of real numbers"):
        env.step(["x"] * 5)
    with pytest.raises(TypeError, match="action must be an array of real numbers"):
        env.step(np.array([1j] * 5))
    with pytest.raises(ValueError, match="steps"):
        SpherusEnv(steps=0)
    with pytest.raises(ValueError, match="--task must be distance or clear"):
        SpherusEnv(task="fly")
    with pytest.raises(TypeError, match="seed"):
        env.reset(seed="7")


def test_gymnasium_checker_when_gymnasium_is_installed():
    gymnasium = pytest.importorskip("gymnasium")
    from gymnasium.utils.env_checker import check_env

    check_env(SpherusEnv(seed=1, steps=50))
    env = gymnasium.make("thyrix/Spherus-v0", steps=10)
    env.reset(seed=1)


def test_episode_k_is_laid_out_as_an_evaluation_episode_of_generation_k():
    task = thyrix.SpherusTask("distance", 10, "ff")
    env = SpherusEnv(steps=10)
    env.reset(seed=31)
    for episode in range(3):
        world = task.make_world([0.0] * task.network.parameter_count,
                                thyrix.derive_seed(31, episode, 0, 0))
        assert env.agent_centre == world.spherus.centre
        env.reset()
