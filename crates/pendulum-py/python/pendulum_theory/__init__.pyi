import os
from typing import Any, Dict, List, Mapping, Optional, Sequence, Tuple, Union

import numpy as np
import numpy.typing as npt

ArrayLike = Union[float, npt.ArrayLike]
Result = Union[float, npt.NDArray[np.float64]]

STANDARD_GRAVITY: float

def ellipk(m: ArrayLike) -> Result: ...
def ellipe(m: ArrayLike) -> Result: ...
def ellipj(u: ArrayLike, m: ArrayLike) -> Tuple[Result, Result, Result, Result]: ...
def period(length: ArrayLike, amplitude: ArrayLike, g: ArrayLike = ...) -> Result: ...
def circular_error_s_per_day(amplitude: ArrayLike) -> Result: ...
def length_for_period(period: ArrayLike, amplitude: ArrayLike = ..., g: ArrayLike = ...) -> Result: ...
def amplitude_for_period(period: ArrayLike, length: ArrayLike, g: ArrayLike = ...) -> Result: ...
def normal_gravity(latitude: ArrayLike, height: ArrayLike = ...) -> Result: ...
def zeta_from_q(q: ArrayLike) -> Result: ...
def q_from_zeta(zeta: ArrayLike) -> Result: ...
def log_decrement_from_zeta(zeta: ArrayLike) -> Result: ...
def zeta_from_log_decrement(delta: ArrayLike) -> Result: ...
def decay_time(zeta: ArrayLike, length: ArrayLike, g: ArrayLike = ...) -> Result: ...
def damped_angle(t: ArrayLike, length: ArrayLike, amplitude: ArrayLike, zeta: ArrayLike = ..., g: ArrayLike = ...) -> Result: ...
def exact_angle(t: ArrayLike, length: ArrayLike, amplitude: ArrayLike, g: ArrayLike = ...) -> Result: ...
def simulate(
    length: float,
    amplitude: float,
    duration: float,
    *,
    q: Optional[float] = ...,
    zeta: Optional[float] = ...,
    log_decrement: Any = ...,
    quadratic_drag: Optional[float] = ...,
    friction_angle: Optional[float] = ...,
    drag: Any = ...,
    g: Optional[float] = ...,
    method: Optional[str] = ...,
    tolerance: Optional[float] = ...,
    force: Any = ...,
) -> Tuple[npt.NDArray[np.float64], npt.NDArray[np.float64], npt.NDArray[np.float64], Dict[str, Any]]: ...

class FitResult(Dict[str, Any]):
    parameters: Dict[str, float]
    standard_errors: Dict[str, float]
    preferred: Optional[str]

