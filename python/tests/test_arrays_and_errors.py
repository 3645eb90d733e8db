"""numpy in and out, and errors as Python exceptions: C order, Fortran order, a
non-contiguous slice and other dtypes (float32, int32) are the same input, the results
float64 arrays of one row per point; a wrong shape or a NaN stops the call naming the
argument; the library's InputError arrives as cyclone.InputError with the key it names."""

import numpy as np
import pytest

import cyclone

K = np.array([[3.0, -1.0], [-1.0, 1.0]])


def chain(M, K, C):
    system = cyclone.HarmonicBalance(M, K, C, harmonics=5, samples=64)
    system.add_element(cyclone.CubicSpring(k3=0.5), between=(0, 1))
    system.add_excitation(dof=1, harmonic=1, cos=0.2)
    return system


def curve_of(system):
    return system.forced_response(0.3, 2.5, output_dofs=[0, 1], harmonics_check=False)


def test_c_order_fortran_order_and_a_strided_slice_give_the_same_curve():
    M, C = np.diag([1.0, 0.5]), 0.02 * K
    reference = curve_of(chain(M, K, C))
    assert reference.end is cyclone.BranchEnd.RANGE_END
    big = np.zeros((4, 6))
    big[::2, ::3] = K  # K as a view with strides in both directions
    strided = big[::2, ::3]
    assert not strided.flags.c_contiguous and not strided.flags.f_contiguous
    for M_, K_, C_ in [(np.asfortranarray(M), np.asfortranarray(K), np.asfortranarray(C)), (M, strided, C),
                       (M.tolist(), K.astype(np.float32).astype(np.float64), C),
                       (M.astype(np.float32), K.astype(np.int32), C)]:  # other dtypes, their values exact
        curve = curve_of(chain(M_, K_, C_))
        np.testing.assert_array_equal(curve.omega, reference.omega)
        np.testing.assert_array_equal(curve.x, reference.x)
    # Out: float64 arrays of one row per point; Hill's verdicts and the sweeps as integers.
    P = len(reference)
    for array, shape in [(reference.omega, (P,)), (reference.parameter, (P,)), (reference.x, (P, 2 * 11)),
                         (reference.coefficients, (P, 2, 11)), (reference.amplitude, (P, 2, 6)),
                         (reference.max_abs, (P, 2))]:
        assert array.shape == shape and array.dtype == np.float64
    assert reference.leading_exponent.shape == (P,) and reference.leading_exponent.dtype == np.complex128
    assert reference.stable.dtype.kind == reference.segment.dtype.kind == "i"


def test_the_callers_arrays_are_copied_and_the_systems_read_only():
    M, C, K2 = np.diag([1.0, 0.5]), 0.02 * K, K.copy()
    system = chain(M, K2, C)
    x = system.linearized_solution(1.0)
    K2[0, 0] = 100.0  # changed after the system took it
    np.testing.assert_array_equal(system.linearized_solution(1.0), x)
    with pytest.raises(ValueError):
        system.K[0, 0] = 100.0  # would not reach the system built from it


@pytest.mark.parametrize("harmonics", [[], [1, -1], [0, 1, 1], 0, "abc"])
def test_a_wrong_harmonic_set_names_harmonics(harmonics):
    with pytest.raises(cyclone.InputError) as error:
        cyclone.HarmonicBalance(np.eye(2), K, harmonics=harmonics)
    assert error.value.key == "harmonics"


@pytest.mark.parametrize("argument, M, K_, C", [
    ("K", np.eye(2), np.ones((2, 3)), None),
    ("K", np.eye(2), np.eye(3), None),
    ("M", np.ones(4), K, None),
    ("C", np.eye(2), K, np.array([[0.1, np.nan], [0.0, 0.1]])),
    ("M", np.array([[1.0, 0.0], [0.0, np.inf]]), K, None),
    ("C", np.eye(2), K, np.eye(2) * (0.1 + 0.1j)),
    ("K", np.eye(2), [["a", "b"], ["c", "d"]], None),
])
def test_a_wrong_shape_or_a_nan_names_the_argument(argument, M, K_, C):
    with pytest.raises(cyclone.InputError) as error:
        cyclone.HarmonicBalance(M, K_, C)
    assert error.value.key == argument
    assert isinstance(error.value, ValueError)
    assert str(error.value).startswith(argument + ": ")


