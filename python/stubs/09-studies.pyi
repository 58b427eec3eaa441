# ---- studies -----------------------------------------------------------------------------------------
class ContactLimits:
    mean_min: float
    mean_max: float
    loss_max: float
    statistical_min: float
    uplift_max: float
    @property
    def acceptance(self) -> Optional[AcceptanceCriteria]: ...
    def any(self) -> bool: ...

class ElementBounds:
    lo: float
    hi: float

class Study:
    def __init__(self, pantograph: Model, catenaries: Union[CatenaryLike, Sequence[CatenaryLike]],
                 speeds: ArrayLike, layouts: Sequence[str], *, contact: ContactLike = None,
                 labels: Optional[Sequence[str]] = None, search: Optional[SearchOptions] = None, lo: float = 0.1,
                 hi: float = 1e9, harmonics: int = 8, name: str = "") -> None: ...
    name: str
    source: str
    positions: list[float]
    @property
    def pantograph(self) -> Model: ...
    @property
    def catenaries(self) -> list[Catenary]: ...
    catenary_labels: list[str]
    contact: Contact
    @property
    def speeds(self) -> FloatArray: ...
    layouts: list[str]
    search: SearchOptions
    lo: float
    hi: float
    harmonics: int
    operating_length: list[float]
    trim: Optional[Trim]
    working_range: WorkingRange
    @property
    def objective(self) -> str: ...
    @property
    def reference(self) -> Catenary: ...
    @property
    def method(self) -> str: ...
    limits: ContactLimits
    bounds: dict[str, ElementBounds]
    @property
    def coarse(self) -> Optional[Study]: ...
    refine: SearchOptions
    worst_speed_first: bool
    refine_candidates: int
    refine_networks: int
    refine_screen: int
    @property
    def refine_optimiser(self) -> str: ...
    @property
    def all_networks(self) -> bool: ...
    def replace(self, *, speeds: Optional[ArrayLike] = None, layouts: Optional[Sequence[str]] = None,
                search: Optional[SearchOptions] = None, lo: Optional[float] = None, hi: Optional[float] = None,
                harmonics: Optional[int] = None, name: Optional[str] = None) -> Study: ...

def load_study(path: PathLike) -> Study: ...
def operating_lengths(study: Study) -> list[float]: ...

class StudyCost:
    J: float
    speed: float
    mean: float
    catenary: int
    unstable_speed: float
    excess: float
    floquet: float
    def settling_spans(self) -> float: ...
    feasible: bool
    violation: str
    mean_min: float
    mean_max: float
    loss_pct: float
    statistical_min: float
    uplift: float
    binding: str
    binding_margin: float
    sigma: float
    commissioning: Optional[Commissioning]
    def penalised(self) -> float: ...

class LayoutResult:
    layout: str
    expression: str
    values: dict[str, float]
    cost: StudyCost
    evaluations: int
    unstable: int
    budget_exhausted: bool
    stock: bool
    at_bounds: list[str]
    coarse_values: dict[str, float]
    coarse_cost: StudyCost
    coarse_here: StudyCost
    coarse_evaluations: int
    ends: list[tuple[dict[str, float], float]]
    refined_from: int
    def network(self) -> Network: ...

def default_suspension(study: Study) -> Network: ...
def evaluate(study: Study, network: NetworkLike, params: Optional[Params] = None) -> StudyCost: ...
def evaluate_batch(study: Study, designs: Sequence[Union[NetworkLike, Tuple[NetworkLike, Optional[Params]]]]) -> list[StudyCost]: ...
def evaluate_time(study: Study, network: NetworkLike, params: Optional[Params] = None) -> StudyCost: ...
def free_parameters(layout: str) -> list[str]: ...
def estimated_evaluation_seconds(study: Study) -> float: ...

class StudyEstimate:
    search_evaluations: int
    refine_evaluations: int
    search_seconds: float
    refine_seconds: float
    @property
    def seconds(self) -> float: ...

def estimated_study_seconds(study: Study) -> StudyEstimate: ...
def cost_of(study: Study, sweeps: Sequence[Sequence[SpeedResult]]) -> StudyCost: ...
def search_variables(study: Study, layout: str) -> list[Variable]: ...
def study_table(study: Study, default_cost: StudyCost, results: Sequence[LayoutResult]) -> str: ...
def prepare_output_folder(dir: PathLike, owned: Sequence[str], force: bool) -> None: ...
def study_output_names() -> list[str]: ...
class DesignCost:
    cost: float
    unstable: bool
    J: float
    excess: float
    def __init__(self) -> None: ...

