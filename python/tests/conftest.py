"""Where the tests find the cyclone program and the scenes: ctest sets CYCLONE_PROGRAM and
CYCLONE_SCENE_DIR (python/CMakeLists.txt); run by hand from the repository's root,
PYTHONPATH=build/python python3 -m pytest python/tests, they default to ./build's."""

import os
import pathlib

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]


def pytest_configure(config):
    config.addinivalue_line("markers", "disc: the disc chain (modes, forced response) against the program (ctest python_disc, label scene)")


@pytest.fixture(scope="session")
def cyclone_program():
    program = pathlib.Path(os.environ.get("CYCLONE_PROGRAM", ROOT / "build" / "drivers" / "cyclone"))
    if not program.exists():
        pytest.fail(f"the cyclone program is not built at {program} (make cyclone)")
    return program


@pytest.fixture(scope="session")
def scene_dir():
    return pathlib.Path(os.environ.get("CYCLONE_SCENE_DIR", ROOT / "regression" / "scenes"))
