"""Builds the module `scalecert` with CMake from the checkout this folder is in, and installs it.

Used by `pip install --no-build-isolation ./python` (pyproject.toml): the extension is the
scalecert_python target of the top-level CMakeLists.txt, built without the floating-point
baselines, the tests and MPI, in pip's build folder; or, when SCALECERT_BUILD_DIR names a
configured build tree (absolute, or relative to the checkout: build), built there and copied (no
second build of the core).
"""
import os
import pathlib
import shutil
import subprocess
import sys

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = pathlib.Path(__file__).resolve().parent.parent


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        target = pathlib.Path(self.get_ext_fullpath(ext.name)).resolve()
        tree = os.environ.get("SCALECERT_BUILD_DIR")
        if tree:
            # (pip runs this in the package's folder: a relative path is the checkout's.)
            build = (ROOT / tree).resolve()
        else:
            build = pathlib.Path(self.build_temp).resolve() / "cmake"
            subprocess.check_call(["cmake", "-S", str(ROOT), "-B", str(build), "-DCMAKE_BUILD_TYPE=Release",
                                   "-DSCALECERT_BUILD_BASELINES=OFF", "-DSCALECERT_BUILD_TESTS=OFF",
                                   "-DSCALECERT_BUILD_MPI=OFF", "-DSCALECERT_BUILD_PYTHON=ON",
                                   "-DPython_EXECUTABLE=" + sys.executable])
        subprocess.check_call(["cmake", "--build", str(build), "--target", "scalecert_python",
                               "-j", str(os.cpu_count() or 1)])
        built = sorted((build / "python").glob("scalecert*.so"))
        if not built:
            raise RuntimeError("the CMake build made no python/scalecert*.so in " + str(build))
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(built[0], target)


setup(ext_modules=[Extension("scalecert", sources=[])], cmdclass={"build_ext": CMakeBuild})
