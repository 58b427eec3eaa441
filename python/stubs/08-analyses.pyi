# ---- analyses ----------------------------------------------------------------------------------------
class IntegratorOptions:
    method: str
    rtol: float
    atol: float
    max_step: float
    max_steps: int
    def __init__(self, method: str = "rk", rtol: float = 1e-6, atol: float = 1e-8, max_step: float = 0.0,
                 max_steps: int = 50000000) -> None: ...

class RunStats:
    steps: int
    rhs_evals: int
    wall_s: float
    max_violation: float
    max_velocity_violation: float
    t_max_violation: float

class RunOptions:
    min_spans: int
    max_spans: int
    tolerance: float
    settled_spans: int
    window_spans: int
    samples_per_span: int
    integrator: IntegratorOptions
    fixed_spans: bool
    filter_cutoff: float
    filter_order: int
    allow_supercritical: bool
    def __init__(self, **kwargs: Any) -> None: ...

class ContactStatistics:
    mean: float
    std: float
    max: float
    min: float
    stat_max: float
    stat_min: float
    loss_pct: float
    samples: int

def statistics(F: ArrayLike) -> ContactStatistics: ...

class OutputSummary:
    name: str
    initial: float
    min: float
    max: float
    mean: float
    samples: int

class Result:
    """Sampled outputs; r['C_y'] and r.t are read-only views of the library's vectors."""
    def __getitem__(self, name: str) -> FloatArray: ...
    def __contains__(self, name: str) -> bool: ...
    def __len__(self) -> int: ...
    def __iter__(self) -> Iterator[str]: ...
    def keys(self) -> list[str]: ...
    @property
    def t(self) -> FloatArray: ...
    @property
    def names(self) -> list[str]: ...
    @property
    def n_samples(self) -> int: ...
    @property
    def data(self) -> FloatArray: ...
    def to_dict(self) -> dict[str, FloatArray]: ...
    def summary(self, from_t: float = 0.0) -> list[OutputSummary]: ...
    @property
    def wall_s(self) -> float: ...
    @property
    def stats(self) -> Optional[RunStats]: ...
    @property
    def assembly(self) -> Optional[AssemblyReport]: ...
    @property
    def equilibrium(self) -> Optional[EquilibriumReport]: ...
    @property
    def steady(self) -> Optional[list[OutputSummary]]: ...
    @property
    def t_end(self) -> Optional[float]: ...
    @property
    def sample(self) -> Optional[float]: ...

def summarise(result: Result, from_t: float) -> list[OutputSummary]: ...
def simulate(model: Model, t_end: Optional[float] = None, sample: Optional[float] = None, *, from_equilibrium: bool = False,
             steady_from: float = -1.0, integrator: Optional[IntegratorOptions] = None, method: Optional[str] = None,
             rtol: Optional[float] = None, atol: Optional[float] = None, max_step: Optional[float] = None,
             progress: Optional[Callable[[float, float], None]] = None) -> Result: ...

class ContactSummary:
    stats: ContactStatistics
    first_loss_t: float
    first_loss_x: float
    lost_samples: int

class CoupledResult:
    @property
    def histories(self) -> list[Result]: ...
    def __getitem__(self, name: str) -> FloatArray: ...
    @property
    def t(self) -> FloatArray: ...
    @property
    def names(self) -> list[str]: ...
    @property
    def contacts(self) -> list[ContactSummary]: ...
    @property
    def stats(self) -> RunStats: ...
    @property
    def speed(self) -> float: ...
    @property
    def span(self) -> float: ...
    @property
    def t_end(self) -> float: ...
    @property
    def sample(self) -> float: ...
    @property
    def window_from(self) -> float: ...
    @property
    def section(self) -> Section: ...
    @property
    def support_x(self) -> FloatArray: ...
    @property
    def supports(self) -> Result: ...
    @property
    def quality(self) -> list[ContactQuality]: ...
    @property
    def uplift(self) -> list[SupportUplift]: ...
    @property
    def wall_s(self) -> float: ...

ModelsOnLine = Union[Model, Sequence[PantographOnLine]]

def simulate_coupled(model: ModelsOnLine, catenary: CatenaryLike, speed: float, *, contact: ContactLike = None,
                     positions: Optional[ArrayLike] = None, spans: int = 12, t_end: Optional[float] = None,
                     sample: Optional[float] = None,
                     window_spans: int = 2, integrator: Optional[IntegratorOptions] = None,
                     method: Optional[str] = None, rtol: Optional[float] = None, atol: Optional[float] = None,
                     max_step: Optional[float] = None,
                     progress: Optional[Callable[[float, float], None]] = None,
                     max_seconds: Optional[float] = 600.0, allow_supercritical: bool = False) -> CoupledResult: ...

