"""pip install . : the Python module minkowski, built by the project's CMake (offline, with
Debian's build tools: python3-setuptools, python3-wheel, cmake, pybind11-dev, python3-dev and
the packages scripts/install-deps.sh build installs). Debian's own Python refuses pip installs
outside a virtual environment; make one that sees Debian's numpy:

    python3 -m venv --system-site-packages ~/venv && ~/venv/bin/pip install .

MINK_CMAKE_BUILD_DIR names a CMake build directory to build in (default build/pip); an existing
one keeps its configuration.
"""

import os
import pathlib
import shutil
import subprocess
import sys

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

SOURCE = pathlib.Path(__file__).resolve().parent


class CMakeBuild(build_ext):
    """Builds minkowski._minkowski with CMake and copies it where setuptools wants it."""

    def build_extension(self, extension):
        build_dir = pathlib.Path(os.environ.get("MINK_CMAKE_BUILD_DIR", SOURCE / "build" / "pip"))
        if not (build_dir / "CMakeCache.txt").exists():
            subprocess.run(["cmake", "-S", str(SOURCE), "-B", str(build_dir),
                            "-DCMAKE_BUILD_TYPE=Release", "-DMINK_BUILD_TESTS=OFF",
                            "-DMINK_WITH_PYTHON=ON", "-DMINK_WITH_SDL2=OFF",
                            "-DMINK_WITH_BOX2D=OFF", f"-DPython3_EXECUTABLE={sys.executable}"],
                           check=True)
        subprocess.run(["cmake", "--build", str(build_dir), "--target", "mink_python", "-j",
                        str(os.cpu_count() or 1)], check=True)
        built = list((build_dir / "python" / "minkowski").glob("_minkowski*.so"))
        if len(built) != 1:
            raise RuntimeError(f"expected one _minkowski*.so in {build_dir}/python/minkowski, "
                               f"found {built}")
        target = pathlib.Path(self.get_ext_fullpath(extension.name))
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(built[0], target)


setup(
    name="minkowski",
    version="0.1.0",
    description="A 2D rigid-body physics engine: exact convex hulls, GJK, a soft-step solver, "
                "numpy batch arrays, headless frames and Dask sweeps",
    packages=["minkowski"],
    package_dir={"minkowski": "python/minkowski"},
    ext_modules=[Extension("minkowski._minkowski", sources=[])],
    cmdclass={"build_ext": CMakeBuild},
    python_requires=">=3.9",
    install_requires=["numpy"],
    extras_require={"sweep": ["pandas", "dask", "distributed", "tqdm"]},
    options={"build": {"build_base": "build/setuptools"},
             "egg_info": {"egg_base": "build"}},
    zip_safe=False,
)
