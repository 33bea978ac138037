# Type stub of the compiled module amls (python/*.cpp); the docstrings there say what each does.
import os
from typing import Any, Literal, Optional, Union

import numpy as np
import numpy.typing as npt

__version__: str

FloatArray = npt.NDArray[np.float64]
IntArray = npt.NDArray[np.int64]
BoolArray = npt.NDArray[np.bool_]
ArrayLike = npt.ArrayLike
PathLike = Union[str, os.PathLike[str]]

# with_rim=True adds the rim marks (before the report, in resample's case) to what read and resample return.
def read(
    path: PathLike, dim: int = 0, *, with_rim: bool = False
) -> Union[tuple[FloatArray, Optional[FloatArray]], tuple[FloatArray, Optional[FloatArray], BoolArray]]: ...
def write(
    path: PathLike, points: ArrayLike, normals: Optional[ArrayLike] = None, spacing: float = 0.0, rim: Optional[ArrayLike] = None
) -> None: ...
def read_mesh(path: PathLike) -> tuple[FloatArray, IntArray]: ...
def resample(
    points: Union[ArrayLike, PathLike],
    normals: Union[ArrayLike, Literal["estimated"], None] = None,
    *,
    spacing: Optional[float] = None,
    grid: Optional[int] = None,
    radius_factor: float = 3.0,
    variant: str = "exact",
    uniform_support: bool = False,
    accept_loss: bool = False,
    dim: int = 0,
    threads: int = 1,
    mesh: str = "",
    rim: Optional[ArrayLike] = None,
    one_pass: bool = False,
    with_rim: bool = False,
    rims: bool = True,
) -> Union[tuple[FloatArray, FloatArray, dict[str, Any]], tuple[FloatArray, FloatArray, BoolArray, dict[str, Any]]]: ...
def mesh(
    points: Union[ArrayLike, PathLike],
    normals: Union[ArrayLike, Literal["estimated"], None] = None,
    *,
    spacing: Optional[float] = None,
    grid: Optional[int] = None,
    radius_factor: float = 3.0,
    variant: str = "exact",
    threads: int = 1,
    out: str = "",
) -> tuple[FloatArray, IntArray]: ...
def run_scene(
    path: str, *, resample: str = "always", threads: int = 1, tracers: float = 50.0, max_steps: int = 0
) -> tuple[FloatArray, FloatArray, dict[str, Any]]: ...

class MlsDeformation:
    def __init__(self, handles: ArrayLike, kind: str = "rigid", alpha: float = 1.0) -> None: ...
    @property
    def handles(self) -> FloatArray: ...
    @property
    def kind(self) -> str: ...
    @property
    def alpha(self) -> float: ...

class Surface:
    def __init__(
        self,
        points: Union[ArrayLike, PathLike],
        normals: Union[ArrayLike, Literal["estimated"], None] = None,
        *,
        h: Optional[float] = None,
        grid: Optional[int] = None,
        radius_factor: float = 3.0,
        variant: str = "exact",
        uniform_support: bool = False,
        threads: int = 1,
    ) -> None: ...
    @property
    def points(self) -> FloatArray: ...
    @property
    def normals(self) -> FloatArray: ...
    @property
    def rim(self) -> BoolArray: ...
    @property
    def h(self) -> float: ...
    @property
    def dimension(self) -> int: ...
    def F(self, x: ArrayLike) -> Union[float, FloatArray]: ...
    def project(self, x: ArrayLike) -> FloatArray: ...
    def resample(self) -> dict[str, Any]: ...
    def step(self, deformation: MlsDeformation, targets: ArrayLike, resample: bool = True) -> dict[str, Any]: ...
    def mesh(self, out: str = "") -> tuple[FloatArray, IntArray]: ...
