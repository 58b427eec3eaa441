# ---- identification ----------------------------------------------------------------------------------
class CsvTable:
    @staticmethod
    def read(path: PathLike) -> CsvTable: ...
    @staticmethod
    def parse(text: str, source: str) -> CsvTable: ...
    @property
    def source(self) -> str: ...
    @property
    def names(self) -> list[str]: ...
    @property
    def rows(self) -> int: ...
    def line(self, row: int) -> int: ...
    def has(self, column: str) -> bool: ...
    def column(self, name: str) -> FloatArray: ...
    def __getitem__(self, name: str) -> FloatArray: ...
    def require_rows(self, n: int, what: str) -> None: ...

class HeadSuspensionPoint:
    f: float
    k2: float
    c2: float

class HeadSuspensionFit:
    k2: float
    c2: float
    points: int
    f_lo: float
    f_hi: float
    rms_residual: float
    per_frequency: list[HeadSuspensionPoint]

def head_suspension_at(m_H: float, f: float, H: complex, E: complex) -> HeadSuspensionPoint: ...
def fit_head_suspension(m_H: float, f: ArrayLike, H: npt.ArrayLike, E: npt.ArrayLike, f_lo: float = 4.0,
                        f_hi: float = 20.0) -> HeadSuspensionFit: ...
def frf_misfit(model: Frf, measured: Frf) -> float: ...
def frf_band(frf: Frf, f_lo: float, f_hi: float) -> Frf: ...

class FrfFit:
    values: list[float]
    cost: float
    initial_cost: float
    evaluations: int
    fitted: Frf

def fit_frf(model: Union[Model, Callable[[list[float]], Model]],
            variables: Union[Sequence[Union[str, Variable]], Mapping[str, Optional[Tuple[float, float]]]],
            measured: Frf, options: Optional[SearchOptions] = None, sets: Overrides = None) -> FrfFit: ...

class LineFit:
    slope: float
    intercept: float
    points: int
    rms: float

def fit_line(x: ArrayLike, y: ArrayLike) -> LineFit: ...

class ActuatorStaticFit:
    forward: LineFit
    backward: LineFit
    F_c: float
    F_r: float
    c1: float

def fit_actuator_static(v: ArrayLike, F: ArrayLike) -> ActuatorStaticFit: ...
def maxwell_admittance(k1: float, c1: float, f: float) -> complex: ...
def harmonic_amplitude(t: ArrayLike, y: ArrayLike, f: float) -> complex: ...

class DynamicTest:
    f: float
    def __init__(self, f: float, t: ArrayLike, x: ArrayLike, F: ArrayLike) -> None: ...
    @property
    def t(self) -> FloatArray: ...
    @property
    def x(self) -> FloatArray: ...
    @property
    def F(self) -> FloatArray: ...

class AdmittancePoint:
    f: float
    Y_E: complex
    amplitude: float
    def __init__(self, f: float, Y_E: complex, amplitude: float = 0.0) -> None: ...

class ActuatorDynamicFit:
    k1: float
    c1: float
    cost: float
    points: list[AdmittancePoint]

def admittance_cost(k1: float, c1: float, points: Sequence[AdmittancePoint]) -> float: ...
def fit_actuator_dynamic(tests: Sequence[DynamicTest], c1: float, piston_mass: float, friction: float,
                         fit_c1: bool = False) -> ActuatorDynamicFit: ...


