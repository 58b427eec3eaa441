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

