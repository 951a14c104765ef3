"""Builds the compiled half of the Python package (ornithopter._ornithopter) with CMake.

`pip install --no-build-isolation .` (or `python3 -m build --no-isolation`) runs this through
setuptools; the metadata is in pyproject.toml. The CMake build tree is build-python/cmake in the
source tree (reused by the next install: only what changed is rebuilt; ORNI_PIP_BUILD_DIR names
another), configured for the Python that runs pip (a venv's too). ORNI_PREBUILT_MODULE=PATH packs
a module already built for this Python instead (python/tests: the build tree's). Needs the same Debian packages
as the C++ build (.ci/setup.sh) plus pybind11-dev and python3-numpy; downloads nothing.
"""
import os
import pathlib
import shutil
import subprocess
import sys

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

SOURCE = pathlib.Path(__file__).parent.resolve()
(SOURCE / "build-python").mkdir(exist_ok=True)  # setuptools' egg-info and build folders


class CMakeExtension(Extension):
    def __init__(self, name):
        super().__init__(name, sources=[])


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        target = pathlib.Path(self.get_ext_fullpath(ext.name))
        target.parent.mkdir(parents=True, exist_ok=True)
        prebuilt = os.environ.get("ORNI_PREBUILT_MODULE")
        if prebuilt:  # a module CMake already built for this Python (the tests' quick path)
            shutil.copy2(prebuilt, target)
            return
        build = pathlib.Path(os.environ.get("ORNI_PIP_BUILD_DIR",
                                            SOURCE / "build-python" / "cmake")).resolve()
        configure = [
            "cmake", "-S", str(SOURCE), "-B", str(build),
            "-DCMAKE_BUILD_TYPE=Release",
            "-DORNI_PYTHON=ON",
            "-DORNI_BUILD_TESTS=OFF",
            "-DORNI_BUILD_BENCHMARKS=OFF",
            "-DORNI_MPI=OFF",
            "-DPython3_EXECUTABLE=" + sys.executable,
        ]
        if shutil.which("ccache"):
            configure.append("-DCMAKE_CXX_COMPILER_LAUNCHER=ccache")
        subprocess.run(configure, check=True, stdout=subprocess.DEVNULL)
        jobs = str(os.cpu_count() or 2)
        subprocess.run(["cmake", "--build", str(build), "--target", "orni_python", "-j", jobs],
                       check=True)
        built = sorted((build / "python" / "ornithopter").glob("_ornithopter*.so"))
        if not built:
            raise RuntimeError("CMake built no _ornithopter*.so in " + str(build))
        shutil.copy2(built[0], target)


setup(
    ext_modules=[CMakeExtension("ornithopter._ornithopter")],
    cmdclass={"build_ext": CMakeBuild},
    options={"build": {"build_base": str(pathlib.Path("build-python") / "setuptools")},
             "egg_info": {"egg_base": "build-python"}},
)
