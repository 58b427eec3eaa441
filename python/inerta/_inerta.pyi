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

# ---- errors ------------------------------------------------------------------------------------------
class Error(Exception): ...
class ModelError(Error, ValueError):
    """'file:line: key: what is wrong; expected ...' — the CLI's text after 'error: '."""
class InvalidArgument(Error, ValueError):
    parameter: str
class NumericalError(Error, RuntimeError): ...
class NetworkError(Error, ValueError):
    column: int

# ---- numerics ----------------------------------------------------------------------------------------
class Variable:
    name: str
    lo: float
    hi: float
    can_open: bool
    can_rigid: bool
    def __init__(self, name: str, lo: float = 1e-3, hi: float = 1e9, can_open: bool = True, can_rigid: bool = True) -> None: ...

class SearchOptions:
    starts: int
    seed: int
    initial_step: float
    initial_values: list[list[float]]
    min_step: float
    max_evaluations: int
    def __init__(self, starts: int = 4, seed: int = 1, initial_step: float = 1.0, min_step: float = 1e-3,
                 max_evaluations: int = 5000) -> None: ...

class SearchResult:
    @property
    def values(self) -> list[float]: ...
    @property
    def u(self) -> list[float]: ...
    @property
    def cost(self) -> float: ...
    @property
    def evaluations(self) -> int: ...
    @property
    def best_start(self) -> int: ...
    @property
    def exhausted(self) -> bool: ...

class FloquetResult:
    @property
    def multipliers(self) -> npt.NDArray[np.complex128]: ...
    @property
    def largest(self) -> float: ...
    @property
    def stable(self) -> bool: ...

def monodromy(A: npt.ArrayLike, b: npt.ArrayLike, r: Callable[[float], npt.ArrayLike], T: float,
              steps: int = 256) -> FloatArray: ...
def floquet(A: npt.ArrayLike, b: npt.ArrayLike, r: Callable[[float], npt.ArrayLike], T: float,
            steps: int = 256) -> FloquetResult: ...

def decode(variable: Variable, u: float) -> float: ...
def describe(value: float) -> str: ...
def pattern_search(variables: Sequence[Variable], cost: Callable[[list[float]], float],
                   options: Optional[SearchOptions] = None, *,
                   progress: Optional[Callable[[int, int, float], None]] = None) -> SearchResult: ...
def model_search(variables: Sequence[Variable], cost: Callable[[list[float]], Union[float, tuple[float, float]]],
                 options: SearchOptions, *, optimiser: str = "bobyqa",
                 progress: Optional[Callable[[int, int, float], None]] = None) -> SearchResult: ...

class CubicSpline:
    def __init__(self, x: Sequence[float], y: Sequence[float], ends: str = "natural") -> None: ...
    def __call__(self, x: ArrayLike) -> Any: ...
    def value(self, x: ArrayLike) -> Any: ...
    def slope(self, x: ArrayLike) -> Any: ...
    def curvature(self, x: ArrayLike) -> Any: ...
    def mean(self) -> float: ...
    @property
    def x_min(self) -> float: ...
    @property
    def x_max(self) -> float: ...

# ---- networks ----------------------------------------------------------------------------------------
class Network:
    class Kind(enum.Enum):
        spring = ...
        damper = ...
        inerter = ...
        series = ...
        parallel = ...
        open = ...
        rigid = ...
        admittance = ...
    def __init__(self, expression: str) -> None: ...
    @property
    def kind(self) -> Network.Kind: ...
    @property
    def name(self) -> str: ...
    @property
    def value(self) -> float: ...
    @property
    def children(self) -> list[Network]: ...
    @property
    def column(self) -> int: ...
    @property
    def num(self) -> list[float]: ...
    @property
    def den(self) -> list[float]: ...
    def is_element(self) -> bool: ...
    def parameter_names(self) -> list[str]: ...
    def assign(self, params: Params) -> Network: ...
    def simplify(self) -> Network: ...
    def to_string(self, with_values: bool = False) -> str: ...
    def admittance(self, s: Union[complex, npt.ArrayLike]) -> Any:
        """Y(s) = F / relative velocity, N·s/m; s in rad/s (s = 2j·π·f)."""

