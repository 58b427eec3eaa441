# Type stubs of the compiled bindings (python/src/*.cpp). SI units: m, s, kg, N, rad; speeds m/s;
# frequencies Hz. python/tests/test_stubs.py checks that every public name is declared here.
from __future__ import annotations

import enum
import os
from typing import Any, Callable, Iterator, Mapping, Optional, Sequence, Tuple, Union, overload

import numpy as np
import numpy.typing as npt

FloatArray = npt.NDArray[np.float64]
ComplexArray = npt.NDArray[np.complex128]
ArrayLike = Union[float, Sequence[float], npt.NDArray[Any]]
PathLike = Union[str, os.PathLike[str]]
Overrides = Union[None, str, Sequence[str], Mapping[str, Union[float, str]]]
CatenaryLike = Union["Catenary", "CatenaryFile", PathLike]
ContactLike = Union[None, "Contact", str]
NetworkLike = Union["Network", str]
Params = Mapping[str, float]

