"""Package layout that pyproject.toml cannot state alone.

The code lives in ``src/``; the MJCF model folders stay at the repository root in
``models/`` (MuJoCo Menagerie layout) and ship as the data package
``wmr_mujoco.model_files``, one sub-package per robot folder, found at run time through
:mod:`importlib.resources` (``wmr_mujoco.models.paths``). A robot folder added to
``models/`` is picked up with no edit here.
"""

from pathlib import Path

from setuptools import find_packages, setup

MODEL_PACKAGE = "wmr_mujoco.model_files"
#: What a model folder ships: MJCF, its README/CHANGELOG, pictures, meshes and textures.
MODEL_FILES = ["*.xml", "*.md", "*.png", "*.stl", "*.obj", "assets/*", "meshes/*"]

robot_folders = sorted(d.name for d in Path(__file__).parent.joinpath("models").iterdir()
                       if d.is_dir())
model_packages = [MODEL_PACKAGE, *(f"{MODEL_PACKAGE}.{name}" for name in robot_folders)]

setup(
    packages=[*find_packages("src"), *model_packages],
    package_dir={"": "src", MODEL_PACKAGE: "models"},
    package_data={package: MODEL_FILES for package in model_packages},
)