def parse(expression: str) -> Network: ...
def parameter_names(network: Network) -> list[str]: ...
def assign(network: Network, params: Params) -> Network: ...
def simplify(network: Network) -> Network: ...
def to_string(network: Network, with_values: bool = False) -> str: ...
def admittance(network: Network, s: Union[complex, npt.ArrayLike]) -> Any: ...

class Layout:
    @property
    def name(self) -> str: ...
    @property
    def expression(self) -> str: ...
    @property
    def fixed(self) -> dict[str, float]: ...
    @property
    def note(self) -> str: ...

def layouts() -> list[Layout]: ...
def find_layout(name: str) -> Optional[Layout]: ...
def resolve(layout: str, params: Optional[Params] = None) -> Network: ...
def draw_network(network: Union[Network, str], params: Optional[Params] = None, title: str = "") -> str: ...

class Rational:
    @property
    def num(self) -> list[float]: ...
    @property
    def den(self) -> list[float]: ...
    def __call__(self, s: Union[complex, npt.ArrayLike]) -> Any: ...

def rational_admittance(simplified: Network) -> Rational: ...

class Realisation:
    @property
    def d0(self) -> float: ...
    @property
    def d1(self) -> float: ...
    @property
    def d2(self) -> float: ...
    @property
    def A(self) -> FloatArray: ...
    @property
    def B(self) -> FloatArray: ...
    @property
    def C(self) -> FloatArray: ...
    @property
    def n_states(self) -> int: ...
    def dynamic_stiffness(self, s: Union[complex, npt.ArrayLike]) -> Any: ...
    def static_stiffness(self) -> float: ...
    def steady_state(self, u: float) -> FloatArray: ...

def realise(simplified: Network) -> Realisation: ...

# ---- every network up to N elements, positive-real test, synthesis (docs/networks.md) ---------------
class ElementCounts:
    elements: int
    springs: int
    dampers: int
    inerters: int

def count_elements(network: Network) -> ElementCounts: ...
def static_path(network: Network) -> bool: ...
def canonical(network: Network) -> Network: ...
def structure(network: Network) -> str: ...
def renamed(network: Network) -> Network: ...

class StaticLoad(enum.Enum):
    any = ...
    required = ...
    excluded = ...

class EnumerationOptions:
    def __init__(self, max_elements: int = 4, springs: bool = True, dampers: bool = True, inerters: bool = True,
                 max_springs: int = -1, max_dampers: int = -1, max_inerters: int = -1,
                 static_load: StaticLoad = StaticLoad.any) -> None: ...
    max_elements: int
    springs: bool
    dampers: bool
    inerters: bool
    max_springs: int
    max_dampers: int
    max_inerters: int
    static_load: StaticLoad

def enumerate_networks(options: EnumerationOptions = ...) -> list[str]: ...
def admittance_leaf(num: Sequence[float], den: Sequence[float]) -> Network: ...

class PrTest:
    positive_real: bool
    reason: str
    re_min: float
    omega_min: float

def positive_real(num: Sequence[float], den: Sequence[float], rel_tol: float = 1e-9) -> PrTest: ...
def biquadratic_positive_real(a0: float, a1: float, a2: float, d0: float, d1: float, d2: float) -> bool: ...

class Synthesis:
    network: Network
    elements: int
    reactive: int
    degree: int
    bott_duffin: bool
    minimal_reactive: bool
    method: str

def synthesise(num: Sequence[float], den: Sequence[float]) -> Synthesis: ...

# ---- models ------------------------------------------------------------------------------------------
class JointType(enum.Enum):
    revolute = ...
    spherical = ...
    prismatic = ...
    fixed = ...
    driving = ...
    distance = ...
    coupling = ...

class OutputKind(enum.Enum):
    coordinate = ...
    position = ...
    velocity = ...
    acceleration = ...
    element_force = ...
    element_length = ...
    reaction = ...
    multiplier = ...

