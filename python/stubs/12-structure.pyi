# ---- exhaustive structure search and the admittance bound (docs/networks.md) -------------------------
class StructureEntry:
    expression: str
    counts: ElementCounts
    values: dict[str, float]
    J: float
    cost: float
    feasible: bool
    evaluations: int
    unstable: int
    reduced: str
    reduced_structure: str
    reduced_counts: ElementCounts
    warm_from: str
    seconds: float
    def reduces(self) -> bool: ...

def reduced_design(entry: StructureEntry) -> tuple[str, dict[str, float]] | None: ...
def ranking(entries: Sequence[StructureEntry]) -> list[int]: ...

class ParetoPoint:
    elements: int
    inerters: int
    J: float
    network: str
    entry: int
    pareto: bool

def pareto_points(entries: Sequence[StructureEntry]) -> list[ParetoPoint]: ...
def prune(expression: str, values: dict[str, float], cost: Callable[[dict[str, float]], float],
          tolerance: float = 1e-4) -> dict[str, float]: ...
@overload
def optimise_all(study: Study, *, progress: Optional[Callable[[int, int, float, float, float], None]] = None
                 ) -> Tuple[list[StructureEntry], list[LayoutResult]]: ...
@overload
def optimise_all(study: ModelStudy, *, progress: Optional[Callable[[int, int, float, float, float], None]] = None
                 ) -> Tuple[list[StructureEntry], list[ModelLayoutResult]]: ...

class ModelStudyResult:
    study: ModelStudy
    baseline: Network
    baseline_cost: ModelCost
    results: list[ModelLayoutResult]
    entries: list[StructureEntry]
    best: int
    admittance: list[AdmittanceBound]
    seconds: float

def run_model_study(study: ModelStudy, *, progress: Optional[Callable[[int, int, float], None]] = None
                    ) -> ModelStudyResult: ...
def model_study_table(result: ModelStudyResult) -> str: ...

class SearchTask:
    layout: str
    warm: list[dict[str, float]]
    network: bool
    coarse: bool
    refine: bool
    def __init__(self, layout: str, warm: Sequence[dict[str, float]] = ..., network: bool = False,
                 coarse: bool = False, refine: bool = False) -> None: ...

class CheckTask:
    layout: str
    values: dict[str, float]
    time: bool
    stop_above: float
    stop_catenary: int
    stop_speed: float
    def __init__(self, layout: str = "", values: dict[str, float] = ..., time: bool = False, stop_above: float = ...,
                 stop_catenary: int = -1, stop_speed: float = ...) -> None: ...

class CheckResult:
    cost: StudyCost
    failure: str
    stopped: bool

class ModelCheckResult:
    cost: ModelCost
    failure: str

@overload
def run_search(study: Study, task: SearchTask, *,
               batch: Optional[Callable[[list[dict[str, float]]], list[DesignCost]]] = None) -> LayoutResult: ...
@overload
def run_search(study: ModelStudy, task: SearchTask) -> ModelLayoutResult: ...
@overload
def run_check(study: Study, task: CheckTask) -> CheckResult: ...
@overload
def run_check(study: ModelStudy, task: CheckTask) -> ModelCheckResult: ...
def best_design(penalised: Sequence[float]) -> int: ...

class StudyExecutor:
    def __init__(self) -> None: ...
    @overload
    def search(self, study: Study, tasks: list[SearchTask], done: Callable[[int, LayoutResult], None],
               searching: Callable[[int, int, int, float], None]) -> list[LayoutResult]: ...
    @overload
    def search(self, study: ModelStudy, tasks: list[SearchTask], done: Callable[[int, ModelLayoutResult], None],
               searching: Callable[[int, int, int, float], None]) -> list[ModelLayoutResult]: ...
    @overload
    def check(self, study: Study, tasks: list[CheckTask]) -> list[CheckResult]: ...
    @overload
    def check(self, study: ModelStudy, tasks: list[CheckTask]) -> list[ModelCheckResult]: ...

class LocalExecutor(StudyExecutor):
    def __init__(self) -> None: ...

class StudyOptions:
    report: bool
    report_options: ReportOptions
    rechecks: int
    early_stops: bool
    def __init__(self, *, report: bool = False, report_options: Optional[ReportOptions] = None,
                 rechecks: int = 5, early_stops: bool = True) -> None: ...

class Recheck:
    entry: int
    periodic_rank: int
    time: StudyCost
    failure: str
    settling_spans: float
    stopped: bool