def fit_decay(
    time: npt.ArrayLike,
    amplitude: npt.ArrayLike,
    model: str = ...,
    *,
    period: Optional[float] = ...,
    length: Optional[float] = ...,
    g: Optional[float] = ...,
    mass: Any = ...,
    force: Any = ...,
) -> FitResult: ...
def fit_trajectory(
    time: npt.ArrayLike,
    angle: Optional[npt.ArrayLike] = ...,
    model: str = ...,
    *,
    angular_velocity: Optional[npt.ArrayLike] = ...,
    length: Optional[float] = ...,
    length_uncertainty: Optional[float] = ...,
    force: Any = ...,
    drag_law: Optional[str] = ...,
) -> FitResult: ...
def fit_beats(
    time: npt.ArrayLike,
    *,
    bph: Optional[float] = ...,
    period: Optional[float] = ...,
    length: Any = ...,
    parts: Any = ...,
    nut_pitch: Any = ...,
    nut_tpi: Any = ...,
    nut_divisions: Any = ...,
    crutch: Any = ...,
    amplitude: Any = ...,
) -> FitResult: ...
def fit_photogate(
    time: npt.ArrayLike,
    *,
    gate: Optional[npt.ArrayLike] = ...,
    select: Optional[int] = ...,
    bob_diameter: Optional[float] = ...,
    bph: Optional[float] = ...,
    period: Optional[float] = ...,
) -> FitResult: ...
def fit_period(
    period: npt.ArrayLike,
    *,
    period_standard_error: Optional[npt.ArrayLike] = ...,
    amplitude: Optional[npt.ArrayLike] = ...,
    length: Optional[npt.ArrayLike] = ...,
    pendulum_length: Optional[float] = ...,
    pendulum_length_standard_error: Optional[float] = ...,
    bob_radius: Optional[float] = ...,
    length_uncertainty: Optional[float] = ...,
) -> FitResult: ...
def lists() -> Dict[str, List[Dict[str, Any]]]: ...
def fit_file(
    path: Union[str, os.PathLike[str]],
    fit: str,
    *,
    columns: Optional[Union[str, Sequence[str]]] = ...,
    angle_unit: Optional[str] = ...,
    frame_rate: Optional[float] = ...,
    run: Optional[int] = ...,
    pivot: Optional[Union[str, Sequence[float]]] = ...,
    y_down: bool = ...,
    scale: Optional[float] = ...,
    model: Optional[str] = ...,
    period: Optional[float] = ...,
    length: Optional[float] = ...,
    length_uncertainty: Optional[float] = ...,
    mass: Optional[float] = ...,
    g: Optional[float] = ...,
    latitude: Optional[float] = ...,
    height: Optional[float] = ...,
    start: Optional[float] = ...,
    stop: Optional[float] = ...,
    bob_radius: Optional[float] = ...,
    force: bool = ...,
) -> dict[str, Any]: ...
def clock(
    length: Optional[float] = ...,
    *,
    parts: Any = ...,
    drive_energy: Optional[float] = ...,
    drive_torque: Optional[float] = ...,
    q: Optional[float] = ...,
    escapement: Optional[str] = ...,
    lift_angle: Optional[float] = ...,
    mass: Optional[float] = ...,
    friction: Optional[float] = ...,
    recoil: Optional[float] = ...,
    impulse_angle: Optional[float] = ...,
    every_beats: Optional[int] = ...,
    beat_error: Optional[float] = ...,
    out_of_beat: Optional[float] = ...,
    g: Optional[float] = ...,
    drive_factor: Optional[ArrayLike] = ...,
    drive_range: Any = ...,
    steps: Any = ...,
    drag: Optional[Dict[str, float]] = ...,
) -> Dict[str, Any]: ...
def clock_run(
    length: float,
    duration: float,
    *,
    every: Optional[float] = ...,
    drive_schedule: Optional[Tuple[npt.ArrayLike, npt.ArrayLike]] = ...,
    rate_schedule: Optional[Tuple[npt.ArrayLike, npt.ArrayLike]] = ...,
    weather: Optional[Mapping[str, Optional[npt.ArrayLike]]] = ...,
    gas: Any = ...,
    force: Any = ...,
    **clock_keywords: Any,
) -> Tuple[Dict[str, npt.NDArray[np.float64]], Dict[str, Any]]: ...
def listen(
    samples: Any,
    sample_rate: Any,
    *,
    bph: Any = ...,
    period: Any = ...,
    sample_rate_error_ppm: Any = ...,
    lift_angle: Any = ...,
    oscillator: Optional[str] = ...,
    every: Any = ...,
    length: Any = ...,
    parts: Any = ...,
    nut_pitch: Any = ...,
    nut_tpi: Any = ...,
    nut_divisions: Any = ...,
    crutch: Any = ...,
    amplitude: Any = ...,
) -> Dict[str, Any]: ...
def period_table(
    length: Any,
    amplitude: Any = ...,
    *,
    amplitude_range: Any = ...,
    steps: Any = ...,
    g: Any = ...,
    series_terms: Any = ...,
    step: Any = ...,
) -> Dict[str, Any]: ...
def length(
    period: Any = ...,
    *,
    bph: Any = ...,
    amplitude: Any = ...,
    g: Any = ...,
) -> Dict[str, Any]: ...
def amplitude(
    length: Any,
    period: Any,
    *,
    period_uncertainty: Any = ...,
    g: Any = ...,
) -> Dict[str, Any]: ...
def damped(
    length: Any,
    amplitude: Any,
    *,
    zeta: Any = ...,
    q: Any = ...,
    log_decrement: Any = ...,
    decay_time: Any = ...,
    damping_coefficient: Any = ...,
    friction_angle: Any = ...,
    mass: Any = ...,
    extrema: Any = ...,
    g: Any = ...,
    force: Any = ...,
) -> Dict[str, Any]: ...
def train(
    wheels: Any,
    pinions: Any,
    *,
    arbor_turns_per_hour: Any = ...,
    g: Any = ...,
) -> Dict[str, Any]: ...
def train_for(
    bph: Any,
    *,
    escape_teeth: Any = ...,
    tolerance: Any = ...,
) -> Dict[str, Any]: ...
def design(
    parts: Any,
    *,
    g: Any = ...,
    pressure_hpa: Any = ...,
    temperature: Any = ...,
    humidity: Any = ...,
    regulated_at: Any = ...,
    gas: Any = ...,
    pivot_q: Any = ...,
    amplitude: Any = ...,
) -> Dict[str, Any]: ...
def regulate(
    rate: Any,
    *,
    length: Any = ...,
    parts: Any = ...,
    part: Any = ...,
    nut_pitch: Any = ...,
    nut_tpi: Any = ...,
    nut_divisions: Any = ...,
    tray: Any = ...,
    bph: Any = ...,
) -> Dict[str, Any]: ...
def compensate(
    parts: Any,
    compensator: Any = ...,
    *,
    part: Any = ...,
    jar_material: Any = ...,
    jar_diameter: Any = ...,
    jar_wall: Any = ...,
    tube_diameter: Any = ...,
    tube_bore: Any = ...,
) -> Dict[str, Any]: ...
def report(
    *,
    length: Any = ...,
    parts: Any = ...,
    amplitude: Any = ...,
    zeta: Any = ...,
    q: Any = ...,
    log_decrement: Any = ...,
    decay_time: Any = ...,
    damping_coefficient: Any = ...,
    mass: Any = ...,
    g: Any = ...,
) -> Dict[str, Any]: ...