class Body:
    name: str
    mass: float
    inertia: float
    q0: FloatArray
    qd0: FloatArray
    inertia3: FloatArray
    q0s: FloatArray
    qd0s: FloatArray
    weighs: bool

class Marker:
    name: str
    body: int
    u: FloatArray
    u3: FloatArray

class Joint:
    name: str
    type: JointType
    body_i: int
    body_j: int
    u_i: FloatArray
    u_j: FloatArray
    axis: FloatArray
    theta0: float
    component: int
    value0: float
    length0: float
    row: int
    spatial: bool
    @property
    def rows(self) -> int: ...

class Output:
    name: str
    kind: OutputKind
    index: int
    component: int
    scale: float
    @property
    def needs_accelerations(self) -> bool: ...

def needs_accelerations(output: Output) -> bool: ...

class Options:
    gravity: bool
    g: FloatArray
    g3: FloatArray
    alpha: float
    beta: float
    centripetal: bool
    t_end: float
    sample: float
    max_violation: float

class State:
    q: FloatArray
    qd: FloatArray
    z: FloatArray
    @overload
    def __init__(self) -> None: ...
    @overload
    def __init__(self, q: npt.ArrayLike, qd: npt.ArrayLike, z: npt.ArrayLike = ...) -> None: ...
    def copy(self) -> State: ...

class ForceElement:
    @property
    def name(self) -> str: ...
    @property
    def type(self) -> str: ...
    @property
    def n_states(self) -> int: ...
    @property
    def state_offset(self) -> int: ...
    @property
    def body_i(self) -> Optional[int]: ...
    @property
    def body_j(self) -> Optional[int]: ...
    @property
    def network(self) -> Optional[Network]: ...
    @property
    def reference_length(self) -> Optional[float]: ...
    @property
    def free_length(self) -> Optional[float]: ...
    @property
    def actuator(self) -> Optional[dict[str, float]]: ...
    def energy(self, model: Model, t: float, state: State) -> float: ...
    def power(self, model: Model, t: float, state: State) -> float: ...
    def length(self, model: Model, state: State) -> float: ...

class AssemblyReport:
    iterations: int
    residual: float
    initial_residual: float
    dq: FloatArray
    largest: int

class EquilibriumReport:
    iterations: int
    force_residual: float
    max_move: float
    largest: int

class ModelCheck:
    state: State
    assembly: AssemblyReport
    rank: int
    dof: int
    redundant: int

class Model:
    """Immutable model (and pantograph metadata); transformations return new models."""
    @property
    def name(self) -> str: ...
    @property
    def source(self) -> str: ...
    @property
    def text(self) -> str: ...
    @property
    def overrides(self) -> list[str]: ...
    @property
    def history(self) -> list[str]: ...
    @property
    def dimension(self) -> int: ...
    @property
    def n_coords(self) -> int: ...
    @property
    def n_constraints(self) -> int: ...
    @property
    def dof(self) -> int: ...
    @property
    def n_states(self) -> int: ...
    @property
    def bodies(self) -> list[Body]: ...
    @property
    def markers(self) -> list[Marker]: ...
    @property
    def joints(self) -> list[Joint]: ...
    @property
    def forces(self) -> list[ForceElement]: ...
    @property
    def outputs(self) -> list[Output]: ...
    @property
    def output_names(self) -> list[str]: ...
    @property
    def coordinate_names(self) -> list[str]: ...
    @property
    def options(self) -> Options: ...
    @property
    def held(self) -> list[int]: ...
    @property
    def notes(self) -> list[str]: ...
    @property
    def is_pantograph(self) -> bool: ...
    @property
    def has_rig(self) -> bool: ...
    @property
    def contact_marker(self) -> int: ...
    @property
    def rig_joint(self) -> int: ...
    @property
    def aero(self) -> Optional[dict[str, float]]: ...
    def aero_force(self, speed: float) -> float: ...
    def at_speed(self, speed: float) -> Model: ...
    def find_body(self, name: str) -> int: ...
    def find_marker(self, name: str) -> int: ...
    def find_joint(self, name: str) -> int: ...
    def find_force(self, name: str) -> int: ...
    def coord_name(self, k: int) -> str: ...
    def body_name(self, index: int) -> str: ...
    def q0(self) -> FloatArray: ...
    def qd0(self) -> FloatArray: ...
    def value(self, key: str) -> Optional[float]: ...
    def with_overrides(self, overrides: Overrides) -> Model: ...
    def with_options(self, *, centripetal: Optional[bool] = None, gravity: Optional[bool] = None,
                     alpha: Optional[float] = None, beta: Optional[float] = None, t_end: Optional[float] = None,
                     sample: Optional[float] = None) -> Model: ...
    def with_suspension(self, network: NetworkLike, params: Optional[Params] = None,
                        reference_length: float = -1.0) -> Model: ...
    def release_head(self) -> Tuple[Model, float]: ...
    def without_joint(self, name: str) -> Model: ...
    def check(self) -> ModelCheck: ...