def test_arguments_of_the_calls_are_named():
    system = chain(np.eye(2), K, None)
    n = system.num_unknowns
    with pytest.raises(cyclone.InputError) as error:
        system.residual(np.zeros(n + 1), 1.0)
    assert error.value.key == "x"
    with pytest.raises(cyclone.InputError) as error:
        system.residual(np.full(n, np.nan), 1.0)
    assert error.value.key == "x"
    with pytest.raises(cyclone.InputError) as error:
        system.add_element(cyclone.Friction2D(kt=1.0, kn=1.0, mu=0.3), W=np.ones((2, 3)))
    assert error.value.key == "W"
    with pytest.raises(cyclone.InputError) as error:
        system.add_element(cyclone.CubicSpring(k3=1.0), dofs=[2])
    assert error.value.key == "dofs"
    with pytest.raises(cyclone.InputError) as error:
        system.forced_response(1.0, 1.0)
    assert error.value.key == "end"
    with pytest.raises(cyclone.InputError) as error:
        system.forced_response(0.5, 1.0, tolerance=1e-2)
    assert error.value.key == "tolerance"
    with pytest.raises(cyclone.InputError) as error:
        system.forced_response(1e-10, 1.0, parameter="force_scale", omega=1.0)
    assert error.value.key == "start"
    static = cyclone.HarmonicBalance(np.eye(2), K, harmonics=[0, 1]).add_excitation(dof=0, harmonic=0, cos=1.0)
    with pytest.raises(cyclone.InputError) as error:
        static.forced_response(0.5, 1.0)
    assert error.value.key == "excitation"


def test_the_librarys_input_error_carries_its_key():
    system = cyclone.HarmonicBalance(np.eye(2), K, harmonics=[1, 3])
    system.add_excitation(dof=0, harmonic=2, cos=1.0)  # harmonic 2 is not in the set: the library says so
    with pytest.raises(cyclone.InputError) as error:
        system.forced_response(0.5, 1.0)
    assert error.value.key == "excitation"
    assert "harmonic 2" in error.value.problem
    with pytest.raises(cyclone.InputError) as error:
        cyclone.Jenkins(kt=-1.0, slip_force=1.0)  # the law refuses it on construction
    assert error.value.key == "Jenkins"
    assert "stiffness" in error.value.problem
    with pytest.raises(cyclone.InputError) as error:
        cyclone.Friction2D(kt=1.0, kn=0.0, mu=0.3)  # kn = 0 holds N at the preload, which must then be > 0
    assert error.value.key == "Friction2D"


def test_the_typed_end_of_a_trace_out_of_points():
    system = chain(np.eye(2), K, 0.02 * K)
    curve = system.forced_response(0.3, 2.5, engine="predictor_corrector", max_points=5, harmonics_check=False)
    assert curve.end is cyclone.BranchEnd.POINT_BUDGET and not curve.finished
    assert len(curve) == 5
    assert {end.value for end in cyclone.BranchEnd} == set(cyclone._core.branch_end_names)


@pytest.mark.parametrize("argument, kwargs", [
    ("K", dict(M=np.eye(2), K=np.array([[3.0, -1.0], [-0.5, 1.0]]))),  # not symmetric
    ("M", dict(M=np.diag([1.0, 0.0]), K=K)),  # a DOF without mass
    ("C", dict(M=np.eye(2), K=K, C=np.diag([0.1, -0.2]))),  # generates energy
    ("engine_order", dict(M=np.eye(2), K=K, engine_order=3)),  # not cyclic
    ("K_next", dict(M=np.eye(2), K=K, K_next=np.eye(2))),  # not cyclic
    ("sectors", dict(M=np.eye(2), K=K, sectors=0)),
    ("engine_order", dict(M=np.eye(2), K=K, sectors=4, engine_order=1.5, K_next=-0.1 * np.eye(2))),  # not an int
    ("samples", dict(M=np.eye(2), K=K, harmonics=5, samples=10)),  # below 2 H + 1 (the library's Aft said it)
    ("samples", dict(M=np.eye(2), K=K, samples=64.5)),  # not read as 64
    ("samples", dict(M=np.eye(2), K=K, samples=1 << 17)),  # above the scenes' 65536
    ("harmonics", dict(M=np.eye(2), K=K, harmonics=[0, 1.5])),  # not read as 1
])
def test_what_a_scene_refuses_is_refused_naming_the_argument(argument, kwargs):
    with pytest.raises(cyclone.InputError) as error:
        cyclone.HarmonicBalance(**kwargs)
    assert error.value.key == argument


