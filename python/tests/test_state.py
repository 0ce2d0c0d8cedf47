"""World states: pickling and copying, restoring and continuing, the reference mode, and
SpherusEnv snapshots. The reference is the uninterrupted run, bit for bit, not a number."""

import copy
import pickle

import numpy as np
import pytest

import thyrix
from thyrix.envs import SpherusEnv

SOLVERS = [thyrix.ContactSolver.BARAFF, thyrix.ContactSolver.GAUSS_SEIDEL]


def make_pile(solver, reference=False):
    """Twelve balls falling into an open box, the same every call."""
    sim = thyrix.Simulator(0.01)
    sim.contact_solver = solver
    sim.reference_mode = reference
    sim.gravity = (0.0, -2.0)
    sim.add_border((0.0, 0.0), (0.0, 1.0))
    sim.add_border((-3.0, 0.0), (1.0, 0.0))
    sim.add_border((3.0, 0.0), (-1.0, 0.0))
    balls = []
    for i in range(12):
        x = -2.0 + (i % 4) * 1.2 + 0.05 * (i // 4)
        balls.append(sim.add_circle(0.5, 1.0, position=(x, 0.6 + 1.1 * (i // 4))))
    return sim, balls


def run(sim, balls, steps):
    """Steps the pile, pushing one ball sideways; returns every ball's pose and velocity."""
    for step in range(steps):
        balls[step % len(balls)].external_force = (0.7, 0.0)
        sim.advance_time()
    return np.array([list(b.position) + list(b.velocity) for b in balls])


@pytest.mark.parametrize("solver", SOLVERS)
def test_a_state_survives_pickle_copy_and_bytes_unchanged(solver):
    sim, balls = make_pile(solver)
    run(sim, balls, 40)
    state = sim.save_state()
    for again in (pickle.loads(pickle.dumps(state)), copy.copy(state), copy.deepcopy(state),
                  thyrix.WorldState(bytes(state))):
        assert again == state
        assert again.hash() == state.hash()
    run(sim, balls, 1)
    assert sim.save_state() != state


@pytest.mark.parametrize("solver", SOLVERS)
def test_a_restored_world_continues_as_the_uninterrupted_run(solver):
    sim, balls = make_pile(solver)
    run(sim, balls, 60)
    saved = pickle.dumps(sim.save_state())
    expected = run(sim, balls, 80)
    expected_hash = sim.save_state().hash()
    # Into a world built the same way, never stepped: the same steps, bit for bit.
    fresh, fresh_balls = make_pile(solver)
    fresh.restore_state(pickle.loads(saved))
    assert fresh.step_count == 60
    np.testing.assert_array_equal(run(fresh, fresh_balls, 80), expected)
    assert fresh.save_state().hash() == expected_hash
    # Into the same world, later on.
    sim.restore_state(pickle.loads(saved))
    np.testing.assert_array_equal(run(sim, balls, 80), expected)


@pytest.mark.parametrize("solver", SOLVERS)
def test_the_reference_mode_gives_the_same_bits(solver):
    fast, fast_balls = make_pile(solver)
    plain, plain_balls = make_pile(solver, reference=True)
    assert plain.reference_mode and not fast.reference_mode
    for _ in range(20):
        np.testing.assert_array_equal(run(fast, fast_balls, 10), run(plain, plain_balls, 10))
        assert fast.save_state() == plain.save_state()


def test_a_state_of_another_world_or_corrupt_bytes_is_refused():
    sim, balls = make_pile(thyrix.ContactSolver.BARAFF)
    run(sim, balls, 10)
    state = sim.save_state()
    other = thyrix.Simulator(0.01)
    other.add_circle(0.5, 1.0, position=(0.0, 0.0))
    before = other.save_state()
    with pytest.raises(ValueError, match="WorldState"):
        other.restore_state(state)
    assert other.save_state() == before  # unchanged
    data = bytearray(bytes(state))
    data[len(data) // 2] ^= 0x10
    with pytest.raises(RuntimeError, match="checksum"):
        thyrix.WorldState(bytes(data))
    with pytest.raises(RuntimeError, match="truncated"):
        thyrix.WorldState(bytes(state)[:-1])


def test_a_spherus_env_branches_from_a_snapshot_exactly():
    env = SpherusEnv(steps=400, objects=10)
    env.reset(seed=5)
    rng = np.random.default_rng(1)
    for _ in range(60):
        env.step(rng.uniform(0.0, 1.0, 5))
    snapshot = pickle.loads(pickle.dumps(env.save_state()))
    assert snapshot.step == 60
    actions = rng.uniform(0.0, 1.0, (50, 5))

    def branch(environment, moves):
        return [environment.step(a)[:2] for a in moves]

    first = branch(env, actions)
    # In another environment made the same way, from the unpickled snapshot.
    other = SpherusEnv(steps=400, objects=10)
    observation = other.restore_state(snapshot)
    assert observation.shape == (35,)
    second = branch(other, actions)
    for (obs_a, reward_a), (obs_b, reward_b) in zip(first, second):
        np.testing.assert_array_equal(obs_a, obs_b)
        assert reward_a == reward_b
    # Back in the first environment, another branch: it goes elsewhere.
    env.restore_state(snapshot)
    third = branch(env, 1.0 - actions)
    assert any(not np.array_equal(a[0], b[0]) for a, b in zip(first, third))
    # A state of another task's world is refused, the environment unchanged.
    small = SpherusEnv(steps=400, objects=3)
    small.reset(seed=1)
    kept = small.save_state()
    with pytest.raises(ValueError, match="WorldState"):
        small.restore_state(snapshot)
    assert small.save_state() == kept