def load_model(path: PathLike, overrides: Overrides = None) -> Model: ...
def load_pantograph(path: PathLike, overrides: Overrides = None) -> Model: ...
def parse_model(text: str, source: str = "<text>", overrides: Overrides = None) -> Model: ...
def split_overrides(path: PathLike, overrides: Overrides) -> Tuple[Sequence[str], Sequence[str]]: ...
def model_value(text: str, source: str, key: str) -> Optional[float]: ...
def check_model(model: Model) -> ModelCheck: ...
def with_suspension(model: Model, network: NetworkLike, params: Optional[Params] = None,
                    reference_length: float = -1.0) -> Model: ...
def release_head(model: Model) -> Tuple[Model, float]: ...
def suspension_index(model: Model) -> int: ...
def at_speed(model: Model, speed: float) -> Model: ...

class LumpedPantographData:
    mass: list[float]
    stiffness: list[float]
    damping: list[float]
    static_uplift: float
    aero_a: float
    aero_b: float
    aero_c: float
    def __init__(self, mass: Sequence[float], stiffness: Sequence[float], damping: Sequence[float],
                 static_uplift: float = 0.0, aero_a: float = 0.0, aero_b: float = 0.0, aero_c: float = 0.0) -> None: ...
    def validate(self) -> None: ...

def make_lumped_pantograph(data: LumpedPantographData) -> Model: ...
def load_lumped_pantograph_data(path: PathLike, overrides: Overrides = None) -> LumpedPantographData: ...
def file_kind(path: PathLike) -> str: ...

class Stepper:
    def __init__(self, model: Model, state: State, t0: float = 0.0,
                 integrator: Optional[IntegratorOptions] = None) -> None: ...
    def advance(self, t_end: float) -> None: ...
    @property
    def state(self) -> State: ...
    @property
    def time(self) -> float: ...
    @property
    def stats(self) -> RunStats: ...

def assemble(model: Model, t0: float = 0.0) -> Tuple[State, AssemblyReport]: ...
def static_equilibrium(model: Model, state: Optional[State] = None, t0: float = 0.0) -> Tuple[State, EquilibriumReport]: ...
def consistent_velocities(model: Model, state: State, t: float = 0.0) -> State: ...
def iso8608_gd0(road_class: str) -> float: ...
def iso8608_psd(road_class: str, n: float) -> float: ...
def iso8608_velocity_psd(road_class: str, speed: float) -> float: ...
def iso8608_variance(road_class: str, n_min: float, n_max: float) -> float: ...
def accelerations(model: Model, t: float, state: State) -> Tuple[FloatArray, FloatArray, FloatArray]: ...
def constraints(model: Model, t: float, state: State) -> Tuple[FloatArray, FloatArray, FloatArray, FloatArray]: ...
def forces(model: Model, t: float, state: State) -> Tuple[FloatArray, FloatArray]: ...
def joint_reaction(model: Model, joint: Union[int, str], t: float, state: State, lam: npt.ArrayLike) -> FloatArray: ...
def kinetic_energy(model: Model, state: State) -> float: ...
def stored_energy(model: Model, t: float, state: State) -> float: ...
def element_power(model: Model, t: float, state: State) -> float: ...
def evaluate_output(model: Model, output: Union[int, str], t: float, state: State) -> float: ...
def integrate(model: Model, state: State, t0: float, t_end: float, dt_sample: float, *,
              integrator: Optional[IntegratorOptions] = None, method: Optional[str] = None,
              rtol: Optional[float] = None, atol: Optional[float] = None,
              max_step: Optional[float] = None) -> Tuple[State, RunStats]: ...

