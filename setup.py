"""Builds the Python package `topocut` with CMake: the extension and the type stubs come from the
CMake target topocut_python_stubs (cmake/python.cmake), the pure-Python part from src/python/topocut.

TOPOCUT_BUILD_DIR names an existing CMake build folder to reuse (it must be configured for this
Python's version); otherwise build-python/cmake is configured (Release, no tests, no benchmarks) for
the interpreter running pip. CMAKE_BUILD_PARALLEL_LEVEL sets the build's jobs (default: all cores).
"""
import os
import pathlib
import re
import shutil
import subprocess
import sys
import sysconfig

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

SOURCE = pathlib.Path(__file__).resolve().parent


def version():
    text = (SOURCE / "CMakeLists.txt").read_text(encoding="utf-8")
    return re.search(r"project\(topocut VERSION ([0-9.]+)", text).group(1)


def run(command):
    print("+ " + " ".join(str(part) for part in command), flush=True)
    subprocess.run([str(part) for part in command], check=True)


class CMakeBuild(build_ext):
    """Builds topocut._topocut and the stubs with CMake and puts them beside the package's sources."""

    def build_extension(self, ext):
        given = os.environ.get("TOPOCUT_BUILD_DIR")
        build = pathlib.Path(given).resolve() if given else SOURCE / "build-python" / "cmake"
        if given and not (build / "CMakeCache.txt").exists():
            sys.exit(f"TOPOCUT_BUILD_DIR={given} is not a configured CMake build folder")
        if not given:
            configure = ["cmake", "-S", SOURCE, "-B", build, "-DCMAKE_BUILD_TYPE=Release", "-DTOPOCUT_BUILD_TESTS=OFF",
                         "-DTOPOCUT_BUILD_BENCHMARKS=OFF", f"-DPython_EXECUTABLE={sys.executable}"]
            if shutil.which("ccache"):
                configure.append("-DCMAKE_CXX_COMPILER_LAUNCHER=ccache")
            run(configure)
        jobs = os.environ.get("CMAKE_BUILD_PARALLEL_LEVEL", str(os.cpu_count() or 1))
        run(["cmake", "--build", build, "--target", "topocut_python_stubs", "-j", jobs])
        package = build / "python" / "topocut"
        built = package / ("_topocut" + sysconfig.get_config_var("EXT_SUFFIX"))
        if not built.exists():
            found = ", ".join(p.name for p in package.glob("_topocut*")) or "nothing"
            sys.exit(f"{build} holds no extension for this Python ({built.name}; found {found}): configure it with "
                     f"-DPython_EXECUTABLE={sys.executable}, or leave TOPOCUT_BUILD_DIR unset")
        target = pathlib.Path(self.get_ext_fullpath(ext.name))
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(built, target)
        shutil.copyfile(package / "__init__.pyi", target.parent / "__init__.pyi")


setup(
    version=version(),
    packages=["topocut"],
    package_dir={"topocut": "src/python/topocut"},
    package_data={"topocut": ["py.typed"]},
    ext_modules=[Extension("topocut._topocut", sources=[])],
    cmdclass={"build_ext": CMakeBuild},
    options={"build": {"build_base": "build-python/setuptools"}},
    zip_safe=False,
)
