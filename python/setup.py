"""Packaging of the crspline Python module (classic scikit-build).

The CMake project is python/CMakeLists.txt used standalone: it adds the
header-only core from the parent folder (../include) and installs the
compiled `_crspline` into the `crspline` package.
"""
import pathlib
import re

from setuptools import find_packages
from skbuild import setup

HERE = pathlib.Path(__file__).resolve().parent
VERSION = re.search(r'version = "([^"]+)"', (HERE.parent / "include/crspline/version.hpp").read_text()).group(1)

setup(
    name="crspline",
    version=VERSION,
    description="Cubic Catmull-Rom curves in any dimension, over NumPy",
    long_description="Python bindings of the crspline C++ library; see docs/python.md.",
    # The package and any subpackage (every module in them ships: the
    # package is split one job a module).
    packages=find_packages(include=["crspline", "crspline.*"]),
    package_data={"crspline": ["py.typed", "*.pyi"]},
    cmake_source_dir=".",
    cmake_args=["-DCMAKE_BUILD_TYPE=Release"],
    install_requires=["numpy"],
    python_requires=">=3.9",
    zip_safe=False,
)