class SpeedResult:
    speed: float
    stats: ContactStatistics
    contacts: list[ContactStatistics]
    spans: int
    sigma_change: float
    converged: bool
    floquet: float
    @property
    def stable(self) -> bool: ...
    @property
    def t(self) -> FloatArray: ...
    @property
    def F(self) -> FloatArray: ...
    @property
    def support_x(self) -> FloatArray: ...
    @property
    def support_uplift(self) -> FloatArray: ...
    filtered: list[ContactStatistics]
    overlap: list[ContactStatistics]
    overlap_filtered: list[ContactStatistics]
    loss_runs: list[list[int]]
    sample_dt: float
    uplift_limit: float
    uplift_limited: bool

class SweepResult:
    def __init__(self, results: Sequence[SpeedResult], wall_s: float = 0.0, method: str = "time") -> None: ...
    def __len__(self) -> int: ...
    def __getitem__(self, i: int) -> SpeedResult: ...
    @property
    def results(self) -> list[SpeedResult]: ...
    @property
    def speed(self) -> FloatArray: ...
    @property
    def mean(self) -> FloatArray: ...
    @property
    def std(self) -> FloatArray: ...
    @property
    def max(self) -> FloatArray: ...
    @property
    def min(self) -> FloatArray: ...
    @property
    def stat_max(self) -> FloatArray: ...
    @property
    def stat_min(self) -> FloatArray: ...
    @property
    def loss_pct(self) -> FloatArray: ...
    @property
    def spans(self) -> npt.NDArray[np.int32]: ...
    @property
    def sigma_change(self) -> FloatArray: ...
    @property
    def converged(self) -> FloatArray: ...
    @property
    def floquet(self) -> FloatArray: ...
    @property
    def stable(self) -> FloatArray: ...
    @property
    def sigma_max(self) -> Tuple[float, float, float]: ...
    @property
    def wall_s(self) -> float: ...
    @property
    def method(self) -> str: ...

def sweep(model: ModelsOnLine, catenary: CatenaryLike, speeds: ArrayLike, *, contact: ContactLike = None,
          positions: Optional[ArrayLike] = None, options: Optional[RunOptions] = None, method: Optional[str] = None,
          rtol: Optional[float] = None, atol: Optional[float] = None,
          progress: Optional[Callable[[int, int], None]] = None,
          max_seconds: Optional[float] = 600.0) -> SweepResult: ...

class AcceptanceCriteria:
    name: str
    source: str
    filter_cutoff: float
    filter_order: int
    has_target: bool
    def target(self, speed: float) -> float: ...  # InvalidArgument outside target_speeds
    @property
    def target_speeds(self) -> tuple[float, float]: ...  # km/h, to included
    @property
    def arcing_text(self) -> str: ...

def load_acceptance(criteria: Union[str, os.PathLike[str]]) -> AcceptanceCriteria: ...
def data_dir() -> str: ...  # criteria/, models/, scripts/: $INERTA_DATA_DIR, an installed share/inerta, or the source tree
def acceptance_presets() -> list[str]: ...
def acceptance(result: Union[SweepResult, CoupledResult],
               criteria: Union[str, os.PathLike[str], AcceptanceCriteria]) -> np.ndarray: ...

class Verdict:
    @property
    def status(self) -> str: ...  # 'PASS', 'FAIL' or 'NOT ASSESSED'
    failed: list[str]
    not_assessed: list[str]
    def __bool__(self) -> bool: ...

def verdict(result: Union[SweepResult, CoupledResult],
            criteria: Union[str, os.PathLike[str], AcceptanceCriteria]) -> Verdict: ...

class AeroFit:
    reached: bool
    a: float
    mean: float
    mean_without: float
    target: float
    runs: int

def fit_aerodynamic(model: Model, catenary: CatenaryLike, speed: float,
                    criteria: Union[str, os.PathLike[str], AcceptanceCriteria], *,
                    contact: ContactLike = None) -> AeroFit: ...

class Trim:
    def __init__(self) -> None: ...
    speed: float
    target: float
    periodic: bool
    harmonics: int
    tolerance: float

class WorkingRange:
    def __init__(self, below: float = 0.1, above: float = 0.1, points: int = 5) -> None: ...
    below: float
    above: float
    points: int

class Commissioning:
    operating_length: float
    static_stiffness: float
    static_force: float
    head_offset: float
    a: float
    mean: float
    mean_without: float
    target: float
    trimmed: bool
    reached: bool
    runs: int
    range_height: list[float]
    range_force: list[float]
    range_model: list[float]
    def range_min(self) -> float: ...
    def range_max(self) -> float: ...

