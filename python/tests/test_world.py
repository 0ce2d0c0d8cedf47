"""Simulator, shapes, registration, advance_time, bulk poses, contacts, solver settings,
sensors, drawing and controllers, checked against closed forms."""

import math

import numpy as np
import pytest

import thyrix
from conftest import TOLERANCE


def test_a_pushed_circle_moves_at_force_over_mass():
    sim = thyrix.Simulator(0.01)
    ball = sim.add_circle(0.5, 2.0, position=(1.0, 2.0))
    for _ in range(100):
        ball.external_force = (3.0, -1.0)
        sim.advance_time()
    # F = m v: v = F / m for 100 steps of 0.01 s.
    assert ball.velocity == pytest.approx((1.5, -0.5), rel=TOLERANCE)
    tolerance = 1e-9 if TOLERANCE < 1e-9 else 1e-4
    assert ball.position == pytest.approx((1.0 + 1.5, 2.0 - 0.5), rel=tolerance)
    assert sim.step_count == 100
    assert sim.time == pytest.approx(1.0)


@pytest.mark.parametrize("solver", [thyrix.ContactSolver.BARAFF, thyrix.ContactSolver.GAUSS_SEIDEL])
def test_a_ball_pushed_into_the_floor_slides_and_the_floor_takes_the_push(solver):
    sim = thyrix.Simulator(0.01)
    sim.contact_solver = solver
    assert sim.contact_solver == solver
    sim.add_border((0.0, 0.0), (0.0, 1.0))
    ball = sim.add_circle(0.5, 1.0, position=(0.0, 0.5))
    for _ in range(50):
        ball.external_force = (1.0, -1.0)
        sim.advance_time()
    contacts = sim.contacts()
    assert contacts["force"].shape == (1,)
    # Quasistatic balance: the floor pushes back the 1 N pressed into it; the ball slides
    # at F_x / m = 1 m/s and does not sink.
    assert contacts["force"][0] == pytest.approx(1.0, rel=1e-4)
    assert abs(contacts["normal"][0][1]) == pytest.approx(1.0, rel=max(1e-9, TOLERANCE))
    assert sorted([contacts["body_a"][0], contacts["body_b"][0]]) == [0, 1]
    assert ball.velocity[0] == pytest.approx(1.0, rel=1e-6)
    assert ball.position[1] == pytest.approx(0.5, abs=1e-3)


def test_poses_and_velocities_are_arrays_of_every_object():
    sim = thyrix.Simulator()
    a = sim.add_circle(0.2, 1.0, position=(1.0, 1.0), angle=0.5)
    b = sim.add_capped_rectangle(1.0, 0.1, 1.0, position=(4.0, 1.0), angle=-0.25)
    b.external_torque = 2.0
    sim.advance_time()
    poses = sim.poses()
    assert poses.shape == (2, 3) and poses.dtype == thyrix.real_dtype
    assert poses[0].tolist() == pytest.approx([1.0, 1.0, 0.5])
    velocities = sim.velocities()
    assert velocities[1][2] == pytest.approx(2.0 / b.inertia)
    new = poses + np.array([[1.0, 0.0, 0.0], [0.0, 1.0, 0.0]])
    sim.set_poses(new)
    assert a.position == pytest.approx((2.0, 1.0))
    assert [type(o) for o in sim.objects] == [thyrix.Circle, thyrix.CappedRectangle]


def test_bad_input_is_refused_and_leaves_the_world_unchanged():
    sim = thyrix.Simulator()
    sim.add_circle(0.2, 1.0, position=(1.0, 1.0))
    before = sim.poses()
    with pytest.raises(ValueError, match=r"poses must have shape \(1, 3\), not \(2, 3\)"):
        sim.set_poses(np.zeros((2, 3)))
    with pytest.raises(ValueError, match="poses must be finite"):
        sim.set_poses(np.array([[np.nan, 0.0, 0.0]]))
    with pytest.raises(TypeError, match="poses must be an array of real numbers"):
        sim.set_poses([["a", "b", "c"]])
    with pytest.raises(ValueError, match="Circle.radius"):
        sim.add_circle(-1.0, 1.0)
    with pytest.raises(ValueError, match="Circle.position"):
        sim.add_circle(1.0, 1.0, position=(math.inf, 0.0))
    with pytest.raises(ValueError, match="Border.normal"):
        sim.add_border((0.0, 0.0), (0.0, 0.0))
    assert len(sim.objects) == 1
    assert np.array_equal(sim.poses(), before)


def test_solver_settings_are_read_and_written():
    sim = thyrix.Simulator()
    settings = sim.solver_settings
    settings.gauss_seidel_max_iterations = 7
    assert sim.solver_settings.gauss_seidel_max_iterations == 7
    sim.gravity = (0.0, -9.81)
    assert sim.gravity == pytest.approx((0.0, -9.81))


def test_tactile_sensors_of_a_circle_pressed_on_the_floor():
    sim = thyrix.Simulator()
    sim.add_border((0.0, 0.0), (0.0, 1.0))
    ball = sim.add_circle(0.5, 1.0, position=(0.0, 0.5))
    # 4 sensors of 90 degrees from -45 degrees: sensor 3 covers the bottom (225 to 315).
    ball.set_tactile_sensors(4, start_angle=-math.pi / 4, saturation=2.0)
    for _ in range(20):
        ball.external_force = (0.0, -1.0)
        sim.advance_time()
    activations = ball.tactile_activations
    assert activations.shape == (4,)
    assert activations[3] == pytest.approx(0.5, rel=1e-4)  # 1 N of a 2 N saturation
    assert activations[:3].tolist() == [0.0, 0.0, 0.0]


