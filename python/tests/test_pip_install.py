"""pip install . works offline: into a virtual environment that sees Debian's packages, with
the extension built by this build tree's CMake (MINK_BUILD_DIR; a fresh build is the same
commands, only slower)."""

import os
import subprocess
import sys

import pytest

from conftest import SOURCE_DIR


def test_pip_install_dot_offline_into_a_venv(tmp_path):
    build_dir = os.environ.get("MINK_BUILD_DIR")
    if not build_dir:
        pytest.skip("MINK_BUILD_DIR (a configured build tree) is not set")
    tools = subprocess.run([sys.executable, "-c", "import setuptools, wheel, pip"],
                           capture_output=True, text=True)
    if tools.returncode != 0:
        pytest.skip(f"pip, setuptools or wheel missing: {tools.stderr.strip()}")
    venv = tmp_path / "venv"
    subprocess.run([sys.executable, "-m", "venv", "--system-site-packages", "--without-pip",
                    str(venv)], check=True)
    python = venv / "bin" / "python"
    env = {key: value for key, value in os.environ.items() if key != "PYTHONPATH"}
    env["MINK_CMAKE_BUILD_DIR"] = build_dir
    install = subprocess.run([str(python), "-m", "pip", "install", "--no-index", "."],
                             cwd=SOURCE_DIR, env=env, capture_output=True, text=True, timeout=900)
    assert install.returncode == 0, install.stdout + install.stderr
    check = subprocess.run(
        [str(python), "-c",
         "import minkowski as mk\n"
         "w = mk.World()\n"
         "w.create_body('dynamic').add_circle(1)\n"
         "w.step(10)\n"
         "print(mk.__file__)\n"
         "print(w.positions()[0, 1])\n"],
        cwd=tmp_path, env=env, capture_output=True, text=True, timeout=120)
    assert check.returncode == 0, check.stderr
    location, height = check.stdout.split()
    assert location.startswith(str(venv))
    assert float(height) < 0