def test_an_element_across_the_sector_boundary_needs_a_cyclic_system():
    with pytest.raises(cyclone.InputError) as error:
        chain(np.eye(2), K, None).add_element(cyclone.CubicSpring(k3=1.0), dofs=[0], W_next=[1.0, 0.0])
    assert error.value.key == "W_next"


@pytest.mark.parametrize("call", [lambda r: cyclone.disc.follow_peak(r, "preload", (1.0, 2.0)),
                                  lambda r: cyclone.disc.peak_stress(r)])
def test_the_discs_peak_studies_need_a_disc_response(call):
    # A matrix system's curve is not a disc response: named, not an AttributeError deep inside.
    curve = chain(np.eye(2), K, 0.02 * K).forced_response(0.3, 2.5, harmonics_check=False)
    with pytest.raises(cyclone.InputError) as error:
        call(curve)
    assert error.value.key == "response"


def test_a_solver_failure_arrives_as_cyclone_solver_error():
    # The sector held at its one mid-blade node: accepted (the set exists, as a static
    # scene accepts it), but three pinned displacements leave the three rigid rotations
    # about that node, so the stiffness of its 3 n - 3 free DOFs is singular and CHOLMOD's
    # factorization refuses it: the library's SolverError, a RuntimeError, not an InputError.
    sector = cyclone.disc.shrouded_sector(mesh_size=12.0)
    assert len(sector.node_sets["mid_blade"]) == 1
    with pytest.raises(cyclone.SolverError) as error:
        cyclone.disc.static_solve(sector, speed_rpm=10000.0, fixed_node_sets=["mid_blade"])
    assert isinstance(error.value, RuntimeError) and not isinstance(error.value, ValueError)
    free = 3 * sector.num_nodes - 3
    assert str(error.value).startswith(f"CHOLMOD: the matrix ({free} equations) is not positive definite")
    # Held at the bore the same call solves.
    assert cyclone.disc.static_solve(sector, speed_rpm=10000.0).relative_residual < 1e-8


@pytest.mark.parametrize("harmonic", [-1, 1.5, "1"])
def test_an_excitations_harmonic_is_a_whole_number_named_harmonic(harmonic):
    with pytest.raises(cyclone.InputError) as error:
        chain(np.eye(2), K, None).add_excitation(dof=0, harmonic=harmonic, cos=1.0)
    assert error.value.key == "harmonic"


def test_a_curves_accessors_name_a_wrong_dof():
    curve = chain(np.eye(2), K, 0.02 * K).forced_response(0.3, 2.5, harmonics_check=False)
    for call in (lambda: curve.mean(2), lambda: curve.amplitude_of(-1, 1)):
        with pytest.raises(cyclone.InputError) as error:
            call()
        assert error.value.key == "dof"


@pytest.mark.parametrize("argument, kwargs", [
    ("samples", dict(samples=3)),  # the scenes' disc: at least 32 (3 samples traced nonsense)
    ("samples", dict(harmonics=[0, 1, 20], samples=32)),  # and 2 H + 1
    ("harmonics", dict(harmonics=[0, 2])),  # the engine-order excitation acts on harmonic 1
    ("harmonics", dict(harmonics=[0, 1.5])),
    ("engine_order", dict(engine_order=2.5)),
    ("frequency_range_hz", dict(frequency_range_hz=(1500.0,))),
    ("engine", dict(engine="newton")),  # disc_response/continuation's keys
    ("tolerance", dict(tolerance=1e-2)),
    ("min_step", dict(min_step=-1.0)),
    ("max_pointz", dict(max_pointz=10)),
])
def test_what_a_disc_scene_refuses_is_refused_before_any_fe_work(argument, kwargs):
    # As DiscSceneReaders.cpp refuses disc_response's keys; checked before the mesh and the
    # models are used (here: none given).
    with pytest.raises(cyclone.InputError) as error:
        cyclone.disc.forced_response(None, None, **{"engine_order": 3, **kwargs})
    assert error.value.key == argument