# ---- catenaries --------------------------------------------------------------------------------------
class Contact:
    kind: str
    stiffness: float
    damping: float
    def __init__(self, kind: str = "bilateral", stiffness: float = 50e3, damping: float = 0.0) -> None: ...
    def validate(self) -> None: ...

def kind_name(contact: Contact) -> str: ...

class LumpedCatenary:
    span: float
    m: list[float]
    c: list[float]
    k: list[float]
    def __init__(self, span: float = 60.0, m: Sequence[float] = ..., c: Sequence[float] = ...,
                 k: Sequence[float] = ...) -> None: ...
    def natural_frequency(self) -> float: ...
    def validate(self) -> None: ...
    @staticmethod
    def harmonic(x: Sequence[float], fp: float, t: float) -> float: ...
    @staticmethod
    def harmonic_rate(x: Sequence[float], fp: float, t: float) -> float: ...

class WireProfile:
    x: list[float]
    h: list[float]
    periodic: bool
    span: float
    def __init__(self, x: Sequence[float], h: Sequence[float], periodic: bool = True, span: float = 0.0) -> None: ...

class Section:
    from_: float
    to: float
    def __init__(self, from_: float, to: float) -> None: ...
    def __len__(self) -> int: ...
    def __getitem__(self, i: int) -> float: ...

class Catenary:
    @property
    def type(self) -> str: ...
    def describe(self) -> str: ...
    @property
    def span(self) -> float: ...
    @property
    def max_pantographs(self) -> int: ...
    @property
    def line_length(self) -> float: ...
    def section(self) -> Section: ...
    def mean(self) -> Catenary: ...
    def point_model(self) -> Optional[LumpedCatenary]: ...

class Lumped(Catenary):
    @overload
    def __init__(self, params: LumpedCatenary) -> None: ...
    @overload
    def __init__(self) -> None: ...
    @property
    def params(self) -> LumpedCatenary: ...

class WireProfileCatenary(Catenary):
    def __init__(self, profile: WireProfile) -> None: ...
    @property
    def profile(self) -> WireProfile: ...

class CatenaryFile:
    @property
    def name(self) -> str: ...
    @property
    def catenary(self) -> Optional[Catenary]: ...
    @property
    def contact(self) -> Contact: ...
    @property
    def fe(self) -> Optional[FeCatenaryData]: ...
    @property
    def path(self) -> str: ...
    @property
    def overrides(self) -> list[str]: ...
    def describe(self) -> str: ...

def load_catenary(path: PathLike, overrides: Overrides = None) -> CatenaryFile: ...

class PantographOnLine:
    x0: float
    contact: Contact
    def __init__(self, model: Model, x0: float = 0.0, contact: Contact = ...) -> None: ...
    @property
    def model(self) -> Model: ...

class LumpedCoupling:
    @property
    def model(self) -> Model: ...
    wire_body: int
    wire_y: int
    element: int
    contact_force: Output
    y_unloaded: float
    bilateral: bool

class FeWire:
    tension: float
    mass_per_length: float
    EI: float
    def __init__(self, tension: float = 0.0, mass_per_length: float = 0.0, EI: float = 0.0) -> None: ...
    def wave_speed(self) -> float: ...

