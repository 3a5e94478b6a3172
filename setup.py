"""Builds the wheel of the Python module: the extension flexure._core comes from the project's
own CMake build (python/CMakeLists.txt), the Python half from python/flexure.

    pip install --no-build-isolation .          # configures and builds in build-wheel/

FLEXURE_CMAKE_BUILD_DIR=DIR uses an existing build folder instead (scripts/test.sh passes build/,
already built, so the wheel costs no second compilation); CMAKE_BUILD_PARALLEL_LEVEL sets the
build's jobs (default: the cores)."""
import os
import re
import shutil
import subprocess
import sys
import sysconfig

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = os.path.dirname(os.path.abspath(__file__))


def version():
    with open(os.path.join(ROOT, "CMakeLists.txt"), encoding="utf-8") as f:
        return re.search(r"project\(flexure VERSION (\S+)", f.read()).group(1)


class CMakeExtension(Extension):
    def __init__(self, name):
        super().__init__(name, sources=[])


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        build_dir = os.environ.get("FLEXURE_CMAKE_BUILD_DIR", os.path.join(ROOT, "build-wheel"))
        build_dir = os.path.abspath(build_dir)
        if not os.path.exists(os.path.join(build_dir, "CMakeCache.txt")):
            # A build of its own: the library, the tool and the module, for this interpreter.
            subprocess.check_call([
                "cmake", "-S", ROOT, "-B", build_dir, "-DCMAKE_BUILD_TYPE=Release",
                f"-DPython_EXECUTABLE={sys.executable}", "-DFLEXURE_BUILD_PYTHON=ON",
                "-DFLEXURE_BUILD_TESTS=OFF", "-DFLEXURE_BUILD_BENCHMARKS=OFF"])
        jobs = os.environ.get("CMAKE_BUILD_PARALLEL_LEVEL", str(os.cpu_count() or 1))
        subprocess.check_call(["cmake", "--build", build_dir, "--target", "flexure_python",
                               "-j", jobs])
        suffix = sysconfig.get_config_var("EXT_SUFFIX")
        built = os.path.join(build_dir, "python", "flexure", "_core" + suffix)
        if not os.path.exists(built):
            found = os.listdir(os.path.join(build_dir, "python", "flexure"))
            sys.exit(f"setup.py: {built} was not built: the build folder {build_dir} is configured "
                     f"for another Python ({[f for f in found if f.startswith('_core')]}); use "
                     f"the interpreter it was built for, or another FLEXURE_CMAKE_BUILD_DIR")
        target = self.get_ext_fullpath(ext.name)
        os.makedirs(os.path.dirname(target), exist_ok=True)
        shutil.copyfile(built, target)


setup(
    version=version(),
    packages=["flexure"],
    package_dir={"": "python"},
    package_data={"flexure": ["*.pyi", "py.typed"]},
    ext_modules=[CMakeExtension("flexure._core")],
    cmdclass={"build_ext": CMakeBuild},
    zip_safe=False,
)