def commission(model: Model, catenary: CatenaryLike, speed: Optional[float] = None,
               criteria: Union[None, str, os.PathLike[str], AcceptanceCriteria] = None, *,
               suspension: Union[None, str, Network] = None, params: Optional[dict[str, float]] = None,
               contact: ContactLike = None, working_range: WorkingRange = ...) -> tuple[Model, Commissioning]: ...
def static_force_at(model: Model, offset: float) -> float: ...
def sweep_periodic(model: Model, catenary: CatenaryLike, speeds: ArrayLike, *, contact: ContactLike = None,
                   harmonics: int = 8) -> SweepResult: ...
class RunComparison:
    speed: float
    reference: SpeedResult
    candidate: SpeedResult
    reference_s: float
    candidate_s: float
def compare(model: Model, reference: CatenaryLike, candidate: CatenaryLike, speeds: ArrayLike, *,
            contact: ContactLike = None) -> list[RunComparison]: ...
def estimated_seconds(model: ModelsOnLine, catenary: CatenaryLike, speed: float, t_end: Optional[float] = None, *,
                      contact: ContactLike = None, positions: Optional[ArrayLike] = None) -> float: ...
def estimated_sweep_seconds(model: ModelsOnLine, catenary: CatenaryLike, speeds: ArrayLike, *, contact: ContactLike = None,
                            positions: Optional[ArrayLike] = None) -> float: ...
def run_speed(model: ModelsOnLine, catenary: CatenaryLike, speed: float, *, contact: ContactLike = None,
              positions: Optional[ArrayLike] = None, options: Optional[RunOptions] = None, method: Optional[str] = None,
              rtol: Optional[float] = None, atol: Optional[float] = None) -> SpeedResult: ...

class LinearModel:
    equilibrium: State
    t: float
    N: FloatArray
    Nt: FloatArray
    independent: list[int]
    A: FloatArray
    M: FloatArray
    C: FloatArray
    K: FloatArray
    dof: int
    nz: int

class Mode:
    eigenvalue: complex
    frequency_hz: float
    damped_frequency_hz: float
    damping_ratio: float
    shape: FloatArray
    description: str

def linearise(model: Model, state: State, t: float = 0.0) -> LinearModel: ...
def modes(model: Model, linear: LinearModel) -> list[Mode]: ...

class ModalAnalysis:
    setting: str
    @property
    def model(self) -> Model: ...
    equilibrium: State
    linear: LinearModel
    modes: list[Mode]
    @property
    def frequencies(self) -> FloatArray: ...
    @property
    def damping_ratios(self) -> FloatArray: ...
    def to_json(self) -> dict[str, Any]: ...

def modal_analysis(model: Model, catenary: Optional[CatenaryLike] = None, contact: ContactLike = None) -> ModalAnalysis: ...
def modal_analysis_free_head(model: Model) -> ModalAnalysis: ...
def linear_model_json(model: Model, linear: LinearModel) -> dict[str, Any]: ...
def write_linear_model(path: PathLike, model: Model, linear: LinearModel) -> None: ...

class Frf:
    def __init__(self, f: ArrayLike, outputs: Sequence[str], H: npt.ArrayLike) -> None: ...
    @property
    def f(self) -> FloatArray: ...
    @property
    def outputs(self) -> list[str]: ...
    @property
    def H(self) -> ComplexArray: ...
    def __getitem__(self, name: str) -> ComplexArray: ...

class SteppedSine:
    vc: float
    cycles: int
    analysed: int
    samples_per_cycle: int
    integrator: IntegratorOptions
    def __init__(self) -> None: ...

def frf_linear(model: Model, outputs: Sequence[str], f: ArrayLike) -> Frf: ...
def frf_stepped_sine(model: Model, outputs: Sequence[str], f: ArrayLike, *, options: Optional[SteppedSine] = None,
                     vc: Optional[float] = None, cycles: Optional[int] = None,
                     analysed: Optional[int] = None) -> Frf: ...

class CatenaryResponse:
    fp: float
    speed: float
    acc_amplitude: float
    disp_amplitude: float
    mean_uplift: float
    growth: float
    def stable(self) -> bool: ...

class CatenaryResponses:
    def __len__(self) -> int: ...
    def __getitem__(self, i: int) -> CatenaryResponse: ...
    @property
    def fp(self) -> FloatArray: ...
    @property
    def speed(self) -> FloatArray: ...
    @property
    def acc_amplitude(self) -> FloatArray: ...
    @property
    def disp_amplitude(self) -> FloatArray: ...
    @property
    def mean_uplift(self) -> FloatArray: ...
    @property
    def growth(self) -> FloatArray: ...
    @property
    def stable(self) -> npt.NDArray[np.bool_]: ...

def catenary_response(catenary: Union[LumpedCatenary, CatenaryLike], fp: ArrayLike, force: float = 70.0,
                      settle: float = 60.0, periods: int = 10) -> CatenaryResponses: ...

