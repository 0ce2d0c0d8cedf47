"""SpherusVectorEnv against single environments, whatever the threads."""

import numpy as np
import pytest

from thyrix.envs import SpherusEnv, SpherusVectorEnv

NUM_ENVS = 5
STEPS = 30  # short episodes, so that the run crosses two autoresets
RUN = 75


def single_trajectories(seed, actions):
    """World i as a SpherusEnv reset with seed + i, reset again (no seed) when truncated."""
    observations = np.zeros((RUN + 1, NUM_ENVS, 35))
    rewards = np.zeros((RUN, NUM_ENVS))
    finals = {}
    for i in range(NUM_ENVS):
        env = SpherusEnv(steps=STEPS)
        observations[0, i], _ = env.reset(seed=seed + i)
        for t in range(RUN):
            observation, rewards[t, i], _, truncated, _ = env.step(actions[t, i])
            if truncated:
                finals[(t, i)] = observation
                observation, _ = env.reset()
            observations[t + 1, i] = observation
    return observations, rewards, finals


@pytest.mark.parametrize("threads", [1, 2, 3])
def test_world_i_follows_a_single_env_seeded_s_plus_i(threads):
    actions = np.random.default_rng(5).uniform(0, 1, size=(RUN, NUM_ENVS, 5))
    expected, expected_rewards, expected_finals = single_trajectories(100, actions)
    vector = SpherusVectorEnv(NUM_ENVS, threads=threads, steps=STEPS)
    assert vector.threads == threads
    observations, info = vector.reset(seed=100)
    assert observations.shape == (NUM_ENVS, 35) and info == {}
    assert np.array_equal(observations, expected[0])
    for t in range(RUN):
        observations, rewards, terminated, truncated, info = vector.step(actions[t])
        assert observations.shape == (NUM_ENVS, 35) and rewards.shape == (NUM_ENVS,)
        assert terminated.dtype == bool and not terminated.any()
        assert np.array_equal(observations, expected[t + 1])
        assert np.array_equal(rewards, expected_rewards[t])
        assert truncated.all() == ((t + 1) % STEPS == 0)
        if truncated.any():
            assert info["_final_observation"].all()
            for i in range(NUM_ENVS):
                assert np.array_equal(info["final_observation"][i], expected_finals[(t, i)])


def test_spaces_and_bad_input():
    vector = SpherusVectorEnv(3, threads=1, seed=1)
    assert vector.single_observation_space.shape == (35,)
    assert vector.single_action_space.shape == (5,)
    assert vector.observation_space.shape == (3, 35)
    assert vector.action_space.shape == (3, 5)
    with pytest.raises(ValueError, match="reset"):
        vector.step(np.zeros((3, 5)))
    vector.reset()
    with pytest.raises(ValueError, match=r"actions must have shape \(3, 5\), not \(5,\)"):
        vector.step(np.zeros(5))
    with pytest.raises(ValueError, match="actions must be finite"):
        vector.step(np.full((3, 5), np.nan))
    with pytest.raises(ValueError, match="num_envs"):
        SpherusVectorEnv(0)
    with pytest.raises(ValueError, match="threads"):
        SpherusVectorEnv(2, threads=0)
    assert vector.render(2).startswith("<?xml")
