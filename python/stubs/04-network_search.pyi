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

