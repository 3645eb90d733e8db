"""The library's progress lines go to Python's logging (logger "cyclone"), and a trace
releases the GIL: other Python threads run while it computes."""

import logging
import threading
import time

import cyclone
from test_friction_closed_forms import tmdsimpy_friction_2dof


def jenkins_oscillator():
    oscillator = cyclone.HarmonicBalance(M=[[1.0]], K=[[1.0]], C=[[0.01]], harmonics=[1], samples=1024)
    oscillator.add_element(cyclone.Jenkins(kt=1.0, slip_force=0.02), dofs=[0])
    return oscillator.add_excitation(dof=0, harmonic=1, cos=0.01)


def test_progress_lines_go_to_the_cyclone_logger(caplog, capfd):
    with caplog.at_level(logging.INFO, logger="cyclone"):
        jenkins_oscillator().forced_response(0.8, 1.8, harmonics_check=False)
    lines = [r.getMessage() for r in caplog.records if r.name == "cyclone"]
    assert any(line.startswith("forced response: 1 DOFs") for line in lines)
    assert any(line.startswith("continuation: ") for line in lines)
    assert "[cyclone" not in capfd.readouterr().out  # not printed as well


def test_quiet_by_default_at_warning_level(caplog, capfd):
    with caplog.at_level(logging.WARNING, logger="cyclone"):
        jenkins_oscillator().forced_response(0.8, 1.8, harmonics_check=False)
    assert not [r for r in caplog.records if r.name == "cyclone" and r.levelno < logging.WARNING]
    assert capfd.readouterr().out == ""


def test_a_trace_lets_other_threads_run():
    system, options = tmdsimpy_friction_2dof(100.0)  # slipping, with the harmonics check: a few tenths of a second
    ticks, done = [], threading.Event()
    trace = threading.Thread(target=lambda: (system.forced_response(2.5, 5.5, **options), done.set()))
    start = time.perf_counter()
    trace.start()
    while not done.is_set():
        ticks.append(time.perf_counter())
        time.sleep(0.001)
    trace.join()
    seconds = time.perf_counter() - start
    gaps = [b - a for a, b in zip([start] + ticks, ticks + [time.perf_counter()])]
    # Holding the GIL, the trace would leave this thread one gap as long as itself.
    assert seconds > 0.1, "the trace is too short to tell"
    assert max(gaps) < 0.5 * seconds