class FeCatenaryData:
    span: float
    spans: int
    encumbrance: float
    dropper_x: list[float]
    presag: list[float]
    nominal_dropper_length: list[float]
    messenger: FeWire
    contact_wire: FeWire
    dropper_EA: float
    dropper_mass_per_length: float
    clamp_mass_messenger: float
    clamp_mass_contact: float
    support_stiffness: float
    support_mass: float
    registration_stiffness: float
    registration_mass: float
    element_length: float
    rayleigh_mass: float
    rayleigh_stiffness: float
    gravity: float
    time_step: float
    hht_alpha: float
    solver: str
    modal_cutoff: float
    window_behind: int
    window_ahead: int
    tension_sections: list[FeCatenaryData]
    overlap_spans: int
    overlap_outgoing: list[float]
    overlap_incoming: list[float]
    overlap_outgoing_x: list[float]
    overlap_incoming_x: list[float]
    mast_height: list[float]
    height_x: list[float]
    height_z: list[float]
    def height_at(self, x: float) -> float: ...
    line_start: float
    first_span: int
    wire_label: int
    def link_sections(self) -> None: ...
    section_first: int
    section_last: int
    def __init__(self) -> None: ...
    def validate(self) -> None: ...

class FeDropper:
    x: float
    node: int
    dof_m: int
    dof_c: int
    length: float
    stiffness: float
    tension: float

class FeLine:
    def __init__(self, data: FeCatenaryData) -> None: ...
    @property
    def data(self) -> FeCatenaryData: ...
    @property
    def n_nodes(self) -> int: ...
    @property
    def n_dofs(self) -> int: ...
    @property
    def length(self) -> float: ...
    @property
    def node_x(self) -> FloatArray: ...
    def dof(self, wire: int, node: int, component: int) -> int: ...
    def matrices(self) -> dict[str, Any]: ...
    @property
    def droppers(self) -> list[FeDropper]: ...
    @property
    def support_x(self) -> FloatArray: ...
    @property
    def support_dofs(self) -> list[int]: ...
    def static_height(self, x: ArrayLike) -> Any: ...
    def static_slope(self, x: ArrayLike) -> Any: ...
    def elasticity(self, x: ArrayLike) -> Any: ...
    def messenger_height(self, node: int) -> float: ...
    def dropper_length_error_max(self) -> float: ...
    def contact_shape(self, x: float) -> Tuple[int, list[int], list[float], list[float]]: ...
    def contact_displacement(self, u: npt.ArrayLike, x: float) -> float: ...
    def load_vector(self, x: float, F: float) -> FloatArray: ...
    def static_displacement(self, x: ArrayLike, F: ArrayLike) -> Tuple[FloatArray, list[bool]]: ...
    def describe(self) -> str: ...

class FeCatenary(Catenary):
    def __init__(self, data: FeCatenaryData) -> None: ...
    @property
    def line(self) -> FeLine: ...

class LumpedFit:
    lumped: LumpedCatenary
    span: int
    @property
    def x(self) -> FloatArray: ...
    @property
    def elasticity(self) -> FloatArray: ...
    @property
    def mass(self) -> FloatArray: ...
    @property
    def damping(self) -> FloatArray: ...
    @property
    def fitted_elasticity(self) -> FloatArray: ...
    max_elasticity_error: float
    max_smoothed_error: float
    rms_error: float
    rms_smoothed_error: float

def fit_lumped(line: Union[FeLine, FeCatenary], span: int = 0, points: int = 220) -> LumpedFit: ...
def beam_stiffness(EI: float, tension: float, length: float) -> FloatArray: ...
def beam_mass(mass_per_length: float, length: float) -> FloatArray: ...
def read_catenary_file(path: PathLike, overrides: Overrides = None) -> CatenaryFile: ...
def read_fe_catenary_data(path: PathLike, overrides: Overrides = None) -> FeCatenaryData: ...
def write_lumped_catenary(path: PathLike, fit: LumpedFit, contact: Contact, source: str) -> None: ...
def write_fit_table(path: PathLike, fit: LumpedFit) -> None: ...

# ---- signal processing, EN 50317 contact quality ----------------------------------------------------
class Biquad:
    b0: float
    b1: float
    b2: float
    a1: float
    a2: float
    def __init__(self, b0: float = 1.0, b1: float = 0.0, b2: float = 0.0, a1: float = 0.0, a2: float = 0.0) -> None: ...

