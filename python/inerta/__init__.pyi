# Type stubs of the package: the compiled bindings (_inerta.pyi) and the Python helpers.
from typing import Any, Optional, Sequence

import numpy as np
import numpy.typing as npt

from ._inerta import *  # noqa: F401,F403
from ._inerta import ModelStudy, Result, Study, StudyOutcome, SweepResult
from . import distributed as distributed

__version__: str

def kmh(v: Any) -> Any:
    """km/h → m/s (v / 3.6), a number or an array."""

def plot_sweep(result: SweepResult, ax: Any = None, label: Optional[str] = None, unit: str = "kmh",
               **kwargs: Any) -> Any: ...
def plot_result(result: Result, names: Optional[Sequence[str]] = None, ax: Any = None, **kwargs: Any) -> Any: ...
def sweep(model: Any, catenary: Any, speeds: Any, *, client: Any = None, contact: Any = None, positions: Any = None,
          options: Any = None, method: Optional[str] = None, rtol: Optional[float] = None, atol: Optional[float] = None,
          progress: Any = None) -> SweepResult:
    """Speed sweep in the time domain; with client (dask.distributed.Client) one task per speed."""

def optimise(study: Any, *, out: Any = None, client: Any = None, progress: Any = None, checkpoint: Any = None,
             force: bool = False, stats: Optional[dict] = None, early_stops: bool = True) -> StudyOutcome:
    """A whole study in one call (run_study); with client its evaluations on Dask, with out its files."""