def test_a_visual_sensor_sees_what_is_in_front_only():
    sim = thyrix.Simulator()
    body = sim.add_circle(0.2, 1.0, position=(0.0, 0.0))
    sim.add_circle(0.5, 1.0, position=(3.0, 0.0))
    eye = thyrix.VisualSensor(body, (0.0, 0.0), 0.0, 3, 0.2)
    eye.update(sim)
    assert eye.pixel_count == 3
    # The circle covers the directions within asin(0.5 / 3) of +x; the pixels cover
    # [-0.3, -0.1], [-0.1, 0.1] and [0.1, 0.3] rad.
    half = math.asin(0.5 / 3)
    side = (half - 0.1) / 0.2
    expected = [side, 1.0, side]
    assert eye.activations.tolist() == pytest.approx(expected, rel=max(1e-6, 10 * TOLERANCE))
    behind = thyrix.VisualSensor(body, (0.0, 0.0), math.pi, 3, 0.2)
    behind.update(sim)
    assert behind.activations.tolist() == [0.0, 0.0, 0.0]


def test_draw_svg_returns_a_document():
    sim = thyrix.SpherusSimulator(seed=3)
    sim.advance_time(5)
    svg = thyrix.draw_svg(sim, lower=(0, 0), upper=(10, 10), width=300, contacts=True,
                          tactile=True, visual_rays=True)
    assert svg.startswith("<?xml") and "<svg" in svg and "<circle" in svg
    with pytest.raises(ValueError, match="SvgGUI"):
        thyrix.draw_svg(sim, lower=(1, 1), upper=(0, 0))


def test_a_python_callable_drives_spherus_as_effectors_set_by_hand():
    action = np.array([1.0, 0.0, 0.8, 0.0, 0.5])
    calls = []

    def controller(sensors):
        calls.append(sensors.shape)
        return action

    driven = thyrix.SpherusSimulator(seed=5, controller=controller)
    by_hand = thyrix.SpherusSimulator(seed=5)
    # The controller's effectors of step k act from step k on; by hand, the effectors set
    # before the first step act the same way.
    by_hand.spherus.effectors = action
    for _ in range(200):
        driven.advance_time()
        by_hand.advance_time()
    assert calls == [(35,)] * 200
    assert np.array_equal(driven.poses(), by_hand.poses())
    assert driven.spherus.centre != pytest.approx((5.0, 5.0), abs=0.1)
    assert isinstance(driven.spherus.controller, thyrix.PythonController)


def test_a_callable_with_a_wrong_result_raises():
    sim = thyrix.SpherusSimulator(controller=lambda sensors: np.zeros(4))
    with pytest.raises(ValueError, match=r"controller's result must have shape \(5,\)"):
        sim.advance_time()
    with pytest.raises(TypeError, match="callable"):
        thyrix.SpherusSimulator(controller=42)


def test_a_neural_controller_computes_its_closed_form():
    spec = thyrix.NetworkSpec(thyrix.NetworkKind.FEED_FORWARD, [2, 1], thyrix.Activation.TANH)
    assert spec.parameter_count == 3
    net = thyrix.NeuralController(spec)
    net.parameters = [0.1, 0.5, -0.25]  # bias, then the weights of inputs 0 and 1
    out = net.control([0.4, 0.8])
    expected = (1 + math.tanh(0.1 + 0.5 * 0.4 - 0.25 * 0.8)) / 2
    assert out[0] == pytest.approx(expected, rel=TOLERANCE)
    with pytest.raises(ValueError, match=r"parameters must have shape \(3,\)"):
        net.parameters = [1.0, 2.0]
    with pytest.raises(ValueError, match="parameters must be finite"):
        net.parameters = [1.0, math.nan, 0.0]
    assert net.parameters.tolist() == pytest.approx([0.1, 0.5, -0.25])


def test_a_genome_round_trips_exactly_and_drives_an_agent():
    spec = thyrix.spherus_network("ff:4")
    rng = np.random.default_rng(7)
    genome = thyrix.Genome(spec, rng.normal(size=spec.parameter_count))
    again = thyrix.Genome.from_text(genome.to_text())
    assert again.spec == spec
    assert np.array_equal(again.parameters, genome.parameters)
    with pytest.raises(RuntimeError, match="thyrix-genome"):
        thyrix.Genome.from_text("not a genome\n")
    a = thyrix.SpherusSimulator(seed=2, controller=genome)
    b = thyrix.SpherusSimulator(seed=2, controller=genome.make_controller())
    a.advance_time(100)
    b.advance_time(100)
    assert np.array_equal(a.poses(), b.poses())


def test_pac_and_iunctus_worlds_step():
    pac = thyrix.PacSimulator(food=4, seed=3)
    pac.advance_time(10)
    assert pac.pac(0).sensors.shape == (21,)
    assert len(pac.food) == 4
    assert 0 <= pac.food_inside(pac.pac(1)) <= 4
    iunctus = thyrix.IunctusSimulator(seed=2)
    iunctus.advance_time(10)
    assert iunctus.iunctus.sensors.ndim == 1
    assert len(iunctus.objects_to_catch) == 1