class Refinement:
    entry: int
    coarse_rank: int
    screen_rank: int

class Screened:
    entry: int
    coarse_rank: int
    cost: StudyCost
    failure: str
    refined: bool
    stopped: bool

class BestDesign:
    index: int
    layout: str
    expression: str
    values: dict[str, float]
    network: Network
    J: float
    J2: float
    feasible: bool
    verified: bool

class StudyOutcome:
    study: Optional[Study]
    model: Optional[ModelStudyResult]
    baseline: Network
    default_cost: StudyCost
    coarse_default_cost: StudyCost
    results: list[LayoutResult]
    entries: list[StructureEntry]
    order: list[int]
    rechecks: list[Recheck]
    refinements: list[Refinement]
    admittance: list[AdmittanceBound]
    report: Optional[Report]
    model_figures: Optional[ModelStudyFigures]
    time_check: StudyCost
    best: BestDesign
    seconds: float
    rank_agreement: float
    coarse_rank_agreement: float
    screened: list[Screened]
    stock_best: bool
    def recheck_csv(self) -> str: ...
    def refined_csv(self) -> str: ...
    def screened_csv(self) -> str: ...

def run_study(study: Union[Study, ModelStudy], options: Optional[StudyOptions] = None, *,
              progress: Optional[Callable[..., None]] = None,
              executor: Optional[StudyExecutor] = None) -> StudyOutcome: ...
def write_study_outcome(outcome: StudyOutcome, dir: str) -> list[str]: ...

class ModelStudyFigures:
    frf_default: Optional[StudyFrf]
    frf_best: Optional[StudyFrf]
    map: Optional[ObjectiveMap]

def model_study_figures(result: ModelStudyResult) -> ModelStudyFigures: ...

class AdmittanceResult:
    degree: int
    y: Rational
    J: float
    cost: float
    evaluations: int
    pr: PrTest
    synthesis: Optional[Synthesis]
    synthesis_error: str
    J_realised: float
    warm_from: str

@overload
def admittance_bound(study: Study, degree: int, warm: Network) -> AdmittanceResult: ...
@overload
def admittance_bound(study: ModelStudy, degree: int, warm: Network) -> AdmittanceResult: ...

class BoundCandidate:
    label: str
    network: Network
    cost: float
    J: float

class AdmittanceBound:
    result: AdmittanceResult
    best: Optional[BoundCandidate]
    seconds: float
    feasible: bool
    gap_pct: float

def write_admittance_results(dir: PathLike, bounds: Sequence[AdmittanceBound], default_J: float) -> list[str]: ...
def reactive_elements(network: Network) -> int: ...
def write_structure_results(dir: PathLike, study: str, objective: str, unit: str, default_J: float,
                            entries: Sequence[StructureEntry]) -> list[str]: ...
def structure_results_json(study: str, objective: str, unit: str, default_J: float,
                           entries: Sequence[StructureEntry]) -> dict[str, Any]: ...

class BuildInfo:
    @property
    def version(self) -> str: ...
    @property
    def commit(self) -> str: ...
    @property
    def modified(self) -> bool: ...
def build_info() -> BuildInfo: ...
class InputFile:
    @property
    def path(self) -> str: ...
    @property
    def what(self) -> str: ...
    @property
    def sha256(self) -> str: ...
    @property
    def bytes(self) -> int: ...
class Record:
    @property
    def command(self) -> str: ...
    @property
    def verdict(self) -> str: ...
    @property
    def numbers(self) -> dict[str, float]: ...
    @property
    def argv(self) -> list[str]: ...
    @property
    def cwd(self) -> str: ...
    @property
    def date(self) -> str: ...
    @property
    def commit(self) -> str: ...
    @property
    def inputs(self) -> list[InputFile]: ...
def read_report(path: str) -> Record: ...
class Difference:
    @property
    def key(self) -> str: ...
    @property
    def reported(self) -> float: ...
    @property
    def now(self) -> float: ...
    @property
    def missing(self) -> str: ...
def compare_reports(a: Record, b: Record, rtol: float = 0.0) -> list[Difference]: ...
def sha256(data: str) -> str: ...
def write_study_report(outcome: StudyOutcome, dir: str) -> str: ...
def report_html(result: Union[SweepResult, CoupledResult], criteria: Optional[Union[AcceptanceCriteria, PathLike]] = None,
                catenary: Optional[Union[Catenary, CatenaryFile]] = None, model: str = "") -> str: ...
