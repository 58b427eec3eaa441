# ---- linear analysis of any model and model studies (docs/linear-analysis.md, docs/studies.md) ----
class LinearSystem:
    lin: LinearModel
    inputs: list[str]
    outputs: list[str]
    motion: list[bool]
    joint: list[int]
    B0: FloatArray
    B1: FloatArray
    B2: FloatArray
    Cy: FloatArray
    D0: FloatArray
    D1: FloatArray
    D2: FloatArray

def linear_system(model: Model, state: State, inputs: Sequence[str], outputs: Sequence[str], t: float = 0.0) -> LinearSystem: ...
def state_names(model: Model, linear: LinearModel) -> list[str]: ...

class UndampedMode:
    frequency_hz: float
    shape: FloatArray
    description: str

def undamped_modes(model: Model, linear: LinearModel) -> list[UndampedMode]: ...

class StateSpace:
    model: str
    states: list[str]
    inputs: list[str]
    outputs: list[str]
    input_units: list[str]
    A: FloatArray
    B: FloatArray
    C: FloatArray
    D: FloatArray
    D1: FloatArray
    D2: FloatArray
    T0: FloatArray
    T1: FloatArray
    system: LinearSystem
    def has_rate_feedthrough(self) -> bool: ...

def state_space(model: Model, inputs: Sequence[str], outputs: Sequence[str], *, state: Optional[State] = None,
                t: float = 0.0) -> StateSpace: ...
def frequency_response(state_space: StateSpace, f_hz: ArrayLike) -> Any: ...

class RandomResponse:
    outputs: list[str]
    rms: FloatArray
    covariance: FloatArray

def white_noise_response(state_space: StateSpace, W: ArrayLike) -> RandomResponse: ...

class Road:
    gd0: float
    speed: float
    inputs: list[str]
    delays: list[float]
    pade_order: int
    def __init__(self) -> None: ...

def road_response(state_space: StateSpace, road: Road) -> RandomResponse: ...
def road_velocity_intensity(gd0: float, speed: float) -> float: ...
def lyapunov(A: ArrayLike, Q: ArrayLike) -> FloatArray: ...

class WeightedOutput:
    name: str
    weight: float

class RmsLimit:
    output: str
    limit: float

class Objective:
    kind: str
    outputs: list[WeightedOutput]
    limits: list[RmsLimit]
    input: str
    frequencies: list[float]

class ModelStudy:
    name: str
    source: str
    model: Model
    strut: int
    objective: Objective
    layouts: list[str]

def load_model_study(path: Any) -> ModelStudy: ...
def is_model_study(path: Any) -> bool: ...

class ModelCost:
    J: float
    penalised: float
    values: list[float]
    limit_values: list[float]
    frequency: float
    feasible: bool

class ModelLayoutResult:
    layout: str
    expression: str
    values: dict[str, float]
    at_bounds: list[str]
    cost: ModelCost
    evaluations: int
    budget_exhausted: bool

def default_network(study: ModelStudy) -> Network: ...
def evaluate_model(study: ModelStudy, layout: str, params: dict[str, float] = ...) -> ModelCost: ...
def optimise_model_layout(study: ModelStudy, layout: str, warm: Sequence[dict[str, float]] = ...) -> ModelLayoutResult: ...
def with_strut_network(model: Model, strut: int, layout: str, params: dict[str, float] = ...) -> Model: ...

class ObjectiveMap:
    layout: str
    x_name: str
    y_name: str
    x: list[float]
    y: list[float]
    J: list[list[float]]

def objective_map(study: ModelStudy, layout: str, values: dict[str, float], x: str, y: str, n: int = 15,
                  decades: float = 1.0) -> ObjectiveMap: ...

class StudyFrf:
    input: str
    outputs: list[str]
    f: list[float]
    magnitude: list[list[float]]

def study_frf(study: ModelStudy, layout: str, params: dict[str, float], f_hz: ArrayLike) -> StudyFrf: ...

