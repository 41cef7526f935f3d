"""Installs the Python package `upf` (python/upf and its compiled module) with Debian's own
build tools, no package index needed:

    /usr/bin/python3 -m venv --system-site-packages venv     # NumPy from Debian
    venv/bin/pip install --no-build-isolation .

The compiled half is built by this project's CMake (target _upf). UPF_BUILD_DIR=build/release
reuses a configured build folder (only the module is built there); otherwise a Release build is
configured under setuptools' temporary folder.
"""

import os
import shutil
import subprocess
import sys
from pathlib import Path

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = Path(__file__).resolve().parent


class CMakeExtension(Extension):
    def __init__(self, name):
        super().__init__(name, sources=[])


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        given = os.environ.get("UPF_BUILD_DIR")
        build_dir = Path(given).resolve() if given else Path(self.build_temp).resolve() / "cmake"
        if not given:
            subprocess.check_call([
                "cmake", "-S", str(ROOT), "-B", str(build_dir), "-G", "Ninja",
                "-DCMAKE_BUILD_TYPE=Release", "-DUPF_BUILD_TESTS=OFF", "-DUPF_BUILD_BENCH=OFF",
                "-DUPF_BUILD_PYTHON=ON", f"-DPython_EXECUTABLE={sys.executable}"])
        subprocess.check_call(["cmake", "--build", str(build_dir), "--target", "_upf",
                               "-j", str(os.cpu_count() or 1)])
        built = sorted((build_dir / "python" / "upf").glob("_upf*.so"))
        if not built:
            raise RuntimeError(f"the build in {build_dir} made no python/upf/_upf*.so")
        target = Path(self.get_ext_fullpath(ext.name))
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copy2(built[0], target)


setup(
    name="upf",
    version="0.1.0",
    description="A unified multi-material particle simulation framework",
    packages=["upf"],
    package_dir={"upf": "python/upf"},
    ext_modules=[CMakeExtension("upf._upf")],
    cmdclass={"build_ext": CMakeBuild},
    python_requires=">=3.9",
    install_requires=["numpy"],
    zip_safe=False,
)
