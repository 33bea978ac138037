"""pip's road to the Python module amls: configures the project with CMake (into $AMLS_BUILD_DIR,
else ./build, the folder scripts/setup.sh builds, so nothing built there is compiled again), builds
only the module's target, and installs the module with its type stub. Needs what scripts/setup.sh
installs (cmake, ninja, a compiler, pybind11-dev, python3-dev and the core's libraries); no network.
"""
import glob
import os
import shutil
import subprocess
import sys

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

SOURCE_DIR = os.path.dirname(os.path.abspath(__file__))


class CMakeModule(Extension):
    def __init__(self, name):
        super().__init__(name, sources=[])


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        build_dir = os.environ.get("AMLS_BUILD_DIR", os.path.join(SOURCE_DIR, "build"))
        configure = ["cmake", "-S", SOURCE_DIR, "-B", build_dir, "-G", "Ninja", "-DCMAKE_BUILD_TYPE=Release",
                     "-DAMLS_PYTHON=ON", f"-DPython3_EXECUTABLE={sys.executable}"]
        if os.path.exists(os.path.join(build_dir, "CMakeCache.txt")):
            # Keep the folder's own generator and settings; only ask for the module.
            configure = ["cmake", "-S", SOURCE_DIR, "-B", build_dir, "-DAMLS_PYTHON=ON",
                         f"-DPython3_EXECUTABLE={sys.executable}"]
        subprocess.check_call(configure)
        subprocess.check_call(["cmake", "--build", build_dir, "--target", "amls_python"])
        built = glob.glob(os.path.join(build_dir, "python", "amls.*.so"))
        if len(built) != 1:
            raise RuntimeError(f"expected one amls.*.so in {build_dir}/python, found {built}")
        target = self.get_ext_fullpath(ext.name)
        os.makedirs(os.path.dirname(target), exist_ok=True)
        shutil.copyfile(built[0], target)
        shutil.copyfile(os.path.join(SOURCE_DIR, "python", "amls.pyi"), os.path.join(os.path.dirname(target), "amls.pyi"))


setup(
    name="amls",
    version="0.1.0",
    description="Deforming point-set (AMLS) surfaces with grid-based resampling",
    ext_modules=[CMakeModule("amls")],
    cmdclass={"build_ext": CMakeBuild},
    zip_safe=False,
)
