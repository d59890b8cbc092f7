from typing import Any, Dict, List, Optional, Tuple, Union

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
    quadratic_drag: float = ...,
    friction_angle: float = ...,
    g: float = ...,
    method: str = ...,
    tolerance: float = ...,
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
    g: float = ...,
) -> FitResult: ...
def fit_trajectory(
    time: npt.ArrayLike, angle: npt.ArrayLike, model: str = ..., *, length: Optional[float] = ...
) -> FitResult: ...
def fit_beats(time: npt.ArrayLike, *, bph: Optional[float] = ..., period: Optional[float] = ...) -> FitResult: ...
def clock(
    length: float,
    *,
    drive_energy: Optional[float] = ...,
    drive_torque: Optional[float] = ...,
    q: float = ...,
    escapement: str = ...,
    lift_angle: float = ...,
    mass: float = ...,
    friction: float = ...,
    recoil: float = ...,
    impulse_angle: float = ...,
    every_beats: int = ...,
    g: float = ...,
    drive_factor: ArrayLike = ...,
) -> Dict[str, Any]: ...
def clock_run(
    length: float,
    duration: float,
    *,
    every: Optional[float] = ...,
    drive_schedule: Optional[Tuple[npt.ArrayLike, npt.ArrayLike]] = ...,
    rate_schedule: Optional[Tuple[npt.ArrayLike, npt.ArrayLike]] = ...,
    drive_energy: Optional[float] = ...,
    drive_torque: Optional[float] = ...,
    q: float = ...,
    escapement: str = ...,
    lift_angle: float = ...,
    mass: float = ...,
    friction: float = ...,
    recoil: float = ...,
    impulse_angle: float = ...,
    every_beats: int = ...,
    g: float = ...,
) -> Tuple[Dict[str, npt.NDArray[np.float64]], Dict[str, Any]]: ...
