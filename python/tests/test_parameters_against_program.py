"""Curves in a parameter other than the frequency, from Python against the program on the
same scene: tmdsimpy's 2-DOF friction (regression/scenes/tmdsimpy_friction2d.yaml) at
W = 3.6 and s = 100, traced in the contact's friction coefficient (contact/mu) and in the
damping's scale, by the program and by hand: the same points to 1e-10."""

import numpy as np
import pytest

import cyclone
import program
from test_friction_closed_forms import tmdsimpy_friction_2dof


def scene(scene_dir, continuation):
    """The tmdsimpy scene with its continuation section replaced."""
    text = (scene_dir / "tmdsimpy_friction2d.yaml").read_text()
    head = text[:text.index("  continuation:")]
    return head + continuation + "  output:\n    dofs: [0, 1]\n"


@pytest.mark.parametrize("parameter, start, end", [("contact/mu", 0.85, 0.3), ("damping_scale", 1.0, 0.3)])
def test_a_curve_in_a_parameter_equals_the_programs(cyclone_program, scene_dir, tmp_path, parameter, start, end):
    continuation = f"  continuation:\n    parameter: {parameter}\n    omega: 3.6\n    from: {start}\n    to: {end}\n"
    expected = program.read_csv(program.run(cyclone_program, scene(scene_dir, continuation), tmp_path / "out")
                                / "frc.csv")
    system, _ = tmdsimpy_friction_2dof(100.0, cx=0.346410161513775)  # the scene's cx, to its 15 digits
    curve = system.forced_response(start, end, parameter=parameter, omega=3.6, force_scale=100.0,
                                   output_dofs=[0, 1])
    assert curve.end is cyclone.BranchEnd.RANGE_END
    assert len(curve) == len(expected["omega_rad_s"]) > 5
    np.testing.assert_allclose(curve.parameter, expected[parameter].astype(float), rtol=1e-10)
    np.testing.assert_allclose(curve.omega, 3.6, rtol=0)
    for k, dof in enumerate([0, 1]):
        np.testing.assert_allclose(curve.max_abs[:, k], expected[f"dof{dof}_max"].astype(float), rtol=1e-10)


def test_an_unknown_element_or_parameter_is_named():
    system, _ = tmdsimpy_friction_2dof(100.0)
    for parameter, named in (("shroud/mu", "shroud"), ("contact/friction", "friction")):
        with pytest.raises(cyclone.InputError) as error:
            system.forced_response(0.85, 0.3, parameter=parameter, omega=3.6)
        assert error.value.key == "parameter"
        assert named in error.value.problem