def stability(
    data: npt.ArrayLike,
    tau0: float,
    *,
    kind: str = ...,
    all_taus: bool = ...,
    force: bool = ...,
    outliers: str = ...,
) -> dict[str, Any]: ...
def tide(
    latitude: float,
    longitude: float,
    time: npt.ArrayLike,
    *,
    height: float = ...,
    force: bool = ...,
) -> dict[str, npt.NDArray[np.float64]]: ...
def clock_log(
    time: npt.ArrayLike,
    values: npt.ArrayLike,
    *,
    kind: str = ...,
    temperature: Optional[npt.ArrayLike] = ...,
    pressure_hpa: Optional[npt.ArrayLike] = ...,
    humidity: Optional[npt.ArrayLike] = ...,
    amplitude_deg: Optional[npt.ArrayLike] = ...,
    pulse_width: Optional[npt.ArrayLike] = ...,
    flag_width: Optional[float] = ...,
    gate_radius: Optional[float] = ...,
    epoch: Optional[float] = ...,
    latitude: Optional[float] = ...,
    longitude: Optional[float] = ...,
    height: float = ...,
    tides: bool = ...,
    events: Optional[npt.ArrayLike] = ...,
    bin: Optional[float] = ...,
    beat: Optional[float] = ...,
    bph: Optional[float] = ...,
    period: Optional[float] = ...,
    force: bool = ...,
    stability: bool = ...,
    wheels: Optional[Sequence[int]] = ...,
    pinions: Optional[Sequence[int]] = ...,
    arbor_turns_per_hour: Optional[float] = ...,
    length: Optional[float] = ...,
    parts: Optional[Any] = ...,
    nut_pitch: Optional[float] = ...,
    nut_tpi: Optional[float] = ...,
    nut_divisions: Optional[int] = ...,
) -> dict[str, Any]: ...