def design_cost(study: Study, layout: str, params: dict[str, float]) -> DesignCost: ...
def optimise_layout(study: Study, layout: str, *,
                    progress: Optional[Callable[[int, int, float], None]] = None,
                    batch: Optional[Callable[[list[dict[str, float]]], list[DesignCost]]] = None) -> LayoutResult: ...
def refine_layout(study: Study, layout: str, coarse: LayoutResult) -> LayoutResult: ...

class SpeedCurve:
    catenary: str
    @property
    def speed(self) -> FloatArray: ...
    @property
    def sigma(self) -> FloatArray: ...
    @property
    def mean(self) -> FloatArray: ...

def sigma_curves(study: Study, network: NetworkLike, params: Optional[Params] = None) -> list[SpeedCurve]: ...
def sigma_curves_time(study: Study, network: NetworkLike, params: Optional[Params] = None, *, centripetal: bool = True,
                      progress: Optional[Callable[[int, int], None]] = None) -> list[SpeedCurve]: ...
def worst_of(curves: Sequence[SpeedCurve]) -> StudyCost: ...
def rig_model(study: Study, network: NetworkLike, params: Optional[Params] = None) -> Model: ...

class ForceHistory:
    catenary: str
    speed: float
    @property
    def t(self) -> FloatArray: ...
    @property
    def F(self) -> FloatArray: ...
    stats: ContactStatistics

def contact_histories(study: Study, network: NetworkLike, speed: float,
                      params: Optional[Params] = None) -> list[ForceHistory]: ...

class CostMap:
    layout: str
    x: str
    y: str
    values: dict[str, float]
    @property
    def xs(self) -> FloatArray: ...
    @property
    def ys(self) -> FloatArray: ...
    @property
    def J(self) -> FloatArray: ...

def cost_map(study: Study, layout: str, values: Params, x: str, xs: ArrayLike, y: str, ys: ArrayLike, *,
             progress: Optional[Callable[[int, int], None]] = None) -> CostMap: ...
def best_with(results: Sequence[LayoutResult], x: str, y: str) -> int: ...
def has_inerter(network: Network) -> bool: ...

class Design:
    label: str
    layout: str
    values: dict[str, float]
    net: Network

class ReportOptions:
    history_speed: float
    frf_f: list[float]
    frf_output: str
    map_size: int
    map_b_max: float
    map_k_max: float
    best: int
    def __init__(self) -> None: ...

class ReportCentripetal:
    design: Design
    on: list[SpeedCurve]
    off: list[SpeedCurve]
    off_simulated: bool

class Report:
    study: str
    catenaries: list[str]
    baseline: Design
    best: Design
    default_cost: StudyCost
    best_cost: StudyCost
    sigma_default: list[SpeedCurve]
    sigma_best: list[SpeedCurve]
    frf_output: str
    frf_default: Frf
    frf_best: Frf
    history_speed: float
    history_default: list[ForceHistory]
    history_best: list[ForceHistory]
    map: Optional[CostMap]
    map_note: str
    map_opt_x: float
    map_opt_y: float
    map_opt_J: float
    centripetal: list[ReportCentripetal]
    time_check: StudyCost
    acceptance: str
    margins: list[MarginRow]

class MarginRow:
    design: str
    catenary: str
    speed: float
    contact: int
    criterion: str
    value: float
    limit: float
    unit: str
    margin: float
    assessed: bool
    passed: bool
    relative: float

def make_report(study: Study, results: Sequence[LayoutResult], options: Optional[ReportOptions] = None, *,
                progress: Optional[Callable[[int, int, str, int, int], None]] = None) -> Report: ...
def write_study_report(report: Report, dir: PathLike) -> list[str]: ...
@overload
def write_study_results(dir: PathLike, study: str, default_cost: StudyCost,
                        results: Sequence[LayoutResult]) -> list[str]: ...
@overload
def write_study_results(result: ModelStudyResult, dir: PathLike) -> list[str]: ...
def study_results_json(study: str, default_cost: StudyCost, results: Sequence[LayoutResult]) -> dict[str, Any]: ...