class SosFilter:
    sections: list[Biquad]
    sample_rate: float
    order: int
    def magnitude(self, f: float) -> Tuple[float, float]: ...
    def dc_gain(self) -> float: ...

def butterworth_lowpass(cutoff: float, sample_rate: float, order: int = 4) -> SosFilter: ...
def filter(filter: SosFilter, x: ArrayLike) -> list[float]: ...
def filtfilt(filter: SosFilter, x: ArrayLike) -> list[float]: ...
def filtfilt_padding(filter: SosFilter) -> int: ...
def uniform_sample_rate(t: ArrayLike, rel_tol: float = 1e-6) -> float: ...

class Spectrum:
    @property
    def f(self) -> FloatArray: ...
    @property
    def S(self) -> FloatArray: ...
    resolution: float
    segments: int
    def integral(self, f_lo: Optional[float] = None, f_hi: Optional[float] = None) -> float: ...

class Window(enum.Enum):
    hann = ...
    rectangular = ...

class WelchOptions:
    segment: int
    overlap: float
    window: Window
    def __init__(self, segment: int = 0, overlap: float = 0.5, window: Window = ...) -> None: ...

def welch(x: ArrayLike, sample_rate: float, options: Optional[WelchOptions] = None) -> Spectrum: ...
def periodogram(x: ArrayLike, sample_rate: float, window: Window = ...) -> Spectrum: ...

class ContactQualityOptions:
    cutoff: float
    order: int
    psd_segment: int
    uniform_tolerance: float
    def __init__(self, cutoff: float = 20.0, order: int = 4, psd_segment: int = 0,
                 uniform_tolerance: float = 1e-6) -> None: ...

class ContactQuality:
    x_from: float
    x_to: float
    t_from: float
    t_to: float
    first: int
    sample_rate: float
    cutoff: float
    order: int
    raw: ContactStatistics
    filtered: ContactStatistics
    loss_pct: float
    psd: Spectrum

def contact_quality(t: ArrayLike, x_contact: ArrayLike, F: ArrayLike, x_from: Union[float, Section],
                    x_to: Optional[float] = None, options: Optional[ContactQualityOptions] = None) -> ContactQuality: ...

class PartStatistics:
    raw: ContactStatistics
    filtered: ContactStatistics

def part_statistics(t: ArrayLike, x_contact: ArrayLike, F: ArrayLike, section: Section, parts: Sequence[Section],
                    options: Optional[ContactQualityOptions] = None) -> PartStatistics: ...

class SupportUplift:
    support: int
    x: float
    max_uplift: float
    t_max: float

def support_uplift(t: ArrayLike, support_x: ArrayLike, uplift: Sequence[Sequence[float]], x_from: float,
                   x_to: float) -> list[SupportUplift]: ...

def couple_lumped(model: Model, catenary: LumpedCatenary, contact: Contact, speed: float) -> LumpedCoupling: ...

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
    def __init__(self, layout: str = "", values: dict[str, float] = ..., time: bool = False) -> None: ...

class CheckResult:
    cost: StudyCost
    failure: str

def run_search(study: Study, task: SearchTask, *,
               batch: Optional[Callable[[list[dict[str, float]]], list[DesignCost]]] = None) -> LayoutResult: ...
def run_check(study: Study, task: CheckTask) -> CheckResult: ...

class StudyExecutor:
    def __init__(self) -> None: ...
    def search(self, study: Study, tasks: list[SearchTask], done: Callable[[int, LayoutResult], None],
               searching: Callable[[int, int, int, float], None]) -> list[LayoutResult]: ...
    def check(self, study: Study, tasks: list[CheckTask]) -> list[CheckResult]: ...

class LocalExecutor(StudyExecutor):
    def __init__(self) -> None: ...

class StudyOptions:
    report: bool
    report_options: ReportOptions
    rechecks: int
    def __init__(self, *, report: bool = False, report_options: Optional[ReportOptions] = None,
                 rechecks: int = 5) -> None: ...

class Recheck:
    entry: int
    periodic_rank: int
    time: StudyCost
    failure: str
    settling_spans: float

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
